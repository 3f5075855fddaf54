// A placed shape's surface normals at a point (placed_shape.hpp).
#include "sim/placed_shape.hpp"

#include <cmath>

namespace wtc::sim {
namespace {

void add(SurfaceNormals& out, const Eigen::Vector3d& n) { out.normals[static_cast<std::size_t>(out.count++)] = n; }

// A box of half extents h: the faces whose planes pass within reach of p,
// p within reach of the box.
void boxFaces(const Eigen::Vector3d& h, const Eigen::Vector3d& p, double reach, SurfaceNormals& out) {
  if (((p.cwiseAbs() - h).array() > reach).any()) return;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(std::abs(p[i]) - h[i]) <= reach) add(out, Eigen::Vector3d::Unit(i) * (p[i] < 0.0 ? -1.0 : 1.0));
  }
}

// A cylinder along z, radius r, half length l: its side (radial) and its caps.
void cylinderFaces(double r, double l, const Eigen::Vector3d& p, double reach, SurfaceNormals& out) {
  const double rho = p.head<2>().norm();
  if (rho > r + reach || std::abs(p.z()) > l + reach) return;
  if (std::abs(rho - r) <= reach && rho > 0.0) add(out, Eigen::Vector3d(p.x() / rho, p.y() / rho, 0.0));
  if (std::abs(std::abs(p.z()) - l) <= reach) add(out, Eigen::Vector3d(0.0, 0.0, p.z() < 0.0 ? -1.0 : 1.0));
}

}  // namespace

SurfaceNormals surfaceNormals(const PlacedShape& shape, const Eigen::Vector3d& p_W, double reach) {
  const Eigen::Vector3d p = shape.pose.inverse() * p_W;
  SurfaceNormals out;
  switch (shape.kind) {
    case PlacedShape::Kind::kBox:
      boxFaces(shape.half_extents, p, reach, out);
      break;
    case PlacedShape::Kind::kSphere:
      if (std::abs(p.norm() - shape.radius) <= reach && p.norm() > 0.0) add(out, p.normalized());
      break;
    case PlacedShape::Kind::kCylinder:
      cylinderFaces(shape.radius, shape.half_length, p, reach, out);
      break;
    case PlacedShape::Kind::kOther:
      break;
  }
  for (int k = 0; k < out.count; ++k) {
    auto& n = out.normals[static_cast<std::size_t>(k)];
    n = shape.pose.linear() * n;
  }
  return out;
}

}  // namespace wtc::sim
