// Geometric hard cases of wtc::queryPoint, each a named test with its
// tolerance: points exactly on faces, edges and vertices; inside, at the
// centroid and a hair under a face; flat pieces; duplicated and nearly
// coincident vertices. The limits of double precision (slivers, far from
// the origin, extreme scales and aspect ratios, far query points) are in
// point_query_extreme_scales_test.cpp.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "brute_force.hpp"
#include "query_checks.hpp"
#include "random_pieces.hpp"
#include "scenarios.hpp"
#include "wtc/base/error.hpp"
#include "wtc/geometry/point_query.hpp"

namespace point_query_hard_cases_test {

using Eigen::Vector3d;
using testing::AnyOf;
using testing::Eq;
using wtc::ConvexPolyhedron;
using wtc::PointQuery;
using wtc::QueryStatus;
using wtc::testing::BruteForceOracle;

// Error allowed on distance and closest point, relative to the piece's size
// (dimensionless): the accuracy target of issue 2.
constexpr double kTolerance = 1e-9;
// Unit vectors are exact to a few roundoffs (dimensionless).
constexpr double kUnitTolerance = 1e-12;

// |got - want| <= tolerance_m, with both vectors in the message.
testing::AssertionResult isNear(const Vector3d& got, const Vector3d& want, double tolerance_m) {
  if ((got - want).norm() <= tolerance_m) return testing::AssertionSuccess();
  return testing::AssertionFailure() << wtc::formatVector(got) << " is " << (got - want).norm() << " m from "
                                     << wtc::formatVector(want) << " (tolerance " << tolerance_m << " m)";
}

ConvexPolyhedron cube() { return ConvexPolyhedron::box(Vector3d(-1, -1, -1), Vector3d(1, 1, 1)); }

TEST(PointQueryHardCaseTest, PointOnFaceReturnsZeroDistance) {
  // Case: p on the +x face of the cube: distance 0, the face normal.
  const ConvexPolyhedron poly = cube();
  const Vector3d p(1.0, 0.25, -0.5);
  const PointQuery got = wtc::queryPoint(poly, p);
  EXPECT_NEAR(got.signed_distance, 0.0, kTolerance * poly.size());
  EXPECT_TRUE(isNear(got.closest_point, p, kTolerance * poly.size())) << wtc::test::describe(got);
  EXPECT_TRUE(isNear(got.normal, Vector3d::UnitX(), kUnitTolerance)) << wtc::test::describe(got);
  EXPECT_TRUE(isNear(got.direction, -Vector3d::UnitX(), kUnitTolerance)) << wtc::test::describe(got);
  EXPECT_THAT(got.status, AnyOf(Eq(QueryStatus::kOutside), Eq(QueryStatus::kInside)));
}

TEST(PointQueryHardCaseTest, PointOnEdgeReturnsZeroDistance) {
  // Case: p on the edge x = y = 1: distance 0, the normal of either face.
  const ConvexPolyhedron poly = cube();
  const Vector3d p(1.0, 1.0, 0.3);
  const PointQuery got = wtc::queryPoint(poly, p);
  EXPECT_NEAR(got.signed_distance, 0.0, kTolerance * poly.size());
  EXPECT_TRUE(isNear(got.closest_point, p, kTolerance * poly.size())) << wtc::test::describe(got);
  EXPECT_TRUE(isNear(got.normal, Vector3d::UnitX(), kUnitTolerance) ||
              isNear(got.normal, Vector3d::UnitY(), kUnitTolerance))
      << wtc::test::describe(got);
  EXPECT_TRUE(isNear(got.direction, -got.normal, kUnitTolerance)) << wtc::test::describe(got);
}

TEST(PointQueryHardCaseTest, PointOnVertexReturnsZeroDistance) {
  // Case: p on the corner (1, 1, 1): distance 0, the normal of a face there.
  const ConvexPolyhedron poly = cube();
  const Vector3d p(1.0, 1.0, 1.0);
  const PointQuery got = wtc::queryPoint(poly, p);
  EXPECT_NEAR(got.signed_distance, 0.0, kTolerance * poly.size());
  EXPECT_TRUE(isNear(got.closest_point, p, kTolerance * poly.size())) << wtc::test::describe(got);
  EXPECT_NEAR(got.normal.maxCoeff(), 1.0, kUnitTolerance) << wtc::test::describe(got);
  EXPECT_TRUE(isNear(got.direction, -got.normal, kUnitTolerance)) << wtc::test::describe(got);
}

TEST(PointQueryHardCaseTest, EveryVertexAndEdgeOfAHullIsAtZeroDistance) {
  // Case: all vertices and edge midpoints of a 64-vertex hull.
  const ConvexPolyhedron poly = wtc::testing::makeShape(wtc::testing::ShapeId::kHull64);
  const BruteForceOracle oracle(poly);
  for (int f = 0; f < poly.faceCount(); ++f) {
    const auto face = poly.faceVertices(f);
    for (std::size_t k = 0; k < face.size(); ++k) {
      const Vector3d a = poly.vertex(face[k]);
      const Vector3d b = poly.vertex(face[(k + 1) % face.size()]);
      for (const Vector3d& p : {a, Vector3d(0.5 * (a + b))}) {
        const PointQuery got = wtc::queryPoint(poly, p);
        EXPECT_NEAR(got.signed_distance, 0.0, kTolerance * poly.size()) << "face " << f << ", k " << k;
        EXPECT_TRUE(wtc::test::agreesWithOracle(poly, oracle, p, got, kTolerance * poly.size()));
      }
    }
  }
}

TEST(PointQueryHardCaseTest, CentroidIsInsideAtTheNearestFaceDepth) {
  // Case: the centre of a 2 x 4 x 6 box is 1 under the two x faces.
  const ConvexPolyhedron poly = ConvexPolyhedron::box(Vector3d(-1, -2, -3), Vector3d(1, 2, 3));
  const PointQuery got = wtc::queryPoint(poly, poly.centroid());
  EXPECT_EQ(got.status, QueryStatus::kInside);
  EXPECT_NEAR(got.signed_distance, -1.0, kTolerance * poly.size());
  EXPECT_NEAR(std::abs(got.direction.x()), 1.0, kUnitTolerance) << wtc::test::describe(got);
  EXPECT_TRUE(isNear(got.normal, got.direction, kUnitTolerance)) << wtc::test::describe(got);
  EXPECT_TRUE(isNear(got.closest_point, got.direction, kTolerance * poly.size())) << wtc::test::describe(got);
}

TEST(PointQueryHardCaseTest, CentroidOfACubeTiesSixFacesAndPicksOne) {
  // Case: at the cube's centre all six faces are nearest; any one will do.
  const ConvexPolyhedron poly = cube();
  const PointQuery got = wtc::queryPoint(poly, Vector3d::Zero());
  EXPECT_EQ(got.status, QueryStatus::kInside);
  EXPECT_NEAR(got.signed_distance, -1.0, kTolerance * poly.size());
  EXPECT_NEAR(got.direction.cwiseAbs().maxCoeff(), 1.0, kUnitTolerance) << wtc::test::describe(got);
  EXPECT_TRUE(isNear(got.closest_point, got.direction, kTolerance * poly.size())) << wtc::test::describe(got);
}

// A hair is 1e-12 of the piece's size. The answer is exact up to the
// rounding of 1 -/+ hair itself, half an ulp of 1 (1.1e-16 m): a few ulps.
constexpr double kHairTolerance = 1e-15;  // m

TEST(PointQueryHardCaseTest, PointAHairInsideAFaceIsInside) {
  // Case: 1e-12 x size under the +x face: inside, depth the hair.
  const ConvexPolyhedron poly = cube();
  const double hair = 1e-12 * poly.size();
  const PointQuery got = wtc::queryPoint(poly, Vector3d(1.0 - hair, 0.2, 0.3));
  EXPECT_EQ(got.status, QueryStatus::kInside);
  EXPECT_NEAR(got.signed_distance, -hair, kHairTolerance);
  EXPECT_TRUE(isNear(got.direction, Vector3d::UnitX(), kUnitTolerance)) << wtc::test::describe(got);
  EXPECT_TRUE(isNear(got.normal, Vector3d::UnitX(), kUnitTolerance)) << wtc::test::describe(got);
  EXPECT_TRUE(isNear(got.closest_point, Vector3d(1.0, 0.2, 0.3), kHairTolerance));
}

TEST(PointQueryHardCaseTest, PointAHairOutsideAFaceIsOutside) {
  // Case: 1e-12 x size over the +x face: outside, distance the hair.
  const ConvexPolyhedron poly = cube();
  const double hair = 1e-12 * poly.size();
  const PointQuery got = wtc::queryPoint(poly, Vector3d(1.0 + hair, 0.2, 0.3));
  EXPECT_EQ(got.status, QueryStatus::kOutside);
  EXPECT_NEAR(got.signed_distance, hair, kHairTolerance);
  EXPECT_TRUE(isNear(got.direction, -Vector3d::UnitX(), kUnitTolerance)) << wtc::test::describe(got);
  EXPECT_TRUE(isNear(got.normal, Vector3d::UnitX(), kUnitTolerance)) << wtc::test::describe(got);
  EXPECT_TRUE(isNear(got.closest_point, Vector3d(1.0, 0.2, 0.3), kHairTolerance));
}

TEST(PointQueryHardCaseTest, FlatSquareHasNoInside) {
  // Case: a 2 x 2 square in z = 0 (with its centre as a fifth point).
  const ConvexPolyhedron poly =
      ConvexPolyhedron::fromPoints({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 0}});
  ASSERT_TRUE(poly.isFlat());
  const double tolerance = kTolerance * poly.size();
  struct Expected {
    Vector3d p, closest;
  };
  for (const Expected& e : {Expected{{0.3, 0.2, 0.0}, {0.3, 0.2, 0.0}},     // on the polygon
                            Expected{{0.3, 0.2, -0.5}, {0.3, 0.2, 0.0}},    // under it
                            Expected{{0.3, 0.2, 0.5}, {0.3, 0.2, 0.0}},     // over it
                            Expected{{3.0, 0.5, 0.0}, {1.0, 0.5, 0.0}},     // beside it, in its plane
                            Expected{{3.0, 3.0, 2.0}, {1.0, 1.0, 0.0}}}) {  // off a corner
    const PointQuery got = wtc::queryPoint(poly, e.p);
    EXPECT_GE(got.signed_distance, 0.0) << wtc::formatVector(e.p);
    EXPECT_NEAR(got.signed_distance, (e.p - e.closest).norm(), tolerance) << wtc::formatVector(e.p);
    EXPECT_TRUE(isNear(got.closest_point, e.closest, tolerance)) << wtc::test::describe(got);
    EXPECT_NE(got.status, QueryStatus::kIterationLimit);
  }
  wtc::test::expectRandomQueriesMatchOracle(poly, 2000, 11, tolerance, tolerance);
}

