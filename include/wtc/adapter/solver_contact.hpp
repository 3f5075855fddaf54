#pragma once
// How the engine adapters hand WTC's contacts to an engine (shared by
// wtc::bullet and wtc::ode, so that the physics of both modes lives here).
//
// Force mode: the tyre model's forces (R at P, M_r about the axle) are
// applied to the wheel body at every internal step. Exact laws; the normal
// spring is explicit, stable only for h sqrt(c/m) < 2 (sqrt(1+zeta^2) - zeta).
//
// Constraint mode: each contact becomes an engine contact whose softness is
// the tyre's spring-damper, solved implicitly by the engine:
//   ERP = h c / (h c + b),  CFM = 1 / (h c + b)   (per unit impulse / h),
// which is the implicit Euler step of R_z = c Z + b v_z: stable at any step.
// Friction is the engine's Coulomb friction with the coefficient the slip
// law gives this step (mu = |R_xy| / R_z of the tread state) and its first
// direction along the traction: within a step, friction is Coulomb-like (it
// stops the slip if it can), so the slip law acts from step to step. At
// rest the tread sticks up to the peak of mu(s) (ContactForce::
// friction_limit), along the load a vehicle at rest feels (gravity's part
// in the tangent plane): an empty tread state (a wheel just put down) would
// otherwise let the first step slide free, g sin(theta) h^2 on a slope.
//
// Implicit mode: the normal row as in constraint mode, and the tread as two
// compliant friction rows the tyre model makes (wtc::TreadRows,
// tyre_kernels.cpp): row i's force is K_i (v_i - V_i+), the implicit step
// of the tread (its spring, or the slip law linearized about the slip seen
// now), bounded by mu_i times the normal force: row 0 along the traction up
// to the law's peak, row 1 across it up to what the cone leaves beside the
// traction, sqrt(peak^2 - mu^2). Engines take a row as a target velocity and
// a compliance 1/K_i: ODE's dContactMotion and dContactSlip, a CFM in
// Bullet's multibody rows (wheel_friction_constraint.hpp).
//
// Rolling resistance stays an explicit moment in every mode. A contact on
// soft soil (the soft_soil effect) hands the engine its normal as a
// frictionless row whose spring is the soil's tangent stiffness about the
// sinkage (soilRow); its shear, a law of the soil's slip over the arc and
// not a friction cone, stays a force (MountedWheel; docs/soft-soil.md).
#include <array>

#include <Eigen/Core>

#include "wtc/tyre/contact_mode.hpp"
#include "wtc/tyre/wheel_forces.hpp"

namespace wtc {
class TyreModel;
struct TyreParameters;
}  // namespace wtc

namespace wtc {

/// One contact as an engine constraint (constraint mode).
struct SolverContact {
  Eigen::Vector3d ground_point{Eigen::Vector3d::Zero()};         ///< On the piece's surface (world, m).
  Eigen::Vector3d tread_point{Eigen::Vector3d::Zero()};          ///< P on the undeformed tread (world, m).
  Eigen::Vector3d normal{Eigen::Vector3d::UnitZ()};              ///< Unit, from the ground toward the wheel centre: -e.
  double depth = 0.0;                                            ///< Z (m), > 0 into the ground.
  double stiffness = 0.0;                                        ///< share x c (N/m).
  double damping = 0.0;                                          ///< share x b, 0 without normal damping (N s/m).
  double friction = 0.0;                                         ///< mu for the engine's friction (dimensionless).
  double load = 0.0;  ///< R_z the tyre model gives the contact this step (N): what implicit mode's rows scale mu by.
  Eigen::Vector3d friction_direction{Eigen::Vector3d::UnitX()};  ///< Unit, normal to `normal`: along the traction.
  /// Implicit mode's tread rows (wtc::TreadRows; zero in constraint mode:
  /// rigid friction along friction_direction only). Row 0 runs along
  /// friction_direction, row 1 along normal x friction_direction; row i
  /// pushes by K_i (friction_velocity_i - V_i), V_i the tread point's
  /// velocity along it, within mu_i times the normal force (friction for
  /// row 0, friction_across for row 1).
  std::array<double, 2> friction_velocity{};  ///< m/s.
  std::array<double, 2> friction_damping{};   ///< K_i (N s/m); 0: rigid friction.
  double friction_across = 0.0;               ///< mu of row 1 (dimensionless); 0: no row 1.
};

/// The engine contact of one contact of `model`'s result for a wheel with
/// `tyre`: stiffness c, damping b if the model has normal damping (else 0),
/// both times the contact's load share; friction ContactForce::
/// friction_limit. While the tread sticks (the limit is above mu) its one
/// friction direction is along the part of `rest_load` (the acceleration
/// that loads a vehicle at rest: the world's gravity, m/s^2) in the contact's
/// tangent plane, where a parked wheel needs it; else along the traction,
/// else against the slip, else any.
SolverContact toSolverContact(const ContactForce& force, const TyreParameters& tyre, const TyreModel& model,
                              const Eigen::Vector3d& rest_load);

/// A contact on soft soil (ContactForce::soft_soil, with a sinkage) as a
/// frictionless row: the soil's spring about this step's sinkage, its
/// stiffness (n + 1/2) W / z and damping R b L, pressing W at depth
/// z / (n + 1/2). The shear stays a force (MountedWheel). toSolverContact
/// gives it for such a contact.
SolverContact soilRow(const ContactForce& force);

/// ERP and CFM of an implicit spring-damper (ODE's convention: CFM in
/// m/(N s) per unit of the constraint force; Bullet derives the same pair
/// from a contact's stiffness and damping).
struct SoftConstraint {
  double erp = 0.0;  ///< h c / (h c + b) (dimensionless).
  double cfm = 0.0;  ///< 1 / (h c + b) (m / (N s)).
};
SoftConstraint softConstraint(double stiffness, double damping, double step_seconds);

}  // namespace wtc
