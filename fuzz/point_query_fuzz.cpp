// libFuzzer target: the point query against the brute-force oracle
// (tests/support/brute_force.hpp) on hulls of fuzzed points and fuzzed
// query points. Bad hulls (too few or coplanar-collinear points) must be an
// InvalidInputError; anything else thrown, a crash, or a distance off the
// oracle by more than kTolerance is a finding.
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <vector>

#include "brute_force.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"
#include "wtc/base/error.hpp"
#include "wtc/geometry/point_query.hpp"

namespace {

// Coordinates are k / 64 m with |k| <= 2^20: exact in double, so sliver,
// coplanar and duplicate points are easy for the fuzzer to reach.
constexpr double kGrid = 1.0 / 64.0;
constexpr int kMaxGridSteps = 1 << 20;
// The query's distance against the oracle's (relative to the scale of the
// problem: the piece's extent plus the point's distance from the origin).
constexpr double kTolerance = 1e-9;

double coordinate(FuzzedDataProvider& in) {
  return kGrid * in.ConsumeIntegralInRange<int>(-kMaxGridSteps, kMaxGridSteps);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const int count = in.ConsumeIntegralInRange<int>(1, 24);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < count; ++i) points.emplace_back(coordinate(in), coordinate(in), coordinate(in));
  std::optional<wtc::ConvexPolyhedron> poly;
  try {
    poly = wtc::ConvexPolyhedron::fromPoints(points);
  } catch (const wtc::InvalidInputError&) {
    return 0;  // refused with a message: fine
  }
  double extent = 0.0;
  for (const auto& v : points) extent = std::max(extent, v.cwiseAbs().maxCoeff());
  while (in.remaining_bytes() > 0) {
    const Eigen::Vector3d p{coordinate(in), coordinate(in), coordinate(in)};
    const wtc::PointQuery q = wtc::queryPoint(*poly, p);
    const auto oracle = wtc::testing::bruteForceQuery(*poly, p);
    const double scale = 1.0 + extent + p.norm();
    if (!std::isfinite(q.signed_distance) ||
        std::abs(q.signed_distance - oracle.signed_distance) > kTolerance * scale) {
      std::fprintf(stderr, "point (%.17g, %.17g, %.17g): query %.17g, oracle %.17g\n", p.x(), p.y(), p.z(),
                   q.signed_distance, static_cast<double>(oracle.signed_distance));
      std::abort();
    }
  }
  return 0;
}
