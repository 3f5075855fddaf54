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
// each half once more, giving up to four children; a child of at most
// kLeafBoxes boxes is a leaf. O(n log n).
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
  auto setNode = [&](std::int32_t index, const float(&min)[3][4], const float(&max)[3][4]) {
    Node& node = nodes_[index];
    std::memcpy(&node.min_x, min[0], sizeof(Float4));
    std::memcpy(&node.min_y, min[1], sizeof(Float4));
    std::memcpy(&node.min_z, min[2], sizeof(Float4));
    std::memcpy(&node.max_x, max[0], sizeof(Float4));
    std::memcpy(&node.max_y, max[1], sizeof(Float4));
    std::memcpy(&node.max_z, max[2], sizeof(Float4));
  };
  constexpr float kInf = std::numeric_limits<float>::infinity();
  // Returns the node index; called only for ranges larger than a leaf.
  auto build = [&](auto& self, std::int32_t begin, std::int32_t end) -> std::int32_t {
    std::int32_t bounds[5];
    int parts = 0;
    const std::int32_t mid = split(begin, end);
    for (const auto& [b, e] : {std::pair{begin, mid}, std::pair{mid, end}}) {
      bounds[parts++] = b;
      if (e - b > kLeafBoxes) bounds[parts++] = split(b, e);
    }
    bounds[parts] = end;
    const auto index = static_cast<std::int32_t>(nodes_.size());
    nodes_.emplace_back();
    float min[3][4], max[3][4];
    for (int c = 0; c < 4; ++c) {
      float lo[3] = {kInf, kInf, kInf}, hi[3] = {-kInf, -kInf, -kInf};  // empty slot: overlaps nothing
      std::int32_t child = -1, count = 0;
      if (c < parts) {
        const std::int32_t b = bounds[c], e = bounds[c + 1];
        storeOutward(rangeBox(b, e), lo, hi);
        if (e - b <= kLeafBoxes) {
          child = ~b;
          count = e - b;
        } else {
          child = self(self, b, e);
        }
      }
      for (int k = 0; k < 3; ++k) {
        min[k][c] = lo[k];
        max[k][c] = hi[k];
      }
      nodes_[index].child[c] = child;
      nodes_[index].count[c] = count;
    }
    setNode(index, min, max);
    return index;
  };
  if (n > kLeafBoxes) {
    build(build, 0, n);
  } else {
    // A root with a single leaf child keeps one query path for all sizes.
    float min[3][4], max[3][4], lo[3], hi[3];
    storeOutward(rangeBox(0, n), lo, hi);
    for (int k = 0; k < 3; ++k) {
      min[k][0] = lo[k];
      max[k][0] = hi[k];
      for (int c = 1; c < 4; ++c) {
        min[k][c] = kInf;
        max[k][c] = -kInf;
      }
    }
    nodes_.emplace_back();
    nodes_[0].child[0] = ~0;
    nodes_[0].count[0] = n;
    for (int c = 1; c < 4; ++c) {
      nodes_[0].child[c] = -1;
      nodes_[0].count[c] = 0;
    }
    setNode(0, min, max);
  }
  // Fitted to its size (the reservation above is about three times it), in
  // memory advised for huge pages.
  std::vector<Node> fitted;
  reserveHuge(fitted, nodes_.size());
  fitted.insert(fitted.end(), nodes_.begin(), nodes_.end());
  nodes_.swap(fitted);
}

}  // namespace wtc::detail
