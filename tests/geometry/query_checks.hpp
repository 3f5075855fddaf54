#pragma once
// What a converged point query must satisfy, checked against the brute-force
// oracle and the conventions of include/wtc/geometry/point_query.hpp:
//   - every number finite, direction and normal unit;
//   - signed distance within `tolerance_m` of the oracle's; never negative
//     on a flat piece; status kOutside / kInside when the oracle's distance
//     is beyond the tolerance on that side;
//   - closest point within `tolerance_m` of the oracle's when outside (it is
//     unique there); always on the surface and |signed distance| from p;
//   - the sign conventions, judged by the query's own verdict (within the
//     tolerance of the surface, query and oracle may legitimately see
//     different sides: their face planes differ by roundoff):
//       outside: normal = -direction, direction along p -> closest point;
//       inside: normal = direction = the normal of a face at that depth;
//       on the surface (|signed distance| < tolerance::kTouchingRelative x
//       size): normal = -direction = the normal of a face through p;
//   - normal an outward supporting direction at the closest point: no vertex
//     above the plane through it, to the normal's own accuracy.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cstdint>
#include <string>

#include "brute_force.hpp"
#include "wtc/geometry/point_query.hpp"

namespace wtc::test {

::testing::AssertionResult agreesWithOracle(const ConvexPolyhedron& poly, const wtc::testing::BruteForceOracle& oracle,
                                            const Eigen::Vector3d& p, const PointQuery& got, double tolerance_m);

/// The result as text, for failure messages.
std::string describe(const PointQuery& result);

/// `count` random queries around `poly` (seeded), each checked with
/// agreesWithOracle at `tolerance_m` and its signed distance within
/// `distance_tolerance_m` of the oracle's; the first 3 failures are printed.
void expectRandomQueriesMatchOracle(const ConvexPolyhedron& poly, int count, std::uint64_t seed, double tolerance_m,
                                    double distance_tolerance_m);

}  // namespace wtc::test
