#pragma once
// A btMultiBodyJointMotor whose solver rows start from the impulse of the
// previous step (internal to the Bullet sim engine).
//
// Bullet's multibody solver warm-starts contact rows (the manifold keeps
// their impulses) but starts every other multibody constraint row at zero.
// A drive that carries a load (a wheel pushing the vehicle, a fold drive
// holding a section) then needs the whole of its impulse rebuilt by
// Gauss-Seidel every step, and the drives of one tree pull on each other
// through it: many iterations before the residual is reached. Starting
// each row at the previous step's impulse times the solver's warm-starting
// factor, clamped to this step's cap, and applying that impulse's joint
// velocity change before the iterations (what the solver does for a
// warm-started contact), converges to the same solution in fewer.
#include <algorithm>

#include <BulletDynamics/ConstraintSolver/btContactSolverInfo.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>

namespace wtc::bullet {

class WarmStartedMotor final : public btMultiBodyJointMotor {
 public:
  using btMultiBodyJointMotor::btMultiBodyJointMotor;

  void createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                            const btContactSolverInfo& info) override {
    const int first = rows.size();
    btMultiBodyJointMotor::createConstraintRows(rows, data, info);
    if ((info.m_solverMode & SOLVER_USE_WARMSTARTING) == 0) return;
    const int dofs = m_bodyA->getNumDofs() + 6;
    for (int i = first; i < rows.size(); ++i) {
      btMultiBodySolverConstraint& row = rows[i];
      const btScalar impulse = std::clamp(getAppliedImpulse(row.m_orgDofIndex) * info.m_warmstartingFactor,
                                          row.m_lowerLimit, row.m_upperLimit);
      row.m_appliedImpulse = impulse;
      // Into the solver's velocity increments (what the rows iterate on)
      // and the tree's pending ones, which the world adds to its velocities
      // after the solve (btMultiBodyDynamicsWorld::solveConstraints); its
      // velocities themselves stay as they were, since the rows created
      // after this one read them as the velocities before any impulse.
      const btScalar* response = &data.m_deltaVelocitiesUnitImpulse[row.m_jacAindex];
      for (int k = 0; k < dofs; ++k) data.m_deltaVelocities[row.m_deltaVelAindex + k] += response[k] * impulse;
      m_bodyA->applyDeltaVeeMultiDof2(response, impulse);
    }
  }
};

}  // namespace wtc::bullet
