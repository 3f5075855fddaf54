// BoxTree, the wide bounding-volume hierarchy behind the terrain's and a
// compact mesh's index (internal to wtc::core): it must offer every box that
// overlaps a query, each once, from any slot of any node, whatever the tree's
// shape (a lone leaf, partly filled nodes, many levels) and however many
// leaves one query meets (more than the walk holds back at once).
#include "terrain/box_tree.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace wtc::detail {
namespace {

// Boxes on a jittered grid, at coordinates far from the origin with fine
// fractional parts, so that their single precision copies round (a copy
// rounded inward would fall short of the double box).
std::vector<Aabb> jitteredBoxes(int count, std::mt19937_64& rng) {
  constexpr double kOriginM = 1234.5678901;  // far enough out that float rounding is ~1e-4 m
  constexpr double kSpacingM = 0.37;         // grid pitch (m)
  std::uniform_real_distribution<double> jitter(-0.1, 0.1), size(0.05, 0.3), height(-0.2, 0.2);
  const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
  std::vector<Aabb> boxes;
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector3d centre(kOriginM + (k % side) * kSpacingM + jitter(rng),
                                 kOriginM + (k / side) * kSpacingM + jitter(rng), height(rng));
    const Eigen::Vector3d half(size(rng), size(rng), size(rng));
    boxes.push_back({centre - half, centre + half});
  }
  return boxes;
}

// Positions reported for `query`, counted per position.
std::vector<int> reports(const BoxTree& tree, std::size_t count, const Aabb& query) {
  std::vector<int> seen(count, 0);
  tree.visit(query, [&](std::int32_t position) {
    ASSERT_GE(position, 0);
    ASSERT_LT(static_cast<std::size_t>(position), count);
    ++seen[static_cast<std::size_t>(position)];
  });
  return seen;
}

// Every box overlapping `query` reported, none twice.
void expectEveryOverlapOnce(const BoxTree& tree, const std::vector<Aabb>& boxes, const std::vector<std::int32_t>& order,
                            const Aabb& query) {
  const std::vector<int> seen = reports(tree, boxes.size(), query);
  for (std::size_t position = 0; position < boxes.size(); ++position) {
    ASSERT_LE(seen[position], 1) << "position " << position << " reported twice";
    if (boxes[static_cast<std::size_t>(order[position])].overlaps(query)) {
      ASSERT_EQ(seen[position], 1) << "box " << order[position] << " missed by a query touching it";
    }
  }
}

TEST(BoxTreeTest, StoresEveryBoxRoundedOutward) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> coordinate(-1e4, 1e4);
  for (int k = 0; k < 10000; ++k) {
    // Case: any double box; its float copy contains it.
    const Eigen::Vector3d a(coordinate(rng), coordinate(rng), coordinate(rng));
    const Aabb box{a, a + Eigen::Vector3d(1e-3, 2e-3, 3e-3)};
    float min[3], max[3];
    storeOutward(box, min, max);
    for (int i = 0; i < 3; ++i) {
      ASSERT_LE(static_cast<double>(min[i]), box.min[i]) << "case " << k << " axis " << i;
      ASSERT_GE(static_cast<double>(max[i]), box.max[i]) << "case " << k << " axis " << i;
    }
  }
}

TEST(BoxTreeTest, ReportsEveryOverlappingBoxOnceForAnyQuery) {
  std::mt19937_64 rng(5);
  // Sizes: a lone leaf, one node partly filled, full nodes, several levels.
  for (const int count : {1, 4, 5, 9, 33, 64, 65, 600, 5000}) {
    const std::vector<Aabb> boxes = jitteredBoxes(count, rng);
    std::vector<std::int32_t> order;
    const BoxTree tree(boxes, order);
    ASSERT_EQ(order.size(), boxes.size());
    Aabb all = boxes[0];
    for (const Aabb& b : boxes) all.include(b);

    // Case: a query grazing each box at each face from outside meets it
    // (overlap is closed), and so does the tree.
    for (std::size_t k = 0; k < boxes.size(); k += 1 + boxes.size() / 100) {
      const Aabb& b = boxes[k];
      for (int axis = 0; axis < 3; ++axis) {
        Aabb above = b, below = b;
        above.min[axis] = b.max[axis];
        above.max[axis] = b.max[axis] + 0.1;
        below.max[axis] = b.min[axis];
        below.min[axis] = b.min[axis] - 0.1;
        expectEveryOverlapOnce(tree, boxes, order, above);
        expectEveryOverlapOnce(tree, boxes, order, below);
      }
    }
    // Case: random queries from wheel-sized to most of the set (the
    // largest meet far more leaves than a walk holds back at once).
    std::uniform_real_distribution<double> x(all.min.x(), all.max.x()), y(all.min.y(), all.max.y());
    std::uniform_real_distribution<double> half(0.01, 0.5 * all.extent().x() + 0.01);
    for (int q = 0; q < 200; ++q) {
      const Eigen::Vector3d c(x(rng), y(rng), 0.0), h(half(rng), half(rng), 0.1);
      expectEveryOverlapOnce(tree, boxes, order, {c - h, c + h});
    }
    // Case: the whole set, each box once.
    const std::vector<int> seen = reports(tree, boxes.size(), all);
    for (std::size_t position = 0; position < boxes.size(); ++position) EXPECT_EQ(seen[position], 1);

    // Case: a box with a NaN meets nothing.
    Aabb nan = all;
    nan.min.x() = std::numeric_limits<double>::quiet_NaN();
    const std::vector<int> none = reports(tree, boxes.size(), nan);
    for (const int n : none) EXPECT_EQ(n, 0);
  }
}

}  // namespace
}  // namespace wtc::detail
