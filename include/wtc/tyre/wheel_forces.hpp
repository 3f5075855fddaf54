#pragma once
// The inputs and results of one wheel's force evaluation (wheel-terrain
// model, sections 3-4). Sign conventions: every force is the ground's
// action ON THE WHEEL; moments are about the wheel centre O; vectors are in
// the world frame.
#include <array>
#include <span>

#include <Eigen/Core>

#include "wtc/contact/wheel_contact.hpp"
#include "wtc/tyre/explicit_stability.hpp"

namespace wtc {

/// The wheel's motion, as the engine reports it at the start of the step.
struct WheelMotion {
  Eigen::Vector3d velocity{Eigen::Vector3d::Zero()};          ///< V_O (m/s).
  Eigen::Vector3d angular_velocity{Eigen::Vector3d::Zero()};  ///< omega of the wheel: spin + carrier (rad/s).
};

/// The tread's force over a step as two rows of an engine's solver, in the
/// contact's tangent plane: row i pushes the wheel along its direction by
///   R_i = damping_i (velocity_i - V_i+),  |R_i| <= limit_i R_z,
/// V_i+ the tread point's velocity along the row at the end of the step.
/// Row 0 runs along `direction` (the traction's), row 1 along
/// direction x e.
struct TreadRows {
  Eigen::Vector3d direction{Eigen::Vector3d::UnitX()};  ///< Unit, normal to e.
  std::array<double, 2> velocity{};                     ///< Target velocity (m/s).
  std::array<double, 2> damping{};                      ///< K_i (N s/m); 0: no row.
  std::array<double, 2> limit{};                        ///< Most |R_i| / R_z (dimensionless).
};

/// One contact's breakdown, for logging and controllers.
struct ContactForce {
  WheelContact contact;                                    ///< P, e, Z, piece, material.
  double deflection_rate = 0.0;                            ///< v_z = V_P . e (m/s); > 0 into the ground.
  double normal_force = 0.0;                               ///< R_z = max(c Z + b v_z, 0) (N).
  Eigen::Vector3d slip_velocity{Eigen::Vector3d::Zero()};  ///< V_s = V_P - v_z e (m/s).
  double slip_ratio = 0.0;                                 ///< s = |V_s| / max(V_t, eps) (dimensionless).
  double mu = 0.0;                                         ///< |R_xy| / R_z applied (dimensionless).
  /// The most |R_xy| / R_z the tread holds now: the peak of mu(s) while it
  /// sticks, ramped out as V_t reaches eps, and mu beyond (dimensionless).
  /// Constraint mode gives it to the engine as its friction coefficient.
  double friction_limit = 0.0;
  Eigen::Vector3d tangential_force{Eigen::Vector3d::Zero()};  ///< R_xy, in the tangent plane (N).
  /// The tread over the coming step as two engine rows, for an engine that
  /// solves it (implicit mode; docs/tyre-model.md, "Implicit mode"). Zero
  /// without traction.
  TreadRows tread_rows;
  Eigen::Vector3d force{Eigen::Vector3d::Zero()};           ///< R = -R_z e + R_xy, applied at P (N).
  Eigen::Vector3d rolling_moment{Eigen::Vector3d::Zero()};  ///< M_r, along the axle (N m).
  /// The soil's stresses (the soft_soil effect, docs/soft-soil.md), not the
  /// tyre's spring: normal_force is W, slip_ratio the soil's slip i,
  /// rolling_moment the shear's moment less OP x R's, and no c Z^2 / 2 is stored.
  /// In the engine-solved modes its normal becomes a row (the soil's
  /// spring below) and its shear stays a force (wtc/adapter/solver_contact.hpp).
  bool soft_soil = false;
  /// On soft soil, the soil as a spring about this step's sinkage z
  /// (soil_contact.cpp): W's tangent stiffness e W / z (Bekker's W ~ z^e,
  /// e = n + 1/2 under a wheel, n + 1 under a ball), at most the soil's
  /// reloading line over the patch, k_u A; its damping R A; and the depth
  /// at which that spring carries the undamped W (z / e uncapped); each
  /// times the load share.
  double soil_stiffness = 0.0;  ///< N/m.
  double soil_damping = 0.0;    ///< N s/m.
  double soil_depth = 0.0;      ///< m.
  /// On soft soil, z: the rim's lowest point below the surface it meets,
  /// the fresh one or, where the ground remembers, the rut (m, [0, r]).
  double soil_sinkage = 0.0;
};

/// The wheel's totals. force and torque are the wrench on the wheel body
/// about O: torque = sum OP x R + sum M_r. It splits into
///   axial_moment   = a (a . sum OP x R) + sum M_r   what the drive feels,
///   bearing_moment = sum OP x R - a (a . sum OP x R) what the chassis feels,
/// so axial_moment + bearing_moment = torque. An engine that applies each R
/// at its P on a wheel body on a revolute joint, plus M_r as a torque,
/// reproduces this split through its joint.
struct WheelForces {
  Eigen::Vector3d force{Eigen::Vector3d::Zero()};           ///< N.
  Eigen::Vector3d torque{Eigen::Vector3d::Zero()};          ///< About O (N m).
  Eigen::Vector3d axial_moment{Eigen::Vector3d::Zero()};    ///< N m, along a.
  Eigen::Vector3d bearing_moment{Eigen::Vector3d::Zero()};  ///< N m, normal to a.
  Eigen::Vector3d rolling_moment{Eigen::Vector3d::Zero()};  ///< sum M_r (N m): what constraint mode applies explicitly.
  std::span<const ContactForce> contacts;                   ///< Valid until the wheel's next step.
  SpringStability normal_stability;  ///< The tyre spring at this step (see explicit_stability.hpp).
};

}  // namespace wtc
