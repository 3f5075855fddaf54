#pragma once
// The shared scenario catalogue: the pieces and query-point sets that the
// tests and bench/point_query_bench.cpp both use, defined once (as Box2D's
// shared/benchmarks.c serves its samples and benchmarks).
//
// Everything is deterministic: a set is a pure function of (piece, set id,
// count, seed), drawn with a portable generator (std::mt19937_64 and our own
// double conversion; std::uniform_real_distribution differs between standard
// libraries), so a failure seen on one machine reproduces on another.
//
// Sets are classified by construction, not by the code under test:
//   face   p = x + t n, x inside a face, n its outward normal, t > 0. The
//          closest point of a convex set to p is x, because n lies in the
//          normal cone at x.
//   edge   p = x + t m, x on an edge (or a vertex), m a strictly positive
//          combination of the normals of the faces meeting there: again
//          inside the normal cone, so x is the closest point, and the closest
//          feature is that edge or vertex.
//   inside rejection sampling against the face planes n_i . p < d_i.
//   near   face or edge points moved by at most kNearBand, inward or outward:
//          the distance to the surface is at most the move.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "wtc/geometry/convex_polyhedron.hpp"

namespace wtc::testing {

enum class ShapeId {
  kBox,     ///< 1 x 0.6 x 0.4 m block, 8 vertices.
  kPrism,   ///< heightfield cell: a tilted ground triangle over a flat base, 6 vertices.
  kHull20,  ///< hull of points on an irregular ellipsoid, exactly 20 vertices.
  kHull64,  ///< the same with exactly 64 vertices (hill-climbing support).
};

enum class QuerySetId {
  kMixed,   ///< uniform in the bounding box scaled 2x about its centre.
  kInside,  ///< strictly inside.
  kFace,    ///< outside, closest feature a face interior.
  kEdge,    ///< outside, closest feature an edge or a vertex.
  kNear,    ///< within kNearBand of the surface, both sides.
  kFar,     ///< kFarMinRelative..kFarMaxRelative x size from the centroid.
};

inline constexpr std::array kAllShapes = {ShapeId::kBox, ShapeId::kPrism, ShapeId::kHull20, ShapeId::kHull64};
inline constexpr std::array kAllQuerySets = {QuerySetId::kMixed, QuerySetId::kInside, QuerySetId::kFace,
                                             QuerySetId::kEdge,  QuerySetId::kNear,   QuerySetId::kFar};

/// Seed of the sets the benchmark and the characterisation tests use.
inline constexpr std::uint64_t kDefaultSeed = 20240611;

/// Half-width of the near-surface band (m).
inline constexpr double kNearBand = 1e-3;
/// Distance from the surface of face and edge points, as a fraction of the
/// piece size (dimensionless): uniform in [min, max].
inline constexpr double kOffsetMinRelative = 1e-3;
inline constexpr double kOffsetMaxRelative = 0.5;
/// Distance of far points from the centroid (multiples of the piece size),
/// log-uniform in [min, max].
inline constexpr double kFarMinRelative = 10.0;
inline constexpr double kFarMaxRelative = 1000.0;

/// "box", "prism", "hull20", "hull64": the names used in benchmark runs.
const char* toString(ShapeId shape);
/// "mixed", "inside", "face", "edge", "near", "far".
const char* toString(QuerySetId set);
std::optional<ShapeId> shapeFromString(std::string_view name);
std::optional<QuerySetId> querySetFromString(std::string_view name);

/// The catalogue piece. Hulls are built once per call (about a millisecond);
/// callers that need a piece often should keep it.
ConvexPolyhedron makeShape(ShapeId shape);

/// The heightfield cell of ShapeId::kPrism built as the terrain builders
/// build it (fromMesh with their face order, src/terrain/builder_support.cpp)
/// instead of through Qhull: the piece the point query's upright prism
/// kernel serves (src/geometry/prism_kernel.hpp); "cell" in the benchmarks.
ConvexPolyhedron makeBuildersCell();

/// The convex hull of points on a slightly irregular ellipsoid (semi-axes
/// 0.5, 0.35, 0.2 m, radius jittered by up to 3 %, rotated off the axes)
/// with exactly `vertex_count` hull vertices (>= 4). Points are added one at
/// a time until the hull has that many vertices: one new point changes the
/// count by at most +1, so the target is met exactly, never overshot.
ConvexPolyhedron makeEllipsoidHull(int vertex_count, std::uint64_t seed);

/// `count` query points of set `set` around `poly` (a solid piece), drawn
/// from `seed`. Throws InvalidInputError for count < 0 or, for the inside,
/// face and edge sets, a flat piece.
std::vector<Eigen::Vector3d> makeQuerySet(const ConvexPolyhedron& poly, QuerySetId set, int count,
                                          std::uint64_t seed = kDefaultSeed);

}  // namespace wtc::testing
