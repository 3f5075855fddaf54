#pragma once
// mj_step's stages for the Euler integrator, run one by one (internal to
// wtc::mujoco), so that WTC's contacts go into mjData's contact list
// between mj_collision and mj_makeConstraint. The order is MuJoCo 2.2.2's
// (engine_forward.c: mj_step, mj_forwardSkip, mj_fwdPosition): with nothing
// added, the step is mj_step's to the bit (tests/mujoco). The implicit
// integrator's mj_implicit is not public in 2.2.2, so only Euler is served.
#include <functional>

#include <mujoco/mujoco.h>

namespace wtc::mujoco {

/// The points of a step where a caller adds its part.
struct StageHooks {
  /// After mj_collision: the positions, the mass matrix and MuJoCo's own
  /// contacts of this step are known; velocities are not yet.
  std::function<void()> after_collision{};
  /// After mj_fwdVelocity (and the velocity sensors): what mj_step1 leaves,
  /// the constraint rows' reference accelerations (efc_aref) included;
  /// before actuation, xfrc_applied and qfrc_applied are read.
  std::function<void()> after_velocity{};
  /// After mj_fwdConstraint: efc_force of this step, before the integration.
  std::function<void()> after_solve{};
};

/// One Euler step of `m` with `hooks` (each may be empty).
void eulerStep(const mjModel& m, mjData& d, const StageHooks& hooks);

}  // namespace wtc::mujoco