TEST(PointQueryHardCaseTest, FlatTriangleOfThreePointsMatchesBruteForce) {
  // Case: the minimum flat piece, a tilted triangle far from the axes.
  const ConvexPolyhedron poly = ConvexPolyhedron::fromPoints({{10.0, 3.0, 1.0}, {11.0, 3.5, 1.2}, {10.2, 4.1, 2.0}});
  ASSERT_TRUE(poly.isFlat());
  wtc::test::expectRandomQueriesMatchOracle(poly, 2000, 11, kTolerance * poly.size(), kTolerance * poly.size());
}

TEST(PointQueryHardCaseTest, DuplicatedVerticesAreMergedAndQueriesExact) {
  // Case: each cube corner given three times, plus interior points.
  std::vector<Vector3d> points;
  for (int copy = 0; copy < 3; ++copy) {
    for (int i = 0; i < 8; ++i) points.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    points.emplace_back(0.1 * copy, 0.0, 0.0);
  }
  const ConvexPolyhedron poly = ConvexPolyhedron::fromPoints(points);
  EXPECT_EQ(poly.vertexCount(), 8);
  EXPECT_EQ(poly.faceCount(), 6);
  wtc::test::expectRandomQueriesMatchOracle(poly, 2000, 11, kTolerance * poly.size(), kTolerance * poly.size());
  EXPECT_NEAR(wtc::queryPoint(poly, Vector3d(2, 0, 0)).signed_distance, 1.0, kTolerance * poly.size());
}

