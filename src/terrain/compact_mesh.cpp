// Triangle-mesh prisms formed on demand (design note in compact_mesh.hpp).
#include "compact_mesh.hpp"

#include <cmath>
#include <limits>
#include <utility>

#include "builder_support.hpp"

namespace wtc::detail {
namespace {

// How far a float box's edge v may lie beyond the exact edge x it was
// rounded outward from (m): the cast is within half an ulp of x, nextafter
// adds one, and an ulp is at most 2^-23 |v| (or the smallest subnormal
// below FLT_MIN); 2^-21 |v| + 2 FLT_MIN covers both with room.
double rounding(double v) { return std::abs(v) * 0x1p-21 + 2.0 * std::numeric_limits<float>::min(); }

}  // namespace

std::array<Eigen::Vector3d, 3> extrudedBottom(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                              const Eigen::Vector3d& c, double thickness) {
  const Eigen::Vector3d offset = thickness * (b - a).cross(c - a).normalized();
  return {a - offset, b - offset, c - offset};
}

CompactTriangleMesh::CompactTriangleMesh(TriangleMesh mesh, double thickness)
    : mesh_(std::move(mesh)), thickness_(thickness) {
  mesh_.vertices.shrink_to_fit();
  mesh_.triangles.shrink_to_fit();
  // The boxes live only while the tree is built.
  std::vector<Aabb> boxes(mesh_.triangles.size());
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    boxes[k] = pieceBounds(k);
    if (k == 0) bounds_ = boxes[k];
    bounds_.include(boxes[k]);
  }
  tree_ = BoxTree(boxes, order_);
  order_.shrink_to_fit();
  boxes_.resize(order_.size());
  for (std::size_t position = 0; position < order_.size(); ++position) {
    storeOutward(boxes[order_[position]], boxes_[position].min, boxes_[position].max);
  }
}

void CompactTriangleMesh::prismCorners(std::size_t k, std::array<Eigen::Vector3d, 3>& top,
                                       std::array<Eigen::Vector3d, 3>& bottom) const {
  const auto& t = mesh_.triangles[k];
  top = {mesh_.vertices[t[0]], mesh_.vertices[t[1]], mesh_.vertices[t[2]]};
  bottom = extrudedBottom(top[0], top[1], top[2], thickness_);
}

void CompactTriangleMesh::overlapping(const Aabb& box, PieceId first, std::vector<PieceId>& out) const {
  auto report = [&](std::int32_t position) {
    const FloatBox& f = boxes_[position];
    // The exact box lies inside the float one: no overlap with it, none.
    if (f.max[0] < box.min[0] || box.max[0] < f.min[0] || f.max[1] < box.min[1] || box.max[1] < f.min[1] ||
        f.max[2] < box.min[2] || box.max[2] < f.min[2]) {
      return;
    }
    // The exact box reaches to within rounding() of each float edge; NaN
    // (an infinite edge) leaves it unsure.
    bool sure = true;
    for (int i = 0; i < 3; ++i) {
      const double lo = f.min[i], hi = f.max[i];
      sure = sure && hi - rounding(hi) >= box.min[i] && lo + rounding(lo) <= box.max[i];
    }
    const auto k = static_cast<std::size_t>(order_[position]);
    if (sure || pieceBounds(k).overlaps(box)) out.push_back(first + static_cast<PieceId>(k));
  };
  // The float boxes report() reads, every line they span, asked for while
  // the walk goes on.
  auto touch = [&](std::int32_t from, std::int32_t count) {
    const auto* at = reinterpret_cast<const char*>(&boxes_[from]);
    const auto* end = reinterpret_cast<const char*>(&boxes_[from] + count);
    for (; at < end; at += kCacheLineBytes) __builtin_prefetch(at);
    __builtin_prefetch(end - 1);  // the last line, when `at` skipped past its start
  };
  tree_.visit(box, report, touch);
}

std::size_t CompactTriangleMesh::memoryBytes() const {
  return sizeof(*this) + mesh_.name.capacity() + mesh_.vertices.capacity() * sizeof(Eigen::Vector3d) +
         mesh_.triangles.capacity() * sizeof(mesh_.triangles[0]);
}

std::size_t CompactTriangleMesh::indexMemoryBytes() const {
  return order_.capacity() * sizeof(std::int32_t) + boxes_.capacity() * sizeof(FloatBox) + tree_.memoryBytes();
}

}  // namespace wtc::detail
