#pragma once
// One WTC contact as an mjContact (internal to wtc::mujoco; the mapping is
// in docs/mujoco-plugin.md, "The spring").
//
// The engine-solved modes hand the tyre's spring-damper (c, b) to MuJoCo as
// the implicit Euler step ODE's ERP and CFM give it (solver_contact.hpp).
// For a constraint row MuJoCo 2.2.2 solves f = (a_ref - a_0) / (A + R), with
// a_ref = -B v - K I r and R = (1 - I) / I D (engine_core_constraint.c:
// mj_makeImpedance, mj_referenceConstraint), D its estimate of A from
// body_invweight0. The implicit step of R_z = c Z - b v over h is
//      f = (c Z / (h (h c + b)) - v / h - a_0) / (1 / (h (h c + b)) + A),
// so with r = -Z the row must have
//      R = R* = 1 / (h (h c + b)),   B = 1 / h,   K I = c R*.
// A negative solref (-k, -b') with a constant impedance solimp (d, d, ...)
// gives K = k / d^2, B = b' / d, I = d: so d = D / (D + R*) (the normal
// row's own R), b' = d / h, k = d c R*. On a pyramidal cone the normal is
// carried by 2 (dim - 1) edges whose common R is 2 mu^2 R_0 / impratio
// (R_0 the normal row's before MuJoCo rescales it): d is chosen so that
// R_0 = 2 (dim - 1) R* impratio / (2 mu^2), with D = tran (1 + mu^2).
// MuJoCo bounds d to [mjMINIMP, mjMAXIMP]; where the bound bites, R is the
// bound's and k = d c R keeps the static deflection W / c exact, while the
// step's damping becomes b = 1 / (h R) - h c (`damping` below).
#include <mujoco/mujoco.h>

#include "wtc/adapter/solver_contact.hpp"

namespace wtc::mujoco {

/// What the mapping needs of the model for one contact.
struct ContactSetting {
  double step_seconds = 0.0;    ///< h: mjModel::opt.timestep.
  double inverse_weight = 0.0;  ///< body_invweight0 (translation) of both bodies: MuJoCo's D (1/kg).
  bool pyramidal = true;        ///< mjModel::opt.cone == mjCONE_PYRAMIDAL.
  double impratio = 1.0;        ///< mjModel::opt.impratio.
  int ground_geom = -1;         ///< geom1: a geom of the world body, or of one welded to it.
  int wheel_geom = -1;          ///< geom2: a geom of the wheel's body.
};

/// The contact and what MuJoCo will make of it.
struct SoftContact {
  mjContact contact{};
  double regularizer = 0.0;      ///< The normal's R as solved (1/kg): R* unless d is bounded.
  double damping = 0.0;          ///< The normal damping the step realizes (N s/m): b unless d is bounded.
  double slip_per_newton = 0.0;  ///< Friction's creep speed per newton of friction, h R_t (m/(N s)); 0 for dim 1.
};

/// False (and no contact) for a row without a spring (h c + b <= 0).
bool toSoftContact(const SolverContact& c, const ContactSetting& setting, SoftContact& out);

}  // namespace wtc::mujoco
