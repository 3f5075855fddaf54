// A body's shape as convex hulls (body_hulls.hpp).
#include "wtc/vehicle/body_hulls.hpp"

#include <cmath>
#include <numbers>

#include "wtc/base/error.hpp"

namespace wtc::vehicle {

ConvexPolyhedron convexHull(const Shape& shape) {
  std::vector<Eigen::Vector3d> points;
  switch (shape.kind) {
    case Shape::Kind::kBox:
      return ConvexPolyhedron::box(-0.5 * shape.box_size, 0.5 * shape.box_size);
    case Shape::Kind::kHull:
      return ConvexPolyhedron::fromPoints(shape.hull_vertices);
    case Shape::Kind::kCylinder: {
      // The axis is the shape frame's cylinder_axis; (u, v) the two others.
      const int a = shape.cylinder_axis, u = (a + 1) % 3, v = (a + 2) % 3;
      for (int k = 0; k < kCylinderHullSides; ++k) {
        const double angle = 2.0 * std::numbers::pi * k / kCylinderHullSides;
        for (const double end : {-0.5, 0.5}) {
          Eigen::Vector3d p;
          p[a] = end * shape.length;
          p[u] = shape.radius * std::cos(angle);
          p[v] = shape.radius * std::sin(angle);
          points.push_back(p);
        }
      }
      return ConvexPolyhedron::fromPoints(points);
    }
    case Shape::Kind::kSphere: {
      points.push_back(shape.radius * Eigen::Vector3d::UnitZ());
      points.push_back(-shape.radius * Eigen::Vector3d::UnitZ());
      for (int ring = 1; ring < kSphereHullRings; ++ring) {
        const double polar = std::numbers::pi * ring / kSphereHullRings;
        for (int k = 0; k < 2 * kSphereHullRings; ++k) {
          const double azimuth = std::numbers::pi * k / kSphereHullRings;
          points.emplace_back(shape.radius * std::sin(polar) * std::cos(azimuth),
                              shape.radius * std::sin(polar) * std::sin(azimuth), shape.radius * std::cos(polar));
        }
      }
      return ConvexPolyhedron::fromPoints(points);
    }
    case Shape::Kind::kNone:
      break;
  }
  throw InvalidInputError("wtc::vehicle::convexHull: a shape of kind none has no hull");
}

std::vector<ConvexPolyhedron> convexHulls(const Body& body) {
  std::vector<ConvexPolyhedron> hulls;
  if (!body.compound.empty()) {
    for (const ShapePart& part : body.compound) {
      const ConvexPolyhedron local = convexHull(part.shape);
      std::vector<Eigen::Vector3d> points;
      for (int v = 0; v < local.vertexCount(); ++v) points.push_back(part.pose_BS * local.vertex(v));
      hulls.push_back(ConvexPolyhedron::fromPoints(points));
    }
    return hulls;
  }
  if (body.shape.kind != Shape::Kind::kNone) hulls.push_back(convexHull(body.shape));
  return hulls;
}

}  // namespace wtc::vehicle
