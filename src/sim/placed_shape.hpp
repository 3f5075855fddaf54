#pragma once
// A vehicle body's collision shape where it is, as an engine gives it, and
// the outward normals of its surface at a point of it: one on a box's face,
// a sphere, a cylinder's side or cap; two on an edge, three at a box's
// corner. Where a body's face rests on a terrain edge, a contact's normal
// must be one both surfaces can give there (TerrainNormalCone).
#include <array>
#include <span>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace wtc::sim {

struct PlacedShape {
  enum class Kind { kBox, kSphere, kCylinder, kOther };
  Kind kind = Kind::kOther;
  Eigen::Vector3d half_extents = Eigen::Vector3d::Zero();  ///< A box's (m).
  double radius = 0.0;                                     ///< A sphere's or a cylinder's (m).
  double half_length = 0.0;                                ///< A cylinder's, along its frame's z (m).
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< The shape's frame in the world.
};

/// The normals whose nonnegative combinations are a surface's normal cone at
/// a point: those of the faces through it.
struct SurfaceNormals {
  std::array<Eigen::Vector3d, 3> normals;
  int count = 0;
  std::span<const Eigen::Vector3d> view() const { return {normals.data(), static_cast<std::size_t>(count)}; }
};

/// The outward unit normals (world) of the faces of `shape` that pass within
/// `reach` (m) of p_W, p_W being within `reach` of the shape: a box's faces,
/// a sphere, a cylinder's side and caps. None farther than `reach` from the
/// surface, or for kOther (a convex hull: the engines' hulls are not read
/// back).
SurfaceNormals surfaceNormals(const PlacedShape& shape, const Eigen::Vector3d& p_W, double reach);

}  // namespace wtc::sim
