#pragma once
// A static wide bounding-volume hierarchy over boxes (internal to
// wtc::core): the terrain's index over its stored pieces, and a compact
// mesh's over its triangles. Built once, top-down over the boxes'
// centres (median splits along the widest axis); each node collapses
// kSplitLevels levels of those binary splits into up to kWidth children and
// keeps their boxes in single precision rounded outward, structure-of-arrays,
// so one vector compare tests four. Chosen over FCL's
// DynamicAABBTreeCollisionManager and Bullet's btDbvt by the benchmark
// bench/wheel_query_bench.cpp (docs/terrain.md).
//
// Why wide: on a terrain larger than the cache a cold query pays one
// dependent miss per level; a node of several adjacent lines costs about
// one miss when its lines are fetched together (they are prefetched as the
// node is pushed), so fewer, wider levels are cheaper. The leaf order is the
// binary splits' order whatever the width (the owners lay their data out by
// it).
//
// The tree never misses a box (outward rounding, a widened query) but may
// offer a few more; the owner decides each offered one exactly, on its own
// double boxes (stored, or computed when asked: a compact mesh keeps none).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <Eigen/Core>

#include "base/cache_line.hpp"

#include "wtc/geometry/aabb.hpp"

namespace wtc::detail {

/// `box` in single precision rounded outward, never smaller than it: the
/// tree's node boxes, and a compact mesh's leaf boxes.
void storeOutward(const Aabb& box, float min[3], float max[3]);

/// A ball (centre, radius): BoxTree::visitNear() also skips the slots whose
/// boxes lie farther than the radius from the centre (decided in single
/// precision with a relative slack of BoxTree::kBallSlack, so never one that
/// comes within it).
struct BoxTreeBall {
  Eigen::Vector3d centre;
  double radius = 0.0;
};

class BoxTree {
 public:
  /// Boxes per leaf: 2 and 4 measure within noise of each other on
  /// heightfields (bench/wheel_query_bench.cpp); 4 halves the node memory.
  static constexpr int kLeafBoxes = 4;
  /// Binary median splits collapsed into one node, and the children a node
  /// holds (2^kSplitLevels, a multiple of the four lanes of a compare).
  static constexpr int kSplitLevels = 3;
  static constexpr int kWidth = 1 << kSplitLevels;

  BoxTree() = default;
  /// Builds over `boxes` (at least one). `order` receives the boxes'
  /// indices in tree order: visit() reports positions in it.
  BoxTree(std::span<const Aabb> boxes, std::vector<std::int32_t>& order);

  /// Calls leaf(position) for every position in order whose leaf's single
  /// precision box overlaps `box` (a superset of the boxes that overlap), in
  /// no particular order. Allocation-free. A box with a NaN meets nothing.
  template <class Leaf>
  void visit(const Aabb& box, Leaf&& leaf) const {
    visit(box, leaf, [](std::int32_t, std::int32_t) {});
  }
  /// The same, and touch(first, count) as soon as positions first ...
  /// first + count - 1 are known to come, before any leaf() of them: a hint
  /// for the owner to prefetch what leaf() will read, so that those misses
  /// overlap the rest of the walk.
  template <class Leaf, class Touch>
  void visit(const Aabb& box, Leaf&& leaf, Touch&& touch) const {
    visit(box, nullptr, leaf, touch);
  }
  using Ball = BoxTreeBall;
  /// visit(box, leaf, touch) for a `box` that holds `ball`, pruned by the
  /// ball: what a wheel's search asks, where the ground within the wheel's
  /// radius is a disc a few cells wide and the box a square of many.
  template <class Leaf, class Touch>
  void visitNear(const Aabb& box, const Ball& ball, Leaf&& leaf, Touch&& touch) const {
    visit(box, &ball, leaf, touch);
  }

  std::size_t memoryBytes() const { return nodes_.capacity() * sizeof(Node); }

