// A body placed inside the ground, said before the run (start_overlap.hpp).
#include "start_overlap.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include "wtc/sim/sim_constants.hpp"

namespace wtc::sim::detail {
namespace {

constexpr int kRimPoints = 16;  // per rim of a cylinder: 22.5 deg apart

// The points of `shape` (in its own frame) that the check looks at.
void shapePoints(const vehicle::Shape& shape, const Eigen::Isometry3d& pose_WS, std::vector<Eigen::Vector3d>& out) {
  using Kind = vehicle::Shape::Kind;
  switch (shape.kind) {
    case Kind::kBox:
      for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d sign((corner & 1) ? 0.5 : -0.5, (corner & 2) ? 0.5 : -0.5, (corner & 4) ? 0.5 : -0.5);
        out.push_back(pose_WS * shape.box_size.cwiseProduct(sign));
      }
      break;
    case Kind::kHull:
      for (const Eigen::Vector3d& p : shape.hull_vertices) out.push_back(pose_WS * p);
      break;
    case Kind::kSphere:
      out.push_back(pose_WS.translation() - shape.radius * Eigen::Vector3d::UnitZ());
      break;
    case Kind::kCylinder: {
      const int a = shape.cylinder_axis, u = (a + 1) % 3, v = (a + 2) % 3;
      for (const double end : {-0.5, 0.5}) {
        for (int k = 0; k < kRimPoints; ++k) {
          const double angle = 2.0 * std::numbers::pi * k / kRimPoints;
          Eigen::Vector3d p = Eigen::Vector3d::Zero();
          p[a] = end * shape.length;
          p[u] = shape.radius * std::cos(angle);
          p[v] = shape.radius * std::sin(angle);
          out.push_back(pose_WS * p);
        }
      }
      break;
    }
    case Kind::kNone:
      break;
  }
}

}  // namespace

std::vector<std::string> startOverlaps(const Terrain& terrain, const vehicle::VehicleDescription& vehicle,
                                       std::span<const vehicle::BodyKinematics> bodies) {
  std::vector<std::string> lines;
  std::vector<Eigen::Vector3d> points;
  std::vector<PieceId> near;
  std::optional<ConvexPolyhedron> scratch;
  for (std::size_t i = 0; i < vehicle.bodies.size(); ++i) {
    const vehicle::Body& body = vehicle.bodies[i];
    if (body.wheel) continue;
    const Eigen::Isometry3d& pose_WB = bodies[i].pose;
    points.clear();
    shapePoints(body.shape, pose_WB, points);
    for (const vehicle::ShapePart& part : body.compound) shapePoints(part.shape, pose_WB * part.pose_BS, points);
    double deepest = kStartOverlapM;
    Eigen::Vector3d where = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : points) {
      near.clear();
      terrain.overlapping(Aabb{p, p}, near);
      for (const PieceId id : near) {
        const double depth = -terrain.piece(id, scratch).planeBound(p);  // > 0 inside: the exact depth
        if (depth > deepest) {
          deepest = depth;
          where = p;
        }
      }
    }
    if (deepest > kStartOverlapM) {
      char text[256];
      std::snprintf(text, sizeof text,
                    "body '%s' starts %.1f mm inside the terrain (its deepest point at (%.3f, %.3f, %.3f) m): the "
                    "engine throws it out in the first step; place the vehicle higher",
                    body.name.c_str(), deepest * 1e3, where.x(), where.y(), where.z());
      lines.emplace_back(text);
    }
  }
  return lines;
}

}  // namespace wtc::sim::detail
