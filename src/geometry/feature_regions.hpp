#pragma once
// Exact Voronoi-region tests of the point query (docs/point-query.md): the
// nearest face's region, then the one edge or vertex of that face the point
// lies beyond. Where a test holds, the closest point is a projection onto
// that feature, exactly; where it fails, the crossed feature seeds GJK.
#include <bit>
#include <cstdint>

#include <Eigen/Core>

#include "polyhedron_layout.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"

namespace wtc::detail {

struct FaceRegion {
  bool inside = true;             // the projection onto the face lies in it
  int count = 0;                  // seed size, 1 or 2
  std::int32_t seed[2] = {0, 0};  // a vertex, or an edge (a, b)
  std::int32_t only_edge = -1;    // count 2: the face-edge when just one edge is crossed
  std::int32_t into_vertex = -1;  // count 1: the crossed face-edge that ends at the vertex
};

/// Edges per face the crossing mask of classify holds.
inline constexpr int kMaskEdges = 32;

/// classify for faces of more than kMaskEdges edges (feature_regions.cpp).
FaceRegion classifyLarge(const ConvexPolyhedron& poly, const Eigen::Vector3d& q, int face);

// Inline: they run on every outside query, between the plane bound and the
// answer, and a call apiece (with the region passed through memory) cost
// more than their bodies on small pieces.

// Bit k set when q is beyond side plane k of a face of N edges (s . q < s . a).
template <int N>
inline std::uint32_t crossedEdges(const double* side, const Eigen::Vector3d& q) {
  std::uint32_t mask = 0;
#pragma GCC unroll 4
  for (int k = 0; k < N; ++k, side += 4) {
    const bool beyond = side[0] * q.x() + side[1] * q.y() + side[2] * q.z() < side[3];
    mask |= static_cast<std::uint32_t>(beyond) << k;
  }
  return mask;
}

// The region of a face from its crossing mask (bit k set when the
// projection lies beyond edge k; see classify): the face's `size` vertex
// indices `vertices` and its first face-edge `start`.
inline FaceRegion regionOfMask(const std::int32_t* vertices, std::int32_t start, int size, std::uint32_t mask) {
  FaceRegion region;
  if (mask == 0) return region;
  region.inside = false;
  const int first = std::countr_zero(mask);
  if ((mask >> first) == 0b11u) {
    region.count = 1;
    region.seed[0] = vertices[first];
    region.into_vertex = start + first;
  } else if (mask == (1u | (1u << (size - 1)))) {
    region.count = 1;
    region.seed[0] = vertices[size - 1];
    region.into_vertex = start + size - 1;
  } else {
    region.count = 2;
    region.seed[0] = vertices[first == 0 ? size - 1 : first - 1];
    region.seed[1] = vertices[first];
    if ((mask & (mask - 1)) == 0) region.only_edge = start + first;
  }
  return region;
}

/// regionOfMask of face `face` of `poly`, its lists read from the piece.
inline FaceRegion regionOfMask(const ConvexPolyhedron& poly, int face, int size, std::uint32_t mask) {
  return regionOfMask(PolyhedronLayout::faceVertexList(poly, face), PolyhedronLayout::faceEdgeStart(poly, face), size,
                      mask);
}

// Which edges of face `face` the projection of q onto its plane lies beyond.
// Face vertices run counter-clockwise about the outward normal n, so the
// projection is on the inner side of edge (a, b) when s . q >= s . a with
// s = n x (b - a), the edge's stored side plane (the projection along n does
// not change s . q). Inside every edge, the projection *is* the closest
// point. Beyond one edge, that edge; beyond two consecutive edges, their
// shared vertex: the feature to test next and, failing that, to seed GJK.
//
// The crossed edges are gathered as a bit mask, one bit per edge set without
// a branch, and the cases read from it: none crossed; exactly two adjacent
// (the mask shifted down to its lowest bit is 0b11, or the first and the last
// edge); otherwise the lowest crossed edge, alone or not. Faces with more
// edges than the mask holds (hull faces merged from many coplanar
// triangles) count them one by one, to the same answer.
inline FaceRegion classify(const ConvexPolyhedron& poly, const Eigen::Vector3d& q, int face) {
  const int size = PolyhedronLayout::faceSize(poly, face);
  const double* side = PolyhedronLayout::faceEdgePlanes(poly, face);
  if (size > kMaskEdges) return classifyLarge(poly, q, face);
  std::uint32_t mask = 0;
  switch (size) {  // triangles and quads (every face of a prism or a box) unrolled
    case 3:
      mask = crossedEdges<3>(side, q);
      break;
    case 4:
      mask = crossedEdges<4>(side, q);
      break;
    default:
      for (int k = 0; k < size; ++k, side += 4) {
        const bool beyond = side[0] * q.x() + side[1] * q.y() + side[2] * q.z() < side[3];
        mask |= static_cast<std::uint32_t>(beyond) << k;
      }
  }
  return regionOfMask(poly, face, size, mask);
}

// The Voronoi region of edge (a, b) shared by faces f and g: q beyond both
// faces' side planes of the edge (the edge's normal cone is the polar of the
// two in-face directions) and between the planes through a and b normal to
// the edge. Inside it the closest point is q's projection on the edge,
// exactly. `region` crossed only this edge of f, so f's side is known; the
// twin face-edge gives g's side plane, `twin` (4 doubles: s, s . a).
// Returns false when q is not in the region.
inline bool edgeRegionBeyond(const ConvexPolyhedron& poly, const Eigen::Vector3d& q, const FaceRegion& region,
                             const double* twin, Eigen::Vector3d* closest) {
  if (twin[0] * q.x() + twin[1] * q.y() + twin[2] * q.z() > twin[3]) return false;
  const Eigen::Vector3d a = poly.vertexLocal(region.seed[0]);
  const Eigen::Vector3d ab = poly.vertexLocal(region.seed[1]) - a;
  const double along = (q - a).dot(ab);
  const double length2 = ab.squaredNorm();
  if (along < 0.0 || along > length2) return false;
  *closest = a + (along / length2) * ab;
  return true;
}

/// edgeRegionBeyond with the twin's side plane looked up in the piece.
inline bool edgeRegion(const ConvexPolyhedron& poly, const Eigen::Vector3d& q, const FaceRegion& region,
                       Eigen::Vector3d* closest) {
  if (region.only_edge < 0) return false;
  const double* twin = PolyhedronLayout::faceEdgePlane(poly, PolyhedronLayout::faceEdgeTwin(poly, region.only_edge));
  return edgeRegionBeyond(poly, q, region, twin, closest);
}

// The Voronoi region of vertex a: (q - a) . (c - a) <= 0 for every edge
// (a, c) (the vertex's normal cone is the polar of its edge directions).
// The edges around a are walked through the face-edge twins: from an edge
// ending at a, the next edge of its face leaves a; that edge's twin ends at
// a again, in the neighbouring face; around until back at the start.
inline bool vertexRegion(const ConvexPolyhedron& poly, const Eigen::Vector3d& q, const FaceRegion& region,
                         Eigen::Vector3d* closest) {
  if (region.into_vertex < 0) return false;
  const Eigen::Vector3d a = poly.vertexLocal(region.seed[0]);
  const Eigen::Vector3d d = q - a;
  std::int32_t into = region.into_vertex;
  for (int guard = 0; guard < poly.vertexCount(); ++guard) {  // a vertex has < V edges
    const std::int32_t out = PolyhedronLayout::faceEdgeNext(poly, into);
    if (d.dot(poly.vertexLocal(PolyhedronLayout::faceEdgeEnd(poly, out)) - a) > 0.0) return false;
    into = PolyhedronLayout::faceEdgeTwin(poly, out);
    if (into == region.into_vertex) {
      *closest = a;
      return true;
    }
  }
  return false;
}

}  // namespace wtc::detail
