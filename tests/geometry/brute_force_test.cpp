// The oracle itself, against a closed form: the signed distance of a box,
//   q = |p - c| - h (per axis),  d = |max(q, 0)| + min(max_i q_i, 0),
// and its closest point, clamp(p, min, max) outside. If the oracle were
// wrong, every oracle test would measure the wrong thing.
#include "brute_force.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "random_pieces.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"
#include "wtc/base/error.hpp"

namespace {

using Eigen::Vector3d;

// The oracle computes in long double and the closed form in double: they
// agree to a few double roundoffs of the coordinates (dimensionless,
// relative to the larger of the box size and |p - c|).
constexpr double kTolerance = 1e-14;

TEST(BruteForceOracleTest, MatchesTheClosedFormOfABox) {
  // Case: 50 random boxes, 400 points each from every region (including
  // exact faces, edges, vertices and points 1e3 sizes away).
  wtc::test::RandomPieces random(71);
  for (int i = 0; i < 50; ++i) {
    const double scale = std::pow(10.0, random.uniform(-3, 3));
    const Vector3d min = scale * Vector3d(random.uniform(-10, 10), random.uniform(-10, 10), random.uniform(-10, 10));
    const Vector3d max = min + scale * Vector3d(random.uniform(0.1, 2), random.uniform(0.1, 2), random.uniform(0.1, 2));
    const wtc::ConvexPolyhedron box = wtc::ConvexPolyhedron::box(min, max);
    const wtc::testing::BruteForceOracle oracle(box);
    const Vector3d centre = 0.5 * (min + max);
    const Vector3d half = 0.5 * (max - min);
    for (int k = 0; k < 400; ++k) {
      const Vector3d p = random.query(box);
      const Vector3d q = (p - centre).cwiseAbs() - half;
      const double exact = q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
      const wtc::testing::BruteForceResult got = oracle.query(p);
      const double tolerance = kTolerance * std::max(box.size(), (p - centre).norm());
      ASSERT_NEAR(got.signed_distance, exact, tolerance) << wtc::formatVector(p);
      ASSERT_NEAR(oracle.surfaceDistance(p), std::abs(exact), tolerance) << wtc::formatVector(p);
      if (exact > 0) {
        ASSERT_LE((got.closest_point - p.cwiseMax(min).cwiseMin(max)).norm(), tolerance);
      } else {
        ASSERT_NEAR((got.closest_point - p).norm(), -exact, tolerance);
        ASSERT_LE(oracle.surfaceDistance(got.closest_point), tolerance);
      }
    }
  }
}

TEST(BruteForceOracleTest, FlatPieceHasNoInside) {
  // Case: a unit square: points on it are at 0, never below.
  const wtc::ConvexPolyhedron square = wtc::ConvexPolyhedron::fromPoints({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  EXPECT_EQ(wtc::testing::bruteForceQuery(square, Vector3d(0.5, 0.5, 0)).signed_distance, 0.0);
  EXPECT_DOUBLE_EQ(wtc::testing::bruteForceQuery(square, Vector3d(0.5, 0.5, -2)).signed_distance, 2.0);
  EXPECT_DOUBLE_EQ(wtc::testing::bruteForceQuery(square, Vector3d(2, 0.5, 0)).signed_distance, 1.0);
}

}  // namespace
