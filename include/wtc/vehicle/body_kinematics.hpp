#pragma once
// A body's motion as an engine reports it (sim::Engine::body) and as the
// sensors, the controllers and the hitch law read it.
#include <Eigen/Geometry>

namespace wtc::vehicle {

/// A body's pose and the velocity of its centre of mass, world frame.
struct BodyKinematics {
  Eigen::Isometry3d pose{Eigen::Isometry3d::Identity()};      ///< Centre-of-mass frame (m).
  Eigen::Vector3d linear_velocity{Eigen::Vector3d::Zero()};   ///< Of the centre of mass (m/s).
  Eigen::Vector3d angular_velocity{Eigen::Vector3d::Zero()};  ///< (rad/s).
};

}  // namespace wtc::vehicle