TEST(PointQueryHardCaseTest, NearlyCoincidentVerticesAreMergedAndQueriesExact) {
  // Case: each cube corner with three copies moved by 1e-12 x size, far
  // below the merge tolerance (tolerance::kHullMergeRelative = 1e-9).
  wtc::test::RandomPieces random(12);
  std::vector<Vector3d> points;
  for (int i = 0; i < 8; ++i) {
    const Vector3d corner(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    for (int copy = 0; copy < 4; ++copy) points.push_back(corner + 3.5e-12 * random.onUnitSphere());
  }
  const ConvexPolyhedron poly = ConvexPolyhedron::fromPoints(points);
  EXPECT_EQ(poly.vertexCount(), 8);
  wtc::test::expectRandomQueriesMatchOracle(poly, 2000, 11, kTolerance * poly.size(), kTolerance * poly.size());
  // The merged piece is the cube to within the moves.
  EXPECT_NEAR(wtc::queryPoint(poly, Vector3d(2, 0.5, 0)).signed_distance, 1.0, kTolerance * poly.size());
}

TEST(PointQueryHardCaseTest, NearlyCoincidentVerticesAboveTheMergeToleranceStayExact) {
  // Case: corner copies moved by 1e-7 x size: kept, making tiny edges and
  // faces the query must still resolve.
  wtc::test::RandomPieces random(13);
  std::vector<Vector3d> points;
  for (int i = 0; i < 8; ++i) {
    const Vector3d corner(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    for (int copy = 0; copy < 3; ++copy) points.push_back(corner + 3.5e-7 * random.onUnitSphere());
  }
  const ConvexPolyhedron poly = ConvexPolyhedron::fromPoints(points);
  EXPECT_GT(poly.vertexCount(), 8);
  wtc::test::expectRandomQueriesMatchOracle(poly, 5000, 11, kTolerance * poly.size(), kTolerance * poly.size());
}

}  // namespace point_query_hard_cases_test
