#pragma once
#include <Eigen/Core>

namespace wtc {

/// Axis-aligned bounding box in the world frame (m).
struct Aabb {
  Eigen::Vector3d min{Eigen::Vector3d::Constant(0.0)};
  Eigen::Vector3d max{Eigen::Vector3d::Constant(0.0)};

  Eigen::Vector3d center() const { return 0.5 * (min + max); }
  Eigen::Vector3d extent() const { return max - min; }

  /// Squared distance from p to the box (m^2), 0 inside: a lower bound on
  /// the squared distance to anything the box contains.
  double squaredDistance(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d below = (min - p).cwiseMax(0.0);
    const Eigen::Vector3d above = (p - max).cwiseMax(0.0);
    return (below + above).squaredNorm();
  }

  bool overlaps(const Aabb& o) const {
    return (min.array() <= o.max.array()).all() && (o.min.array() <= max.array()).all();
  }
};

}  // namespace wtc
