#pragma once
// A static 4-wide bounding-volume hierarchy over boxes (internal to
// wtc::core): the terrain's index over its stored pieces, and a compact
// mesh's over its triangles. Built once, top-down over the boxes'
// centres (median splits along the widest axis); each node keeps its four
// children's boxes in single precision rounded outward, structure-of-arrays,
// so one vector compare tests all four. Chosen over FCL's
// DynamicAABBTreeCollisionManager and Bullet's btDbvt by the benchmark
// bench/wheel_query_bench.cpp (docs/terrain.md).
//
// The tree never misses a box (outward rounding, a widened query) but may
// offer a few more; the owner decides each offered one exactly, on its own
// double boxes (stored, or computed when asked: a compact mesh keeps none).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "wtc/geometry/aabb.hpp"

namespace wtc::detail {

/// `box` in single precision rounded outward, never smaller than it: the
/// tree's node boxes, and a compact mesh's leaf boxes.
void storeOutward(const Aabb& box, float min[3], float max[3]);

class BoxTree {
 public:
  /// Boxes per leaf: 2 and 4 measure within noise of each other on
  /// heightfields (bench/wheel_query_bench.cpp); 4 halves the node memory.
  static constexpr int kLeafBoxes = 4;

  BoxTree() = default;
  /// Builds over `boxes` (at least one). `order` receives the boxes'
  /// indices in tree order: visit() reports positions in it.
  BoxTree(std::span<const Aabb> boxes, std::vector<std::int32_t>& order);

  /// Calls leaf(position) for every position in order whose leaf's single
  /// precision box overlaps `box` (a superset of the boxes that overlap).
  /// Allocation-free. A box with a NaN meets nothing.
  template <class Leaf>
  void visit(const Aabb& box, Leaf&& leaf) const;

  std::size_t memoryBytes() const { return nodes_.capacity() * sizeof(Node); }

 private:
  // child >= 0 is an inner node; child < 0 a leaf holding positions ~child
  // ... ~child + count - 1. Unused slots have empty boxes (min > max).
  using Float4 = float __attribute__((vector_size(16)));
  struct alignas(16) Node {
    Float4 min_x, min_y, min_z, max_x, max_y, max_z;
    std::int32_t child[4];
    std::int32_t count[4];
  };
  // The query box in single precision, widened by at least one ulp.
  static void widen(const Aabb& box, float lo[3], float hi[3]);

  std::vector<Node> nodes_;
};

template <class Leaf>
void BoxTree::visit(const Aabb& box, Leaf&& leaf) const {
  if (nodes_.empty()) return;
  float lo[3], hi[3];
  widen(box, lo, hi);
  const Float4 lx{lo[0], lo[0], lo[0], lo[0]}, ly{lo[1], lo[1], lo[1], lo[1]}, lz{lo[2], lo[2], lo[2], lo[2]};
  const Float4 hx{hi[0], hi[0], hi[0], hi[0]}, hy{hi[1], hi[1], hi[1], hi[1]}, hz{hi[2], hi[2], hi[2], hi[2]};
  // Depth-first; a 4-wide tree of depth 32 would hold 2^64 leaves.
  std::int32_t stack[3 * 32 + 1];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    const auto hit = (lx <= node.max_x) & (node.min_x <= hx) & (ly <= node.max_y) & (node.min_y <= hy) &
                     (lz <= node.max_z) & (node.min_z <= hz);
    for (int c = 0; c < 4; ++c) {
      if (hit[c] == 0) continue;
      const std::int32_t child = node.child[c];
      if (child >= 0) {
        stack[top++] = child;
        continue;
      }
      for (std::int32_t k = ~child; k < ~child + node.count[c]; ++k) leaf(k);
    }
  }
}

}  // namespace wtc::detail
