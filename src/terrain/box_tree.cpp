// The terrain's bounding-volume hierarchy (design note in box_tree.hpp).
#include "box_tree.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <utility>

#include "base/huge_pages.hpp"

namespace wtc::detail {

// Never smaller than the double box, so the tree never misses one.
void storeOutward(const Aabb& box, float min[3], float max[3]) {
  for (int k = 0; k < 3; ++k) {
    min[k] = std::nextafter(static_cast<float>(box.min[k]), -std::numeric_limits<float>::infinity());
    max[k] = std::nextafter(static_cast<float>(box.max[k]), std::numeric_limits<float>::infinity());
  }
}

// 2^-22 relative plus the smallest normal float covers the rounding of the
// cast, without a libm call (this runs once per wheel query).
void BoxTree::widen(const Aabb& box, float lo[3], float hi[3]) {
  constexpr float kUlps = 2.384185791015625e-07f;  // 2^-22
  constexpr float kTiny = std::numeric_limits<float>::min();
  for (int k = 0; k < 3; ++k) {
    const float a = static_cast<float>(box.min[k]);
    const float b = static_cast<float>(box.max[k]);
    lo[k] = a - (std::abs(a) * kUlps + kTiny);
    hi[k] = b + (std::abs(b) * kUlps + kTiny);
  }
}

// A node's range is split at the median along the widest centre axis, and
// each part again, up to kSplitLevels deep, giving up to kWidth children; a
// part of at most kLeafBoxes boxes is a leaf and is not split further.
// O(n log n).
BoxTree::BoxTree(std::span<const Aabb> boxes, std::vector<std::int32_t>& order) {
  const auto n = static_cast<std::int32_t>(boxes.size());
  order.resize(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  if (n == 0) return;
  std::vector<Eigen::Vector3d> centre(static_cast<std::size_t>(n));
  for (std::int32_t i = 0; i < n; ++i) centre[i] = boxes[i].center();
  auto rangeBox = [&](std::int32_t begin, std::int32_t end) {
    Aabb box = boxes[order[begin]];
    for (std::int32_t k = begin + 1; k < end; ++k) box.include(boxes[order[k]]);
    return box;
  };
  auto split = [&](std::int32_t begin, std::int32_t end) {
    Aabb centres{centre[order[begin]], centre[order[begin]]};
    for (std::int32_t k = begin + 1; k < end; ++k) centres.include(centre[order[k]]);
    int axis = 0;
    centres.extent().maxCoeff(&axis);
    const std::int32_t mid = begin + (end - begin) / 2;
    std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                     [&](std::int32_t a, std::int32_t b) { return centre[a][axis] < centre[b][axis]; });
    return mid;
  };
  nodes_.reserve(static_cast<std::size_t>(n) / kLeafBoxes + 1);
  constexpr float kInf = std::numeric_limits<float>::infinity();
  // Node `index`'s slots from its parts' bounds (parts <= kWidth ranges,
  // bounds[parts] the end); a part larger than a leaf becomes a node by
  // `inner`. Unused slots get empty boxes, which overlap nothing.
  auto fill = [&](std::int32_t index, const std::int32_t* bounds, int parts, auto&& inner) {
    float min[3][kWidth], max[3][kWidth];
    std::int32_t child[kWidth], count[kWidth];
    for (int c = 0; c < kWidth; ++c) {
      float lo[3] = {kInf, kInf, kInf}, hi[3] = {-kInf, -kInf, -kInf};
      child[c] = -1;
      count[c] = 0;
      if (c < parts) {
        const std::int32_t b = bounds[c], e = bounds[c + 1];
        storeOutward(rangeBox(b, e), lo, hi);
        if (e - b <= kLeafBoxes) {
          child[c] = ~b;
          count[c] = e - b;
        } else {
          child[c] = inner(b, e);
        }
      }
      for (int k = 0; k < 3; ++k) {
        min[k][c] = lo[k];
        max[k][c] = hi[k];
      }
    }
    Node& node = nodes_[index];  // after the recursion: it may grow nodes_
    for (int g = 0; g < kGroups; ++g) {
      std::memcpy(&node.min_x[g], &min[0][4 * g], sizeof(Float4));
      std::memcpy(&node.min_y[g], &min[1][4 * g], sizeof(Float4));
      std::memcpy(&node.min_z[g], &min[2][4 * g], sizeof(Float4));
      std::memcpy(&node.max_x[g], &max[0][4 * g], sizeof(Float4));
      std::memcpy(&node.max_y[g], &max[1][4 * g], sizeof(Float4));
      std::memcpy(&node.max_z[g], &max[2][4 * g], sizeof(Float4));
    }
    std::memcpy(node.child, child, sizeof child);
    std::memcpy(node.count, count, sizeof count);
  };
  // Binary levels a node over `count` boxes takes: the rest of the binary
  // depth below it a multiple of kSplitLevels, so the partly filled node is
  // the root (cached) and the nodes above the leaves, the most numerous,
  // are full. Median splits keep every leaf at depth d or d - 1, d that of
  // the larger half's chain.
  auto levels = [](std::int32_t count) {
    int depth = 0;
    for (; count > kLeafBoxes; count -= count / 2) ++depth;
    return (depth - 1) % kSplitLevels + 1;
  };
  // Returns the node index; called only for ranges larger than a leaf.
  auto build = [&](auto& self, std::int32_t begin, std::int32_t end) -> std::int32_t {
    std::int32_t bounds[kWidth + 1];
    int parts = 0;
    auto partition = [&](auto& again, std::int32_t b, std::int32_t e, int deep) -> void {
      if (deep == 0 || e - b <= kLeafBoxes) {
        bounds[parts++] = b;
        return;
      }
      const std::int32_t mid = split(b, e);
      again(again, b, mid, deep - 1);
      again(again, mid, e, deep - 1);
    };
    partition(partition, begin, end, levels(end - begin));
    bounds[parts] = end;
    const auto index = static_cast<std::int32_t>(nodes_.size());
    nodes_.emplace_back();
    fill(index, bounds, parts, [&](std::int32_t b, std::int32_t e) { return self(self, b, e); });
    return index;
  };
  if (n > kLeafBoxes) {
    build(build, 0, n);
  } else {
    // A root with a single leaf child keeps one query path for all sizes.
    const std::int32_t bounds[2] = {0, n};
    nodes_.emplace_back();
    fill(0, bounds, 1, [](std::int32_t, std::int32_t) { return std::int32_t{-1}; });
  }
  // Fitted to its size (the reservation above is several times it), in
  // memory advised for huge pages.
  std::vector<Node> fitted;
  reserveHuge(fitted, nodes_.size());
  fitted.insert(fitted.end(), nodes_.begin(), nodes_.end());
  nodes_.swap(fitted);
}

}  // namespace wtc::detail
