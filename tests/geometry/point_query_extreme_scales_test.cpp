// Hard cases of wtc::queryPoint at the limits of double precision: sliver
// tetrahedra, a 1 mm piece 1e6 m from the origin, 1e-6 m and 1e4 m pieces,
// aspect ratio 1e6, and query points 1e9 m away. Each test states its
// tolerance; where it is looser than kTolerance x size, the reason is the
// resolution of double at the coordinates involved.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "brute_force.hpp"
#include "query_checks.hpp"
#include "random_pieces.hpp"
#include "scenarios.hpp"
#include "wtc/base/error.hpp"
#include "wtc/geometry/point_query.hpp"

namespace point_query_extreme_scales_test {

using Eigen::Vector3d;
using wtc::ConvexPolyhedron;
using wtc::PointQuery;
using wtc::testing::BruteForceOracle;

// Error allowed on distance and closest point, relative to the piece's size
// (dimensionless): the accuracy target of issue 2.
constexpr double kTolerance = 1e-9;

void expectQueriesMatchOracle(const ConvexPolyhedron& poly, int count) {
  wtc::test::expectRandomQueriesMatchOracle(poly, count, 21, kTolerance * poly.size(), kTolerance * poly.size());
}

// Hull of `count` random points of a ball of radius `radius` centred at `centre`.
ConvexPolyhedron ballHull(int count, double radius, const Vector3d& centre, std::uint64_t seed) {
  wtc::test::RandomPieces random(seed);
  std::vector<Vector3d> points;
  for (int i = 0; i < count; ++i) points.push_back(centre + radius * random.inUnitBall());
  return ConvexPolyhedron::fromPoints(points);
}

TEST(PointQueryExtremeTest, SliverTetrahedraMatchBruteForce) {
  // Case: a tetrahedron 1e-6 thick; a needle (1e-5 base, length 1); the
  // classic sliver (a square's corners lifted alternately by 1e-6); a cap
  // (one vertex 1e-6 off the opposite edge).
  const std::vector<std::vector<Vector3d>> slivers = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.3, 0.3, 1e-6}},
                                                      {{0, 0, 0}, {1e-5, 0, 0}, {0, 1e-5, 0}, {0.2, 0.1, 1}},
                                                      {{0, 0, 0}, {1, 1, 0}, {1, 0, 1e-6}, {0, 1, 1e-6}},
                                                      {{0, 0, 0}, {1, 0, 0}, {0.5, 1e-6, 0}, {0.5, 0.5, 1}}};
  for (const std::vector<Vector3d>& points : slivers) {
    const ConvexPolyhedron poly = ConvexPolyhedron::fromPoints(points);
    EXPECT_FALSE(poly.isFlat());
    EXPECT_EQ(poly.vertexCount(), 4);
    expectQueriesMatchOracle(poly, 3000);
  }
}

// World coordinates near 1e6 m are resolved to ulp(1e6) = 2^-33 m =
// 1.16e-10 m. The closest point is reported in world coordinates: the
// query's rounding and the oracle's each move a coordinate by up to half an
// ulp, so they may differ by one ulp per coordinate, sqrt(3) ulp in norm.
// The distance needs no world coordinate and keeps kTolerance x size.
constexpr double kResolutionAt1e6 = 0x1p-33;                        // m
constexpr double kFarFromOriginTolerance = 2.0 * kResolutionAt1e6;  // m

TEST(PointQueryExtremeTest, MillimetrePieceFarFromOriginKeepsItsPrecision) {
  // Case: a 1 mm box and a 1 mm hull, 1e6 m from the origin on every axis.
  const Vector3d corner(1e6 + 0.123, -1e6 + 0.456, 1e6 - 0.789);
  const ConvexPolyhedron box = ConvexPolyhedron::box(corner, corner + Vector3d(1e-3, 1e-3, 1e-3));
  const ConvexPolyhedron hull = ballHull(40, 0.5e-3, corner, 22);
  for (const ConvexPolyhedron* poly : {&box, &hull}) {
    wtc::test::expectRandomQueriesMatchOracle(*poly, 3000, 21, kFarFromOriginTolerance, kTolerance * poly->size());
  }
  // Exact expectations: 0.5 mm over the middle of the box's top face.
  const Vector3d top = corner + Vector3d(0.5e-3, 0.5e-3, 1e-3);
  const PointQuery got = wtc::queryPoint(box, top + Vector3d(0, 0, 0.5e-3));
  EXPECT_NEAR(got.signed_distance, (top + Vector3d(0, 0, 0.5e-3)).z() - top.z(), kTolerance * box.size());
  EXPECT_LE((got.closest_point - top).norm(), kFarFromOriginTolerance);
  EXPECT_LE((got.direction + Vector3d::UnitZ()).norm(), 1e-12);
}

