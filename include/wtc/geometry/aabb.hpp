#pragma once
#include <iterator>

#include <Eigen/Core>

namespace wtc {

/// Axis-aligned bounding box in the world frame (m).
struct Aabb {
  Eigen::Vector3d min{Eigen::Vector3d::Constant(0.0)};
  Eigen::Vector3d max{Eigen::Vector3d::Constant(0.0)};

  /// The box of a non-empty point set.
  template <typename Points>
  static Aabb of(const Points& points) {
    Aabb box{*std::begin(points), *std::begin(points)};
    for (const Eigen::Vector3d& p : points) box.include(p);
    return box;
  }

  void include(const Eigen::Vector3d& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  void include(const Aabb& box) {
    min = min.cwiseMin(box.min);
    max = max.cwiseMax(box.max);
  }

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
