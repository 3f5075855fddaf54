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

/// One Euler step of `m`: `afterCollision` runs after mj_collision (the
/// positions, the mass matrix and MuJoCo's own contacts of this step are
/// known; velocities are not yet), `afterSolve` after mj_fwdConstraint
/// (efc_force of this step) and before the integration.
void eulerStep(const mjModel& m, mjData& d, const std::function<void()>& afterCollision,
               const std::function<void()>& afterSolve);

}  // namespace wtc::mujoco