TEST(PointQueryExtremeTest, MicrometrePieceMatchesBruteForce) {
  // Case: hulls of 1e-6 m, near the origin and 1e-3 m from it.
  expectQueriesMatchOracle(ballHull(30, 1e-6, Vector3d(1e-6, -2e-6, 0.5e-6), 23), 3000);
  expectQueriesMatchOracle(ballHull(30, 1e-6, Vector3d(1e-3, 0, -1e-3), 24), 3000);
}

TEST(PointQueryExtremeTest, TenKilometrePieceMatchesBruteForce) {
  // Case: hulls of 1e4 m, like a quarry floor, near and away from the origin.
  expectQueriesMatchOracle(ballHull(30, 1e4, Vector3d(0, 0, 0), 25), 3000);
  expectQueriesMatchOracle(ballHull(30, 1e4, Vector3d(3e4, -2e4, 1e3), 26), 3000);
}

TEST(PointQueryExtremeTest, AspectRatioOfAMillionMatchesBruteForce) {
  // Case: a 100 m x 1 m x 0.1 mm slab, axis-aligned and rotated, and a
  // 100 m needle of 0.1 mm x 0.1 mm section.
  const ConvexPolyhedron slab = ConvexPolyhedron::box(Vector3d(0, 0, 0), Vector3d(100, 1, 1e-4));
  expectQueriesMatchOracle(slab, 3000);
  std::vector<Vector3d> rotated;
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.3, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  for (int i = 0; i < 8; ++i) {
    rotated.push_back(rotation * Vector3d(i & 1 ? 100 : 0, i & 2 ? 1 : 0, i & 4 ? 1e-4 : 0));
  }
  expectQueriesMatchOracle(ConvexPolyhedron::fromPoints(rotated), 3000);
  expectQueriesMatchOracle(ConvexPolyhedron::box(Vector3d(0, 0, 0), Vector3d(100, 1e-4, 1e-4)), 3000);

  // The thin direction is resolved to the same relative accuracy as the
  // slab's own thickness: 10 um over and under its top face.
  const double thin_tolerance = kTolerance * 1e-4;  // m
  EXPECT_NEAR(wtc::queryPoint(slab, Vector3d(50, 0.5, 1.1e-4)).signed_distance, 1e-5, thin_tolerance);
  EXPECT_NEAR(wtc::queryPoint(slab, Vector3d(50, 0.5, 0.9e-4)).signed_distance, -1e-5, thin_tolerance);
}

// A query point 1e9 m away carries its own rounding: ulp(1e9) = 1.19e-7 m.
// The query forms p - v for vertices v, each rounded to that resolution; the
// closest point and the distance inherit a few such roundings. 1e-6 m is
// 8 ulp(1e9), i.e. a relative error of 1e-15 on the distance.
constexpr double kGigametreTolerance = 1e-6;  // m

TEST(PointQueryExtremeTest, QueryPointsAGigametreAwayAreExactToDoubleResolution) {
  // Case: the 2 m cube seen from 1e9 m in a face, an edge and a vertex region.
  const ConvexPolyhedron cube = ConvexPolyhedron::box(Vector3d(-1, -1, -1), Vector3d(1, 1, 1));
  struct Expected {
    Vector3d p, closest;
  };
  for (const Expected& e : {Expected{{1e9, 0.25, -0.5}, {1, 0.25, -0.5}}, Expected{{1e9, 1e9, 0.5}, {1, 1, 0.5}},
                            Expected{{-1e9, 1e9, -1e9}, {-1, 1, -1}}}) {
    const PointQuery got = wtc::queryPoint(cube, e.p);
    EXPECT_EQ(got.status, wtc::QueryStatus::kOutside);
    EXPECT_NEAR(got.signed_distance, (e.p - e.closest).norm(), kGigametreTolerance);
    EXPECT_LE((got.closest_point - e.closest).norm(), kGigametreTolerance) << wtc::test::describe(got);
    EXPECT_LE((got.direction - (e.closest - e.p).normalized()).norm(), 1e-12) << wtc::test::describe(got);
  }
  // Case: a 64-vertex hull seen from 1e9 m in random directions.
  const ConvexPolyhedron hull = wtc::testing::makeShape(wtc::testing::ShapeId::kHull64);
  const BruteForceOracle oracle(hull);
  wtc::test::RandomPieces random(27);
  for (int i = 0; i < 1000; ++i) {
    const Vector3d p = hull.centroid() + 1e9 * random.onUnitSphere();
    const PointQuery got = wtc::queryPoint(hull, p);
    const wtc::testing::BruteForceResult want = oracle.query(p);
    EXPECT_NEAR(got.signed_distance, want.signed_distance, kGigametreTolerance) << wtc::formatVector(p);
    EXPECT_LE((got.closest_point - want.closest_point).norm(), kGigametreTolerance)
        << wtc::formatVector(p) << ": " << wtc::test::describe(got);
  }
}

}  // namespace point_query_extreme_scales_test
