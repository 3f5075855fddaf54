#include "wtc/adapter/solver_contact.hpp"

#include <cmath>

#include "wtc/base/tolerances.hpp"
#include "wtc/tyre/tyre_model.hpp"
#include "wtc/tyre/tyre_parameters.hpp"

namespace wtc {

SolverContact toSolverContact(const ContactForce& f, const TyreParameters& tyre, const TyreModel& model,
                              const Eigen::Vector3d& rest_load) {
  if (f.soft_soil) return soilRow(f);
  const double stiffness = tyre.radial_stiffness;
  const double damping = model.effects().has(Effect::kNormalDamping) ? tyre.radial_damping : 0.0;
  SolverContact c;
  c.ground_point = f.contact.ground_point;
  c.tread_point = f.contact.point;
  c.normal = -f.contact.e;
  c.depth = f.contact.deflection;
  c.stiffness = f.contact.load_share * stiffness;
  c.damping = f.contact.load_share * damping;
  c.load = f.normal_force;
  if (model.mode() == ContactMode::kImplicit) {  // the tread's rows, as the model made them
    const TreadRows& rows = f.tread_rows;
    c.friction = rows.damping[0] > 0.0 ? rows.limit[0] : 0.0;
    c.friction_direction = rows.direction;
    c.friction_velocity = rows.velocity;
    c.friction_damping = rows.damping;
    c.friction_across = rows.damping[1] > 0.0 ? rows.limit[1] : 0.0;
    return c;
  }
  c.friction = f.friction_limit;
  // Sticking: along the rest load's tangential part. Else along the
  // traction if there is one, else against the slip, else any.
  const Eigen::Vector3d load = rest_load - rest_load.dot(c.normal) * c.normal;
  const double traction = f.tangential_force.norm(), slip = f.slip_velocity.norm();
  if (f.friction_limit > f.mu && load.norm() > tolerance::kRestLoadRelative * rest_load.norm()) {
    c.friction_direction = load.normalized();
  } else if (traction > 0.0 && std::isfinite(traction)) {
    c.friction_direction = f.tangential_force / traction;
  } else if (slip > 0.0 && std::isfinite(slip)) {
    c.friction_direction = -f.slip_velocity / slip;
  } else {
    c.friction_direction = c.normal.unitOrthogonal();
  }
  return c;
}

SolverContact soilRow(const ContactForce& f) {
  SolverContact c;
  c.ground_point = f.contact.ground_point;
  c.tread_point = f.contact.point;
  c.normal = -f.contact.e;
  c.depth = f.soil_depth;
  c.stiffness = f.soil_stiffness;
  c.damping = f.soil_damping;
  c.friction_direction = c.normal.unitOrthogonal();  // no friction: the shear stays a force
  return c;
}

SoftConstraint softConstraint(double stiffness, double damping, double h) {
  const double denominator = h * stiffness + damping;
  return {h * stiffness / denominator, 1.0 / denominator};
}

}  // namespace wtc
