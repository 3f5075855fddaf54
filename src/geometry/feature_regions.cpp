#include "feature_regions.hpp"

#include "polyhedron_layout.hpp"

namespace wtc::detail {

using Eigen::Vector3d;
using Layout = PolyhedronLayout;

// Which edges of face `face` the projection of q onto its plane lies beyond.
// Face vertices run counter-clockwise about the outward normal n, so the
// projection is on the inner side of edge (a, b) when s . q >= s . a with
// s = n x (b - a), the edge's stored side plane (the projection along n does
// not change s . q). Inside every edge, the projection *is* the closest
// point. Beyond one edge, that edge; beyond two consecutive edges, their
// shared vertex: the feature to test next and, failing that, to seed GJK.
FaceRegion classify(const ConvexPolyhedron& poly, const Vector3d& q, int face) {
  const auto vertices = poly.faceVertices(face);
  const double* side = Layout::faceEdgePlanes(poly, face);
  const auto size = static_cast<int>(vertices.size());
  int crossed[2] = {-1, -1};
  int count = 0;
  for (int k = 0; k < size; ++k, side += 4) {
    if (side[0] * q.x() + side[1] * q.y() + side[2] * q.z() < side[3]) {
      if (count < 2) crossed[count] = k;
      ++count;
    }
  }
  FaceRegion region;
  if (count == 0) return region;
  region.inside = false;
  if (count == 2 && crossed[1] == crossed[0] + 1) {
    region.count = 1;
    region.seed[0] = vertices[crossed[0]];
    region.into_vertex = Layout::faceEdgeStart(poly, face) + crossed[0];
  } else if (count == 2 && crossed[0] == 0 && crossed[1] == size - 1) {
    region.count = 1;
    region.seed[0] = vertices[size - 1];
    region.into_vertex = Layout::faceEdgeStart(poly, face) + size - 1;
  } else {
    region.count = 2;
    region.seed[0] = vertices[(crossed[0] + size - 1) % size];
    region.seed[1] = vertices[crossed[0]];
    if (count == 1) region.only_edge = Layout::faceEdgeStart(poly, face) + crossed[0];
  }
  return region;
}

// The Voronoi region of edge (a, b) shared by faces f and g: q beyond both
// faces' side planes of the edge (the edge's normal cone is the polar of the
// two in-face directions) and between the planes through a and b normal to
// the edge. Inside it the closest point is q's projection on the edge,
// exactly. `region` crossed only this edge of f, so f's side is known; the
// twin face-edge gives g's. Returns false when q is not in the region.
bool edgeRegion(const ConvexPolyhedron& poly, const Vector3d& q, const FaceRegion& region, Vector3d* closest) {
  if (region.only_edge < 0) return false;
  const double* twin = Layout::faceEdgePlane(poly, Layout::faceEdgeTwin(poly, region.only_edge));
  if (twin[0] * q.x() + twin[1] * q.y() + twin[2] * q.z() > twin[3]) return false;
  const Vector3d a = poly.vertexLocal(region.seed[0]);
  const Vector3d ab = poly.vertexLocal(region.seed[1]) - a;
  const double along = (q - a).dot(ab);
  const double length2 = ab.squaredNorm();
  if (along < 0.0 || along > length2) return false;
  *closest = a + (along / length2) * ab;
  return true;
}

// The Voronoi region of vertex a: (q - a) . (c - a) <= 0 for every edge
// (a, c) (the vertex's normal cone is the polar of its edge directions).
// The edges around a are walked through the face-edge twins: from an edge
// ending at a, the next edge of its face leaves a; that edge's twin ends at
// a again, in the neighbouring face; around until back at the start.
bool vertexRegion(const ConvexPolyhedron& poly, const Vector3d& q, const FaceRegion& region, Vector3d* closest) {
  if (region.into_vertex < 0) return false;
  const Vector3d a = poly.vertexLocal(region.seed[0]);
  const Vector3d d = q - a;
  std::int32_t into = region.into_vertex;
  for (int guard = 0; guard < poly.vertexCount(); ++guard) {  // a vertex has < V edges
    const std::int32_t out = Layout::faceEdgeNext(poly, into);
    if (d.dot(poly.vertexLocal(Layout::faceEdgeEnd(poly, out)) - a) > 0.0) return false;
    into = Layout::faceEdgeTwin(poly, out);
    if (into == region.into_vertex) {
      *closest = a;
      return true;
    }
  }
  return false;
}

}  // namespace wtc::detail