 private:
  // child >= 0 is an inner node; child < 0 a leaf holding positions ~child
  // ... ~child + count - 1. Unused slots have empty boxes (min > max).
  // Aligned to the cache line so a node spans no more lines than its size.
  using Float4 = float __attribute__((vector_size(16)));
  static constexpr int kGroups = kWidth / 4;  // four-lane compares per node
  struct alignas(kCacheLineBytes) Node {
    Float4 min_x[kGroups], min_y[kGroups], min_z[kGroups], max_x[kGroups], max_y[kGroups], max_z[kGroups];
    std::int32_t child[kWidth];
    std::int32_t count[kWidth];
  };
  static_assert(sizeof(Node) % kCacheLineBytes == 0);
  static_assert(kWidth <= 32, "a node's hits are bits of an unsigned");
  // A four-lane compare's result (each lane all ones or zero) as four bits.
  using Int4 = std::int32_t __attribute__((vector_size(16)));
  static unsigned laneBits(Int4 hit) {
#if defined(__SSE2__)
    return static_cast<unsigned>(_mm_movemask_ps(reinterpret_cast<__m128>(hit)));
#else
    return (hit[0] & 1u) | (hit[1] & 2u) | (hit[2] & 4u) | (hit[3] & 8u);
#endif
  }
  // Hit leaves a walk holds back before reporting them: more than a wheel's
  // query meets, few enough for the stack.
  static constexpr int kPendingLeaves = 16;
  // Asks for all the lines of node `index` (a hint: it changes no answer).
  void prefetchNode(std::int32_t index) const {
    const char* at = reinterpret_cast<const char*>(&nodes_[index]);
#pragma GCC unroll 8
    for (std::size_t line = 0; line < sizeof(Node); line += kCacheLineBytes) __builtin_prefetch(at + line);
  }
  // The query box in single precision, widened by at least one ulp.
  static void widen(const Aabb& box, float lo[3], float hi[3]);
  // Relative slack of the ball's single-precision test (float's epsilon is
  // 6e-8: the centre's and the boxes' rounding stay far inside it).
  static constexpr double kBallSlack = 1e-5;
  static Float4 positive(Float4 v) { return v > Float4{} ? v : Float4{}; }
  template <class Leaf, class Touch>
  void visit(const Aabb& box, const Ball* ball, Leaf&& leaf, Touch&& touch) const;

  std::vector<Node> nodes_;
};

template <class Leaf, class Touch>
void BoxTree::visit(const Aabb& box, const Ball* ball, Leaf&& leaf, Touch&& touch) const {
  if (nodes_.empty()) return;
  float lo[3], hi[3];
  widen(box, lo, hi);
  const Float4 lx{lo[0], lo[0], lo[0], lo[0]}, ly{lo[1], lo[1], lo[1], lo[1]}, lz{lo[2], lo[2], lo[2], lo[2]};
  const Float4 hx{hi[0], hi[0], hi[0], hi[0]}, hy{hi[1], hi[1], hi[1], hi[1]}, hz{hi[2], hi[2], hi[2], hi[2]};
  // The ball in single precision, its radius grown by the slack.
  Float4 bx{}, by{}, bz{}, br2{};
  if (ball != nullptr) {
    const Eigen::Vector3d& c = ball->centre;
    const double grown = (ball->radius + kBallSlack * (c.cwiseAbs().maxCoeff() + ball->radius)) * (1.0 + kBallSlack);
    const auto f = [](double v) { return Float4{float(v), float(v), float(v), float(v)}; };
    bx = f(c.x()), by = f(c.y()), bz = f(c.z()), br2 = f(grown * grown);
  }
  // Hit leaves wait here, touched, while the walk goes on; leaf() runs for
  // them when the buffer is full and at the end.
  std::int32_t pending_first[kPendingLeaves], pending_count[kPendingLeaves];
  int pending = 0;
  auto flush = [&] {
    for (int p = 0; p < pending; ++p) {
      for (std::int32_t k = pending_first[p]; k < pending_first[p] + pending_count[p]; ++k) leaf(k);
    }
    pending = 0;
  };
  // Depth-first. Positions are int32, so a binary tree of them is at most
  // 32 deep, and each of the wide levels leaves at most kWidth - 1 siblings
  // on the stack.
  std::int32_t stack[(kWidth - 1) * 32 + 1];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    unsigned hits = 0;  // bit s: slot s's box overlaps the query
    for (int g = 0; g < kGroups; ++g) {
      const Int4 hit = (lx <= node.max_x[g]) & (node.min_x[g] <= hx) & (ly <= node.max_y[g]) &
                       (node.min_y[g] <= hy) & (lz <= node.max_z[g]) & (node.min_z[g] <= hz);
      if (ball == nullptr) {
        hits |= laneBits(hit) << (4 * g);
        continue;
      }
      const Float4 ex = positive(node.min_x[g] - bx) + positive(bx - node.max_x[g]);
      const Float4 ey = positive(node.min_y[g] - by) + positive(by - node.max_y[g]);
      const Float4 ez = positive(node.min_z[g] - bz) + positive(bz - node.max_z[g]);
      hits |= laneBits(hit & (ex * ex + ey * ey + ez * ez <= br2)) << (4 * g);
    }
    // Every slot in turn, unrolled: each test is a branch of its own, which
    // a rolling wheel's steady pattern predicts (walking the set bits by
    // count-trailing-zeros measured fewer instructions but more time).
#pragma GCC unroll 8
    for (int slot = 0; slot < kWidth; ++slot) {
      if ((hits >> slot & 1u) == 0) continue;
      const std::int32_t child = node.child[slot];
      if (child >= 0) {
        // Every hit child's lines are asked for now, so the misses of
        // siblings overlap instead of coming one after another.
        prefetchNode(child);
        stack[top++] = child;
        continue;
      }
      if (pending == kPendingLeaves) flush();
      pending_first[pending] = ~child;
      pending_count[pending] = node.count[slot];
      touch(pending_first[pending], pending_count[pending]);
      ++pending;
    }
  }
  flush();
}

}  // namespace wtc::detail
