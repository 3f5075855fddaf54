#include "contact_joint.hpp"

namespace wtc::ode {
namespace {

// Implicit mode's tread rows (solver_contact.hpp): ODE solves a friction
// row as v+ = motion - slip f (dContactMotion, force-dependent slip), f the
// force on the wheel (body 1) along the row, within mu times the solved
// normal force (dContactApprox1): with motion = v_i and slip = 1 / K_i
// that is f = K_i (v_i - v+), the row's law. Row 1 is ODE's own
// fdir2 = normal x fdir1.
void treadRows(const SolverContact& c, dContact& j) {
  j.surface.mode |= dContactFDir1 | dContactMotion1 | dContactSlip1 | dContactMu2;
  j.surface.motion1 = c.friction_velocity[0];
  j.surface.slip1 = 1.0 / c.friction_damping[0];
  j.surface.mu2 = c.friction_across;  // 0: ODE adds no second row
  if (c.friction_across > 0.0) {
    j.surface.mode |= dContactMotion2 | dContactSlip2;
    j.surface.motion2 = c.friction_velocity[1];
    j.surface.slip2 = 1.0 / c.friction_damping[1];
  }
  for (int i = 0; i < 3; ++i) j.fdir1[i] = c.friction_direction[i];
}

}  // namespace

dContact toOdeContact(const SolverContact& c, double h, double surface_layer, dGeomID wheel, dGeomID ground) {
  dContact j{};
  // The tyre's c and b as an implicit spring-damper: ODE's soft ERP/CFM.
  const SoftConstraint soft = softConstraint(c.stiffness, c.damping, h);
  // dContactApprox1: mu is a coefficient (|f| <= mu f_n), not a force bound.
  j.surface.mode = dContactSoftERP | dContactSoftCFM | dContactApprox1;
  j.surface.soft_erp = soft.erp;
  j.surface.soft_cfm = soft.cfm;
  j.surface.mu = c.friction;  // 0 (no slip yet): ODE then adds no friction rows
  if (c.friction > 0.0 && c.friction_damping[0] > 0.0) {
    treadRows(c, j);
  } else if (c.friction > 0.0) {
    // One friction direction, along the traction: ODE caps each direction
    // at mu f_n separately, so a second one (normal x fdir1) would make a
    // pyramid whose diagonal carries up to sqrt(2) mu f_n and holds sideways
    // what the slip law lets slide (measured, a wheel spun by 100 N m under
    // a side force of 0.3 m g: 1.007 mu_max R_z and 1.56 m/s of side slip
    // after 1 s, against the law's 2.27 m/s; SpinningWheelTractionStaysIn-
    // TheFrictionCone). mu2 = 0 removes ODE's second row; grip across comes
    // from the tread state turning toward any new slip, from step to step.
    j.surface.mode |= dContactFDir1 | dContactMu2;
    j.surface.mu2 = 0.0;
    for (int i = 0; i < 3; ++i) j.fdir1[i] = c.friction_direction[i];
  }
  // At P, on the undeformed tread, as force mode applies R: the same lever
  // arm about the wheel centre in both modes.
  for (int i = 0; i < 3; ++i) {
    j.geom.pos[i] = c.tread_point[i];
    j.geom.normal[i] = c.normal[i];
  }
  j.geom.depth = c.depth + surface_layer;
  j.geom.g1 = wheel;
  j.geom.g2 = ground;
  return j;
}

double correctingVelocity(const SolverContact& c, double h) {
  return softConstraint(c.stiffness, c.damping, h).erp * c.depth / h;
}

}  // namespace wtc::ode
