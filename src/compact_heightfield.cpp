// Heightfield prisms formed on demand (design note in compact_heightfield.hpp).
#include "compact_heightfield.hpp"

#include "builder_support.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace wtc::detail {

CompactHeightfield::CompactHeightfield(Heightfield field) : field_(std::move(field)) {
  validate(field_);
  field_.heights.shrink_to_fit();  // the samples and nothing more
  field_.cell_materials.shrink_to_fit();
  base_z_ = field_.baseZ();
  // The corners' coordinates as sample() computes them; origin.z + h is
  // monotonic in h, so the highest sample gives the highest top.
  const double highest = *std::max_element(field_.heights.begin(), field_.heights.end());
  const Eigen::Vector3d far = field_.origin + Eigen::Vector3d((field_.cols - 1) * field_.spacing_x,
                                                              (field_.rows - 1) * field_.spacing_y, highest);
  bounds_ = {Eigen::Vector3d(field_.origin.x(), field_.origin.y(), base_z_), far};
}

void CompactHeightfield::corners(std::size_t k, Eigen::Vector3d p[3]) const {
  const std::size_t cell = k / 2;
  const auto cells_per_row = static_cast<std::size_t>(field_.cols - 1);
  const int r = static_cast<int>(cell / cells_per_row);
  const int c = static_cast<int>(cell % cells_per_row);
  // addHeightfield: (p00, p01, p11) first, then (p00, p11, p10).
  p[0] = field_.sample(r, c);
  p[1] = k % 2 == 0 ? field_.sample(r, c + 1) : field_.sample(r + 1, c + 1);
  p[2] = k % 2 == 0 ? field_.sample(r + 1, c + 1) : field_.sample(r + 1, c);
}

ConvexPolyhedron CompactHeightfield::piece(std::size_t k) const {
  Eigen::Vector3d p[3];
  corners(k, p);
  // makeTriangularPrism's corners, checked once for the whole field.
  return makeCheckedPrism({p[0], p[1], p[2]},
                          {Eigen::Vector3d(p[0].x(), p[0].y(), base_z_), Eigen::Vector3d(p[1].x(), p[1].y(), base_z_),
                           Eigen::Vector3d(p[2].x(), p[2].y(), base_z_)});
}

Aabb CompactHeightfield::pieceBounds(std::size_t k) const {
  Eigen::Vector3d p[3];
  corners(k, p);
  // ConvexPolyhedron's bounds are the min and max of its vertices: the
  // three corners and their feet on the base.
  Aabb box{p[0], p[0]};
  for (const Eigen::Vector3d& q : p) {
    box.include(q);
    box.include(Eigen::Vector3d(q.x(), q.y(), base_z_));
  }
  return box;
}

namespace {

// The cells [first, last] along one axis whose span [x(i), x(i + 1)], with
// x(i) = origin + i spacing computed as Heightfield::sample does, meets
// [lo, hi]: exactly the cells whose pieces' boxes meet the box along that
// axis (both triangles of a cell span the whole cell). The division only
// guesses; the comparisons on x(i) decide. Empty when first > last.
void cellSpan(double lo, double hi, double origin, double spacing, int cells, int& first, int& last) {
  const auto x = [&](int i) { return origin + i * spacing; };
  const double guess_lo = std::floor((lo - origin) / spacing);
  const double guess_hi = std::floor((hi - origin) / spacing);
  first = static_cast<int>(std::clamp(guess_lo, 0.0, static_cast<double>(cells - 1)));
  last = static_cast<int>(std::clamp(guess_hi, 0.0, static_cast<double>(cells - 1)));
  while (first > 0 && x(first) >= lo) --first;           // cell first - 1 may still reach lo
  while (first < cells && x(first + 1) < lo) ++first;    // ends before lo
  while (last + 1 < cells && x(last + 1) <= hi) ++last;  // starts within hi
  while (last >= 0 && x(last) > hi) --last;              // starts after hi
}

}  // namespace

void CompactHeightfield::overlapping(const Aabb& box, PieceId first, std::vector<PieceId>& out) const {
  const Heightfield& f = field_;
  // Every piece reaches down to the base: a box below it meets none. A
  // box with a NaN meets nothing (every comparison fails), as in
  // Terrain::overlapping.
  if (!(box.max.z() >= base_z_) || box.min.hasNaN() || box.max.hasNaN()) return;
  int c0, c1, r0, r1;
  cellSpan(box.min.x(), box.max.x(), f.origin.x(), f.spacing_x, f.cols - 1, c0, c1);
  cellSpan(box.min.y(), box.max.y(), f.origin.y(), f.spacing_y, f.rows - 1, r0, r1);
  const auto cells_per_row = static_cast<std::size_t>(f.cols - 1);
  const double lowest = box.min.z();
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) {
      // The pieces' tops: the corners' z as sample() computes them.
      const double z00 = f.origin.z() + f.height(r, c), z01 = f.origin.z() + f.height(r, c + 1);
      const double z10 = f.origin.z() + f.height(r + 1, c), z11 = f.origin.z() + f.height(r + 1, c + 1);
      const auto k = static_cast<PieceId>(2 * (static_cast<std::size_t>(r) * cells_per_row + c));
      if (lowest <= std::max({z00, z01, z11})) out.push_back(first + k);
      if (lowest <= std::max({z00, z11, z10})) out.push_back(first + k + 1);
    }
  }
}

std::size_t CompactHeightfield::memoryBytes() const {
  return sizeof(*this) + field_.heights.capacity() * sizeof(double) +
         field_.cell_materials.capacity() * sizeof(MaterialId);
}

}  // namespace wtc::detail
