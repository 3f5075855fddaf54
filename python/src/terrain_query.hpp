#pragma once
// The terrain's point query: the signed distance from a point to the
// ground, the ground's outward normal there and the piece it belongs to —
// the nearest piece among those whose boxes come within `reach` of the
// point (queryPoint on each, the smallest signed distance; ties keep the
// lower id). wtc.Terrain.query runs it over a NumPy array in one C++ loop;
// the benchmark (bench/python_batch_query_bench.py) compares that loop
// with this function called point by point from C++.
#include <Eigen/Core>
#include <limits>
#include <optional>
#include <vector>

#include "wtc/geometry/convex_polyhedron.hpp"
#include "wtc/terrain/terrain.hpp"

namespace wtc::python {

struct TerrainPoint {
  /// Signed distance to the ground (m): > 0 above it, < 0 inside a piece;
  /// +inf when no piece comes within reach.
  double distance = std::numeric_limits<double>::infinity();
  Eigen::Vector3d normal{Eigen::Vector3d::Zero()};  ///< Outward, unit; zero with no piece.
  PieceId piece = -1;                               ///< The nearest piece; -1 with none.
};

/// Scratch memory of the query, reused from point to point.
struct TerrainQueryScratch {
  std::vector<PieceId> candidates;
  std::optional<ConvexPolyhedron> formed;
};

/// The query at `p` (finite; InvalidInputError otherwise), pieces within
/// `reach` (m, > 0 and finite) only.
TerrainPoint queryTerrain(const Terrain& terrain, const Eigen::Vector3d& p, double reach, TerrainQueryScratch& scratch);

}  // namespace wtc::python
