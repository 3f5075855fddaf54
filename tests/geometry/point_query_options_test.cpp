// wtc::queryPoint's inputs and options: non-finite points and invalid
// options are rejected with a message that names them; the iteration cap,
// max_distance and the warm-start cache do what include/wtc/geometry/point_query.hpp
// promises.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "brute_force.hpp"
#include "query_checks.hpp"
#include "random_pieces.hpp"
#include "scenarios.hpp"
#include "wtc/base/error.hpp"
#include "wtc/geometry/point_query.hpp"

namespace point_query_options_test {

using Eigen::Vector3d;
using testing::AllOf;
using testing::HasSubstr;
using testing::ThrowsMessage;
using wtc::ConvexPolyhedron;
using wtc::InvalidInputError;
using wtc::PointQuery;
using wtc::QueryOptions;
using wtc::QueryStatus;
using wtc::testing::BruteForceOracle;

// Error allowed on distance and closest point, relative to the piece's size
// (dimensionless): the accuracy target of issue 2.
constexpr double kTolerance = 1e-9;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

ConvexPolyhedron cube() { return ConvexPolyhedron::box(Vector3d(-1, -1, -1), Vector3d(1, 1, 1)); }

TEST(PointQueryOptionsTest, NonFiniteQueryPointThrowsNamingTheValue) {
  // Case: NaN and +-infinity in each coordinate, with and without a cache.
  const ConvexPolyhedron poly = cube();
  wtc::QueryCache cache;
  struct Bad {
    Vector3d p;
    const char* printed;  // how the bad coordinate appears in the message
  };
  for (const Bad& bad : {Bad{{kNaN, 0, 1}, "nan"}, Bad{{0, kInf, 0}, "inf"}, Bad{{0, 0, -kInf}, "-inf"}}) {
    EXPECT_THAT([&] { wtc::queryPoint(poly, bad.p); },
                ThrowsMessage<InvalidInputError>(AllOf(HasSubstr("not finite"), HasSubstr(bad.printed))));
    EXPECT_THAT([&] { wtc::queryPoint(poly, bad.p, {}, cache); },
                ThrowsMessage<InvalidInputError>(HasSubstr("not finite")));
  }
}

TEST(PointQueryOptionsTest, InvalidOptionsThrowNamingTheOption) {
  // Case: relative_tolerance outside (0, 1) or NaN; max_iterations < 1;
  // max_distance NaN.
  const ConvexPolyhedron poly = cube();
  const Vector3d p(2, 0, 0);
  for (const double tolerance : {0.0, 1.0, -1e-3, 2.0, kNaN}) {
    QueryOptions options;
    options.relative_tolerance = tolerance;
    EXPECT_THAT([&] { wtc::queryPoint(poly, p, options); },
                ThrowsMessage<InvalidInputError>(HasSubstr("relative_tolerance")))
        << "relative_tolerance = " << tolerance;
  }
  for (const int iterations : {0, -1}) {
    QueryOptions options;
    options.max_iterations = iterations;
    EXPECT_THAT([&] { wtc::queryPoint(poly, p, options); },
                ThrowsMessage<InvalidInputError>(HasSubstr("max_iterations")));
  }
  QueryOptions options;
  options.max_distance = kNaN;
  EXPECT_THAT([&] { wtc::queryPoint(poly, p, options); }, ThrowsMessage<InvalidInputError>(HasSubstr("max_distance")));
}

TEST(PointQueryOptionsTest, IterationCapIsHonouredWithAFiniteUpperBound) {
  // Case: caps of 1, 2 and 3 iterations on a 64-vertex hull. A converged
  // status must be exact; kIterationLimit must carry a finite upper bound:
  // a point of the piece at |signed_distance| from p, not closer than the
  // true distance.
  const ConvexPolyhedron poly = wtc::testing::makeShape(wtc::testing::ShapeId::kHull64);
  const BruteForceOracle oracle(poly);
  const double tolerance = kTolerance * poly.size();
  wtc::test::RandomPieces random(31);
  int limited = 0;
  for (const int cap : {1, 2, 3}) {
    QueryOptions options;
    options.max_iterations = cap;
    for (int i = 0; i < 2000; ++i) {
      const Vector3d p = random.query(poly);
      const PointQuery got = wtc::queryPoint(poly, p, options);
      EXPECT_LE(got.iterations, cap);
      if (got.status != QueryStatus::kIterationLimit) {
        EXPECT_TRUE(wtc::test::agreesWithOracle(poly, oracle, p, got, tolerance)) << "cap " << cap;
        continue;
      }
      ++limited;
      ASSERT_TRUE(std::isfinite(got.signed_distance) && got.closest_point.allFinite() && got.direction.allFinite())
          << wtc::test::describe(got);
      const wtc::testing::BruteForceResult want = oracle.query(p);
      EXPECT_GE(got.signed_distance, want.signed_distance - tolerance) << wtc::formatVector(p);
      EXPECT_LE(oracle.query(got.closest_point).signed_distance, tolerance)
          << "closest point outside the piece: " << wtc::test::describe(got);
      EXPECT_NEAR((got.closest_point - p).norm(), got.signed_distance, tolerance);
      EXPECT_NEAR(got.direction.norm(), 1.0, 1e-12);
    }
  }
  EXPECT_GT(limited, 0) << "no query reached the cap: the test exercised nothing";
}

TEST(PointQueryOptionsTest, DefaultCapIsNotReachedOnARotatedBox) {
  // Case: a rotated 591 m box whose top is split into two coplanar
  // triangles, seen from 0.057 m over it near the split: the support
  // alternates between the two triangles' apexes, so GJK must stop on its
  // bounds, not on a repeated vertex (tolerances.hpp: the default cap "is
  // never reached on valid pieces").
  const ConvexPolyhedron poly =
      ConvexPolyhedron::fromPoints({{-1375.9963226024711, 8171.9438432253346, -8602.5801957207968},
                                    {-1045.0534591126143, 7777.1238222562069, -8513.9421223530953},
                                    {-1040.8919108530047, 7776.1474627054668, -8544.7266012380314},
                                    {-1424.4617469536752, 8123.6114973739332, -8576.2209888535599},
                                    {-1000.7495830210196, 7826.4325276583486, -8509.516850335398},
                                    {-1380.1578708620807, 8172.9202027760748, -8571.7957168358607},
                                    {-1420.3001986940656, 8122.635137823193, -8607.005467738496},
                                    {-996.58803476140997, 7825.4561681076084, -8540.3013292203341}});
  const Vector3d p(-1147.1680163710912, 7961.7178215478289, -8550.207216578674);
  const PointQuery got = wtc::queryPoint(poly, p);
  EXPECT_EQ(got.status, QueryStatus::kOutside) << wtc::test::describe(got);
  EXPECT_LT(got.iterations, wtc::tolerance::kDefaultMaxIterations);
  EXPECT_NEAR(got.signed_distance, wtc::testing::bruteForceQuery(poly, p).signed_distance, kTolerance * poly.size());
}

TEST(PointQueryOptionsTest, ToleranceBelowRoundoffStillTerminatesExactly) {
  // Case: relative_tolerance 1e-300, far below what double can resolve:
  // the query must still stop (a repeated support point ends GJK) and
  // agree with the oracle; it may report kIterationLimit, never loop.
  const ConvexPolyhedron poly = wtc::testing::makeShape(wtc::testing::ShapeId::kHull20);
  const BruteForceOracle oracle(poly);
  QueryOptions options;
  options.relative_tolerance = 1e-300;
  wtc::test::RandomPieces random(32);
  for (int i = 0; i < 2000; ++i) {
    const Vector3d p = random.query(poly);
    const PointQuery got = wtc::queryPoint(poly, p, options);
    EXPECT_NEAR(got.signed_distance, oracle.query(p).signed_distance, kTolerance * poly.size())
        << wtc::formatVector(p) << ": " << wtc::test::describe(got);
  }
}

TEST(PointQueryOptionsTest, MaxDistanceReturnsBeyondWithATrueLowerBound) {
  // Case: the cube seen from 10 m (face region) and from a corner, with
  // max_distance 1 m: kBeyond, and 1 < signed_distance <= the distance.
  const ConvexPolyhedron poly = cube();
  QueryOptions options;
  options.max_distance = 1.0;
  for (const Vector3d& p : {Vector3d(11, 0, 0), Vector3d(11, 11, 11), Vector3d(3, 0.5, 0)}) {
    const double exact = wtc::testing::bruteForceQuery(poly, p).signed_distance;
    const PointQuery got = wtc::queryPoint(poly, p, options);
    EXPECT_EQ(got.status, QueryStatus::kBeyond) << wtc::formatVector(p);
    EXPECT_GT(got.signed_distance, options.max_distance) << wtc::formatVector(p);
    EXPECT_LE(got.signed_distance, exact + kTolerance * poly.size()) << wtc::formatVector(p);
    EXPECT_TRUE(got.closest_point.allFinite() && got.direction.allFinite());
  }
  // Case: nearer than max_distance, and inside: exact, not kBeyond.
  const PointQuery near = wtc::queryPoint(poly, Vector3d(1.5, 0, 0), options);
  EXPECT_EQ(near.status, QueryStatus::kOutside);
  EXPECT_NEAR(near.signed_distance, 0.5, kTolerance * poly.size());
  options.max_distance = 0.0;
  const PointQuery inside = wtc::queryPoint(poly, Vector3d(0.5, 0, 0), options);
  EXPECT_EQ(inside.status, QueryStatus::kInside);
  EXPECT_NEAR(inside.signed_distance, -0.5, kTolerance * poly.size());
}

TEST(PointQueryOptionsTest, WarmStartMatchesColdStartWithNoMoreIterations) {
  // Case: a point circling each catalogue piece on a tilted, wavy orbit
  // that passes inside and outside, 1000 steps, one cache per piece.
  for (const wtc::testing::ShapeId shape : wtc::testing::kAllShapes) {
    const ConvexPolyhedron poly = wtc::testing::makeShape(shape);
    const double size = poly.size();
    wtc::QueryCache cache;
    long warm_iterations = 0;
    long cold_iterations = 0;
    for (int step = 0; step < 1000; ++step) {
      const double t = 2.0 * M_PI * step / 1000.0;
      const Vector3d p =
          poly.centroid() + 0.5 * size * Vector3d(std::cos(t), std::sin(t), 0.3 * std::sin(t) + 0.4 * std::sin(5 * t));
      const PointQuery cold = wtc::queryPoint(poly, p);
      const PointQuery warm = wtc::queryPoint(poly, p, {}, cache);
      EXPECT_NEAR(warm.signed_distance, cold.signed_distance, kTolerance * size)
          << wtc::testing::toString(shape) << " step " << step;
      EXPECT_LE((warm.closest_point - cold.closest_point).norm(), kTolerance * size)
          << wtc::testing::toString(shape) << " step " << step;
      EXPECT_EQ(warm.status, cold.status) << wtc::testing::toString(shape) << " step " << step;
      warm_iterations += warm.iterations;
      cold_iterations += cold.iterations;
    }
    EXPECT_LE(warm_iterations, cold_iterations) << wtc::testing::toString(shape);
  }
}

TEST(PointQueryOptionsTest, DefaultCacheIsAColdStart) {
  // Case: a fresh cache gives exactly the uncached result.
  const ConvexPolyhedron poly = wtc::testing::makeShape(wtc::testing::ShapeId::kHull20);
  wtc::test::RandomPieces random(33);
  for (int i = 0; i < 200; ++i) {
    const Vector3d p = random.query(poly);
    wtc::QueryCache cache;
    const PointQuery warm = wtc::queryPoint(poly, p, {}, cache);
    const PointQuery cold = wtc::queryPoint(poly, p);
    EXPECT_EQ(warm.signed_distance, cold.signed_distance);
    EXPECT_EQ(warm.iterations, cold.iterations);
  }
}

TEST(PointQueryOptionsTest, CacheFromAnotherPieceIsHarmless) {
  // Case: a cache left by a 64-vertex hull, reused on an 8-vertex box: its
  // vertex indices are out of range there and must not be followed.
  const ConvexPolyhedron hull = wtc::testing::makeShape(wtc::testing::ShapeId::kHull64);
  const ConvexPolyhedron box = cube();
  const BruteForceOracle oracle(box);
  wtc::test::RandomPieces random(34);
  for (int i = 0; i < 200; ++i) {
    wtc::QueryCache cache;
    wtc::queryPoint(hull, hull.centroid() + hull.size() * random.onUnitSphere(), {}, cache);
    const Vector3d p = random.query(box);
    const PointQuery got = wtc::queryPoint(box, p, {}, cache);
    EXPECT_TRUE(wtc::test::agreesWithOracle(box, oracle, p, got, kTolerance * box.size()));
  }
}

}  // namespace point_query_options_test
