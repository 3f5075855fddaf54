// The rare case of the face-region test, out of line: faces of more edges
// than classify's crossing mask holds (hull faces merged from many coplanar
// triangles). The common tests are inline in feature_regions.hpp.
#include "feature_regions.hpp"

namespace wtc::detail {

using Eigen::Vector3d;
using Layout = PolyhedronLayout;

// classify for faces of more than kMaskEdges edges: the crossings counted
// one by one, to the same answer.
FaceRegion classifyLarge(const ConvexPolyhedron& poly, const Vector3d& q, int face) {
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

}  // namespace wtc::detail
