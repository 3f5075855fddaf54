#include "query_checks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "random_pieces.hpp"
#include "wtc/base/error.hpp"

namespace wtc::test {
namespace {

using Eigen::Vector3d;

// Unit vectors are normalised in double: a few roundoffs (dimensionless).
constexpr double kUnitTolerance = 1e-12;

// The face whose normal is nearest to `direction`.
int matchingFaceNormal(const ConvexPolyhedron& poly, const Vector3d& direction) {
  int best = 0;
  for (int f = 1; f < poly.faceCount(); ++f) {
    if ((poly.faceNormal(f) - direction).norm() < (poly.faceNormal(best) - direction).norm()) best = f;
  }
  return best;
}

// Height of p above the plane of face f (m), measured from one of the face's
// vertices: n . (p - v) keeps its precision far from the origin, where
// n . p - offset would cancel two large numbers.
double heightAbove(const ConvexPolyhedron& poly, int f, const Vector3d& p) {
  return poly.faceNormal(f).dot(p - poly.vertex(poly.faceVertices(f)[0]));
}

}  // namespace

std::string describe(const PointQuery& r) {
  std::ostringstream out;
  out.precision(17);
  out << "status " << toString(r.status) << ", signed_distance " << r.signed_distance << ", closest_point "
      << formatVector(r.closest_point) << ", direction " << formatVector(r.direction) << ", normal "
      << formatVector(r.normal) << ", iterations " << r.iterations;
  return out.str();
}

::testing::AssertionResult agreesWithOracle(const ConvexPolyhedron& poly, const wtc::testing::BruteForceOracle& oracle,
                                            const Vector3d& p, const PointQuery& got, double tolerance_m) {
  const wtc::testing::BruteForceResult want = oracle.query(p);
  std::ostringstream problems;
  problems.precision(17);
  const auto expect = [&](bool ok, const char* what) {
    if (!ok) problems << "\n  - " << what;
  };

  const bool finite = std::isfinite(got.signed_distance) && got.closest_point.allFinite() &&
                      got.direction.allFinite() && got.normal.allFinite();
  expect(finite, "a result is not finite");
  expect(got.status == QueryStatus::kOutside || got.status == QueryStatus::kInside,
         "status is neither kOutside nor kInside");
  expect(got.iterations >= 0, "negative iteration count");
  expect(std::abs(got.signed_distance - want.signed_distance) <= tolerance_m,
         "signed distance differs from the oracle's");
  if (poly.isFlat()) expect(got.signed_distance >= 0.0, "negative distance to a flat piece");
  if (want.signed_distance > tolerance_m) {
    expect(got.status == QueryStatus::kOutside, "outside but status is not kOutside");
    expect((got.closest_point - want.closest_point).norm() <= tolerance_m, "closest point differs from the oracle's");
  }
  if (want.signed_distance < -tolerance_m) {
    expect(got.status == QueryStatus::kInside, "inside but status is not kInside");
  }
  expect(oracle.surfaceDistance(got.closest_point) <= tolerance_m, "closest point is off the surface");
  expect(std::abs((got.closest_point - p).norm() - std::abs(got.signed_distance)) <= tolerance_m,
         "|closest_point - p| differs from |signed_distance|");
  expect(std::abs(got.direction.norm() - 1.0) <= kUnitTolerance, "direction is not unit");
  expect(std::abs(got.normal.norm() - 1.0) <= kUnitTolerance, "normal is not unit");

  // Conventions follow the query's own verdict (got.signed_distance): near
  // the surface, within the tolerance, the query and the oracle may
  // legitimately disagree on the side (their face planes differ by roundoff).
  const double size = poly.size();
  const double touching = tolerance::kTouchingRelative * size;
  double angle_tolerance = kUnitTolerance;  // of the normal (rad)
  if (got.signed_distance > 2.0 * touching) {
    expect((got.normal + got.direction).norm() <= kUnitTolerance, "outside: normal != -direction");
    // p -> closest point is known to 2 x tolerance over the distance.
    angle_tolerance = std::min(2.0, 2.0 * tolerance_m / std::max(want.signed_distance, tolerance_m));
    if (want.signed_distance > tolerance_m) {
      const Vector3d toward = (want.closest_point - p) / want.signed_distance;
      expect((got.direction - toward).norm() <= angle_tolerance + kUnitTolerance,
             "outside: direction is not along p -> closest point");
    }
  } else if (got.signed_distance < -2.0 * touching) {
    expect((got.normal - got.direction).norm() <= kUnitTolerance, "inside: normal != direction");
    const int f = matchingFaceNormal(poly, got.direction);
    expect((poly.faceNormal(f) - got.direction).norm() <= kUnitTolerance, "inside: direction is not a face normal");
    expect(std::abs(heightAbove(poly, f, p) - got.signed_distance) <= tolerance_m,
           "inside: the direction's face is not at depth |signed_distance|");
  } else if (std::abs(got.signed_distance) < 0.5 * touching) {
    expect((got.normal + got.direction).norm() <= kUnitTolerance, "on the surface: normal != -direction");
    const int f = matchingFaceNormal(poly, got.normal);
    expect((poly.faceNormal(f) - got.normal).norm() <= kUnitTolerance, "on the surface: normal is not a face normal");
    expect(std::abs(heightAbove(poly, f, p)) <= tolerance_m,
           "on the surface: the normal's face does not pass through p");
  } else {
    angle_tolerance = 2.0;  // between conventions: either side's is right
  }
  // The normal is an outward supporting direction at the closest point: no
  // vertex above the plane through it (to the normal's own accuracy).
  double support = -INFINITY;
  for (int i = 0; i < poly.vertexCount(); ++i) {
    support = std::max(support, got.normal.dot(poly.vertex(i) - got.closest_point));
  }
  expect(support <= tolerance_m + angle_tolerance * size, "normal is not a supporting direction at the closest point");

  const std::string found = problems.str();
  if (found.empty()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "query p = " << formatVector(p) << found << "\n  got:  " << describe(got)
                                       << "\n  want: signed_distance " << want.signed_distance << ", closest_point "
                                       << formatVector(want.closest_point) << " (tolerance " << tolerance_m << " m)\n  "
                                       << describe(poly);
}

void expectRandomQueriesMatchOracle(const ConvexPolyhedron& poly, int count, std::uint64_t seed, double tolerance_m,
                                    double distance_tolerance_m) {
  RandomPieces random(seed);
  const wtc::testing::BruteForceOracle oracle(poly);
  int failures = 0;
  for (int i = 0; i < count; ++i) {
    const Vector3d p = random.query(poly);
    const PointQuery got = wtc::queryPoint(poly, p);
    ::testing::AssertionResult result = agreesWithOracle(poly, oracle, p, got, tolerance_m);
    const double exact = oracle.query(p).signed_distance;
    if (result && std::abs(got.signed_distance - exact) > distance_tolerance_m) {
      result = ::testing::AssertionFailure()
               << "signed distance " << got.signed_distance << " at p = " << wtc::formatVector(p)
               << " is off the oracle's " << exact << " by more than " << distance_tolerance_m << " m";
    }
    if (!result && ++failures <= 3) ADD_FAILURE() << "query " << i << ": " << result.message();
  }
  EXPECT_EQ(failures, 0) << "failed cases out of " << count;
}

}  // namespace wtc::test
