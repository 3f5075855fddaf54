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
// Rolling resistance stays an explicit moment in both modes.
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
  Eigen::Vector3d friction_direction{Eigen::Vector3d::UnitX()};  ///< Unit, normal to `normal`: along the traction.
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

/// ERP and CFM of an implicit spring-damper (ODE's convention: CFM in
/// m/(N s) per unit of the constraint force; Bullet derives the same pair
/// from a contact's stiffness and damping).
struct SoftConstraint {
  double erp = 0.0;  ///< h c / (h c + b) (dimensionless).
  double cfm = 0.0;  ///< 1 / (h c + b) (m / (N s)).
};
SoftConstraint softConstraint(double stiffness, double damping, double step_seconds);

}  // namespace wtc
