#pragma once
// The elastic hitch's force (vehicles spec, section 2), engine-free:
//
//   P = H diag(C) H^T Delta + H diag(mu) H^T dDelta/dt,   Delta = D1 - D2,
//
// with H = [x_h y_h z] the tug's horizontal axes: x_h its forward axis
// projected on the horizontal plane, z the world vertical, y_h = z x x_h.
// P acts on the towed body at D2 and -P on the tug at D1. The source writes
// the law in the horizontal axes only; vertically this project uses the
// same form with its own Cz, mu_z (a towbar's vertical compliance; a stiff
// Cz keeps the two hitch points together, as a pin would).
//
// dDelta/dt is the relative velocity of the two points (world frame), not
// the rate seen in the rotating axes: the damping force then always opposes
// the relative motion, so its power is -dDelta/dt^T H diag(mu) H^T dDelta/dt
// <= 0 and the hitch never feeds energy in.
#include <Eigen/Geometry>

#include "wtc/vehicle/body_kinematics.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::vehicle {

struct HitchForce {
  Eigen::Vector3d point_a{Eigen::Vector3d::Zero()};      ///< D1, world (m).
  Eigen::Vector3d point_b{Eigen::Vector3d::Zero()};      ///< D2, world (m).
  Eigen::Vector3d force_on_b{Eigen::Vector3d::Zero()};   ///< P, world (N); -P acts on the tug at D1.
  Eigen::Vector3d deflection{Eigen::Vector3d::Zero()};   ///< Delta in the tug's horizontal axes (m).
  Eigen::Vector3d force_local{Eigen::Vector3d::Zero()};  ///< P in the tug's horizontal axes (N).
};

/// The hitch force for the tug `a` and the towed body `b`; `damping_on` is
/// the hitch_damping effect (off: P = H diag(C) H^T Delta alone). The tug
/// must not point straight up (its x axis needs a horizontal part).
HitchForce hitchForce(const Hitch& hitch, const BodyKinematics& a, const BodyKinematics& b, bool damping_on);

}  // namespace wtc::vehicle
