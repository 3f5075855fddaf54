#pragma once
// The point query: signed distance from a point to a convex polyhedron, by
// the modified GJK of the wheel-terrain model (docs/point-query.md).
//
// One of GJK's two sets is the single point p, so the Minkowski difference is
// the polyhedron shifted by -p and the support function is the polyhedron's
// own. The simplex sub-algorithm is the signed-volumes method (Montanari,
// Petrinic, Barbieri, "Improving the GJK algorithm for faster and more
// reliable distance queries between convex objects", ACM TOG 36(3), 2017).
// Around it, exact accelerations:
//   1. the bounding box gives a lower bound for the `max_distance` early exit;
//   2. the face-plane bound max_i(n_i . p - d_i) is the exact signed distance
//      when p is inside (no GJK at all) and a lower bound outside;
//   3. Voronoi-region tests on the nearest face, the one edge or vertex of it
//      that p lies beyond: where they hold, the closest point is a
//      projection, exact; otherwise they seed GJK with that edge or vertex;
//   4. a caller-owned QueryCache warm-starts GJK from the previous simplex.
#include <cstdint>
#include <limits>

#include <Eigen/Core>

#include "wtc/base/tolerances.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"

namespace wtc {

enum class QueryStatus : std::uint8_t {
  kOutside,         ///< p outside; distance exact to the tolerance.
  kInside,          ///< p in the closed polyhedron; signed_distance <= 0, exact.
  kBeyond,          ///< Proved farther than max_distance; signed_distance is
                    ///< a lower bound, closest_point and direction approximate.
  kIterationLimit,  ///< Cap reached; best upper bound returned, still finite.
};

const char* toString(QueryStatus status);

struct QueryOptions {
  /// Stop when the GJK bounds prove the closest point to within this
  /// fraction of the distance (dimensionless, in (0, 1)); the distance is
  /// then within tol^2 / 2 of it. The exact stop (no new support vertex)
  /// usually comes first.
  double relative_tolerance = tolerance::kQueryRelativeTolerance;
  /// Iteration cap (>= 1): the query never loops beyond it.
  int max_iterations = tolerance::kDefaultMaxIterations;
  /// Distances above this need not be exact (m): the query returns kBeyond
  /// as soon as a lower bound exceeds it. +inf disables the early exit.
  double max_distance = std::numeric_limits<double>::infinity();
  /// Resolve the nearest face's, edge's and vertex's Voronoi regions exactly
  /// before GJK (docs/point-query.md). Off: the plain modified GJK after the
  /// plane bound, for comparison and for testing GJK alone.
  bool feature_regions = true;
};

/// Warm start for a point that moves a little between queries (a wheel
/// centre between steps). Owned by the caller, one per (point, piece) pair;
/// a default-constructed cache means a cold start. The cached simplex is
/// used when it starts nearer than the nearest-face seed; indices out of
/// range (a cache from another piece) are ignored.
struct QueryCache {
  std::int32_t count = 0;  ///< Vertices in the last simplex (0..3).
  std::int32_t vertex[3] = {0, 0, 0};
};

struct PointQuery {
  /// Distance from p to the surface (m): positive outside, negative inside.
  double signed_distance = 0.0;
  /// The point of the surface closest to p (world, m).
  Eigen::Vector3d closest_point{Eigen::Vector3d::Zero()};
  /// Unit vector from p toward closest_point when outside; the outward normal
  /// of the nearest face when inside. When p is on the surface (within
  /// tolerance::kTouchingRelative x size) it is minus that face's normal, the
  /// limit from outside.
  Eigen::Vector3d direction{Eigen::Vector3d::UnitZ()};
  /// Outward surface normal seen from p: -direction outside, the nearest
  /// face's normal inside. Continuous as p crosses the surface, so contact
  /// code can use it on both sides.
  Eigen::Vector3d normal{Eigen::Vector3d::UnitZ()};
  /// GJK iterations (support evaluations); 0 when the bounds alone decided.
  int iterations = 0;
  QueryStatus status = QueryStatus::kOutside;
};

/// Signed distance, closest point and direction from p to `poly`.
/// Throws InvalidInputError if p is not finite or the options are invalid
/// (tolerance outside (0, 1), max_iterations < 1, NaN max_distance).
PointQuery queryPoint(const ConvexPolyhedron& poly, const Eigen::Vector3d& p, const QueryOptions& options = {});

/// The same query, warm-started from `cache` and leaving the final simplex
/// in it for the next call.
PointQuery queryPoint(const ConvexPolyhedron& poly, const Eigen::Vector3d& p, const QueryOptions& options,
                      QueryCache& cache);

}  // namespace wtc
