// mj_step's stages for Euler, one by one (euler_stages.hpp).
#include "euler_stages.hpp"

namespace wtc::mujoco {

void eulerStep(const mjModel& m, mjData& d, const StageHooks& hooks) {
  const bool energy = (m.opt.enableflags & mjENBL_ENERGY) != 0;
  mj_checkPos(&m, &d);
  mj_checkVel(&m, &d);
  // mj_forward: mj_fwdPosition with WTC's contacts after mj_collision.
  mj_kinematics(&m, &d);
  mj_comPos(&m, &d);
  mj_camlight(&m, &d);
  mj_tendon(&m, &d);
  mj_crb(&m, &d);
  mj_factorM(&m, &d);
  mj_collision(&m, &d);
  if (hooks.after_collision) hooks.after_collision();
  mj_makeConstraint(&m, &d);
  mj_transmission(&m, &d);
  mj_projectConstraint(&m, &d);
  mj_sensorPos(&m, &d);
  if (energy) mj_energyPos(&m, &d);
  mj_fwdVelocity(&m, &d);
  mj_sensorVel(&m, &d);
  if (energy) mj_energyVel(&m, &d);
  if (hooks.after_velocity) hooks.after_velocity();
  if (mjcb_control != nullptr) mjcb_control(&m, &d);
  mj_fwdActuation(&m, &d);
  mj_fwdAcceleration(&m, &d);
  mj_fwdConstraint(&m, &d);
  mj_sensorAcc(&m, &d);
  if (hooks.after_solve) hooks.after_solve();
  mj_checkAcc(&m, &d);
  if ((m.opt.enableflags & mjENBL_FWDINV) != 0) mj_compareFwdInv(&m, &d);
  mj_Euler(&m, &d);
}

}  // namespace wtc::mujoco
