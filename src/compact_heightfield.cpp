// Heightfield prisms formed on demand (design note in compact_heightfield.hpp).
#include "compact_heightfield.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace wtc::detail {

CompactHeightfield::CompactHeightfield(Heightfield field) : field_(std::move(field)) {
  validate(field_);
  field_.heights.shrink_to_fit();  // the samples and nothing more
  base_z_ = field_.baseZ();
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
  return makeTriangularPrism(p[0], p[1], p[2], base_z_);
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

void CompactHeightfield::overlapping(const Aabb& box, PieceId first, std::vector<PieceId>& out) const {
  const Heightfield& f = field_;
  if (!(box.max.z() >= base_z_)) return;  // below the base: every piece reaches down to it, none lower
  // Cells whose x range [x_c, x_c+1] can meet [box.min.x, box.max.x]; one
  // cell of margin on each side absorbs the rounding of the division, the
  // exact test below decides.
  const auto range = [](double lo, double hi, double origin, double spacing, int cells, int& first_cell,
                        int& last_cell) {
    const double a = std::floor((lo - origin) / spacing) - 1.0;
    const double b = std::floor((hi - origin) / spacing) + 1.0;
    first_cell = static_cast<int>(std::clamp(a, 0.0, static_cast<double>(cells)));
    last_cell = static_cast<int>(std::clamp(b, -1.0, static_cast<double>(cells - 1)));
  };
  int c0, c1, r0, r1;
  range(box.min.x(), box.max.x(), f.origin.x(), f.spacing_x, f.cols - 1, c0, c1);
  range(box.min.y(), box.max.y(), f.origin.y(), f.spacing_y, f.rows - 1, r0, r1);
  const auto cells_per_row = static_cast<std::size_t>(f.cols - 1);
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) {
      const std::size_t k = 2 * (static_cast<std::size_t>(r) * cells_per_row + c);
      for (std::size_t t = 0; t < 2; ++t) {
        if (pieceBounds(k + t).overlaps(box)) out.push_back(first + static_cast<PieceId>(k + t));
      }
    }
  }
}

std::size_t CompactHeightfield::memoryBytes() const {
  return sizeof(*this) + field_.heights.capacity() * sizeof(double);
}

}  // namespace wtc::detail
