// A body's hull, eroded by Bullet's margin (body_hull.hpp).
#include "body_hull.hpp"

#include <algorithm>
#include <limits>

#include "wtc/base/error.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"

namespace wtc::bullet {

// The hull eroded by m: { x : n_f . x <= d_f - m } over its faces f. Its
// vertices come from the polar dual about the centroid c: face f, at
// distance e_f = d_f - m - n_f . c from c, is the dual point n_f / e_f; a
// face of the dual points' hull, u . q = k (k > 0), is the eroded hull's
// vertex c + u / k (every shifted face plane holds it, with equality for
// the faces whose dual points span that dual face). Qhull builds both hulls
// (ConvexPolyhedron::fromPoints).
std::unique_ptr<btConvexHullShape> makeBodyHull(const std::vector<Eigen::Vector3d>& points) {
  const ConvexPolyhedron hull = ConvexPolyhedron::fromPoints(points);
  const Eigen::Vector3d c = hull.centroid();
  double depth = std::numeric_limits<double>::infinity();  // from c to the nearest face (m)
  for (int f = 0; f < hull.faceCount(); ++f) {
    depth = std::min(depth, hull.faceOffset(f) - hull.faceNormal(f).dot(c));
  }
  if (hull.isFlat() || !(depth > 0.0)) {
    throw InvalidInputError("wtc::bullet sim engine: a body's hull spans no volume (" +
                            std::to_string(hull.vertexCount()) + " vertices in one plane)");
  }
  const double m = std::min(kBodyHullMarginM, kBodyHullMarginShare * depth);
  std::vector<Eigen::Vector3d> dual;
  dual.reserve(static_cast<std::size_t>(hull.faceCount()));
  for (int f = 0; f < hull.faceCount(); ++f) {
    const Eigen::Vector3d n = hull.faceNormal(f);
    dual.push_back(n / (hull.faceOffset(f) - m - n.dot(c)));
  }
  const ConvexPolyhedron polar = ConvexPolyhedron::fromPoints(dual);
  auto shape = std::make_unique<btConvexHullShape>();
  for (int g = 0; g < polar.faceCount(); ++g) {
    const Eigen::Vector3d p = c + polar.faceNormal(g) / polar.faceOffset(g);
    shape->addPoint(btVector3(p.x(), p.y(), p.z()), false);
  }
  shape->recalcLocalAabb();
  shape->setMargin(m);
  return shape;
}

}  // namespace wtc::bullet
