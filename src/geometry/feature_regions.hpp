#pragma once
// Exact Voronoi-region tests of the point query (docs/point-query.md): the
// nearest face's region, then the one edge or vertex of that face the point
// lies beyond. Where a test holds, the closest point is a projection onto
// that feature, exactly; where it fails, the crossed feature seeds GJK.
#include <cstdint>

#include <Eigen/Core>

#include "wtc/geometry/convex_polyhedron.hpp"

namespace wtc::detail {

struct FaceRegion {
  bool inside = true;             // the projection onto the face lies in it
  int count = 0;                  // seed size, 1 or 2
  std::int32_t seed[2] = {0, 0};  // a vertex, or an edge (a, b)
  std::int32_t only_edge = -1;    // count 2: the face-edge when just one edge is crossed
  std::int32_t into_vertex = -1;  // count 1: the crossed face-edge that ends at the vertex
};

/// Classifies q (local frame) against face `face`'s edges.
FaceRegion classify(const ConvexPolyhedron& poly, const Eigen::Vector3d& q, int face);

/// True, with the closest point (local), when q is in the Voronoi region of
/// the one edge `region` crossed.
bool edgeRegion(const ConvexPolyhedron& poly, const Eigen::Vector3d& q, const FaceRegion& region,
                Eigen::Vector3d* closest);

/// True, with the closest point (local), when q is in the Voronoi region of
/// the vertex `region` points to.
bool vertexRegion(const ConvexPolyhedron& poly, const Eigen::Vector3d& q, const FaceRegion& region,
                  Eigen::Vector3d* closest);

}  // namespace wtc::detail
