#include "warm_started_motor.hpp"

#include <algorithm>
#include <limits>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodySolverConstraint.h>

namespace wtc::bullet {

WarmStartedMotor::WarmStartedMotor(btMultiBody* body, int link)
    : btMultiBodyJointMotor(body, link, 0.0, 0.0), link_(link) {
  m_bodyB = nullptr;  // before the Jacobians are sized (finalizeMultiDof): A's alone
}

void WarmStartedMotor::setTarget(double rate, double cap, bool active, double h) {
  setVelocityTarget(rate);
  setMaxAppliedImpulse(active ? std::min(cap * h, std::numeric_limits<double>::max()) : 0.0);
  const double feedforward = active ? std::clamp(last_effort_, -cap, cap) : 0.0;
  getMultiBodyA()->addJointTorque(link_, feedforward - feedforward_);
  feedforward_ = feedforward;
  active_ = active;
  h_ = h;
}

void WarmStartedMotor::stepped() {
  // active_: h_ was set; no row (a zero cap, or a body the solver skipped): none of its impulse.
  last_effort_ = active_ ? feedforward_ + (row_made_ ? getAppliedImpulse(0) / h_ : 0.0) : 0.0;
  feedforward_ = 0.0;
  row_made_ = false;
}

// The row btMultiBodyConstraint::fillMultiBodyConstraint makes for a joint
// motor, without body B: Jacobian J = e_dof, response M^-1 J^T, effective
// mass 1 / (J M^-1 J^T), and the impulse that brings the joint rate to the
// target, bounded by the cap less the feedforward.
void WarmStartedMotor::createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                                            const btContactSolverInfo&) {
  if (m_numDofsFinalized != m_jacSizeBoth) finalizeMultiDof();
  if (m_numDofsFinalized != m_jacSizeBoth || getMaxAppliedImpulse() == 0.0) return;  // off
  btMultiBody& mb = *m_bodyA;
  const int n = mb.getNumDofs() + 6;  // the base's 6, then the joints'
  const btMultibodyLink& link = mb.getLink(m_linkA);
  const int dof = 6 + link.m_dofOffset;

  btMultiBodySolverConstraint& row = rows.expand();
  row_made_ = true;
  row.m_orgConstraint = this;
  row.m_orgDofIndex = 0;
  row.m_multiBodyA = m_bodyA;
  row.m_linkA = m_linkA;  // no body B, no solver body: its ids stay -1

  row.m_deltaVelAindex = mb.getCompanionId();  // the multibody's velocity change, shared by its rows
  if (row.m_deltaVelAindex < 0) {
    row.m_deltaVelAindex = data.m_deltaVelocities.size();
    mb.setCompanionId(row.m_deltaVelAindex);
    data.m_deltaVelocities.resize(data.m_deltaVelocities.size() + n);
  }
  row.m_jacAindex = data.m_jacobians.size();
  data.m_jacobians.resize(row.m_jacAindex + n);
  std::copy_n(jacobianA(0), n, &data.m_jacobians[row.m_jacAindex]);
  data.m_deltaVelocitiesUnitImpulse.resize(row.m_jacAindex + n);
  btScalar* response = &data.m_deltaVelocitiesUnitImpulse[row.m_jacAindex];
  mb.calcAccelerationDeltasMultiDof(&data.m_jacobians[row.m_jacAindex], response, data.scratch_r, data.scratch_v);

  const double inverse_mass = response[dof];                                    // J M^-1 J^T
  row.m_jacDiagABInv = inverse_mass > SIMD_EPSILON ? 1.0 / inverse_mass : 0.0;  // Bullet's: off when singular
  row.m_rhs = (m_desiredVelocity - mb.getVelocityVector()[dof]) * row.m_jacDiagABInv;
  row.m_rhsPenetration = 0.0;
  row.m_cfm = 0.0;
  row.m_friction = 0.0;
  row.m_appliedImpulse = 0.0;
  row.m_appliedPushImpulse = 0.0;
  row.m_lowerLimit = -getMaxAppliedImpulse() - feedforward_ * h_;
  row.m_upperLimit = getMaxAppliedImpulse() - feedforward_ * h_;

  // The reaction the solver records on the link (its constraint force),
  // as Bullet's motor has it: a torque about a revolute axis, a force
  // along a prismatic one.
  const btVector3 zero(0, 0, 0);
  row.m_angularComponentA = row.m_angularComponentB = zero;
  row.m_contactNormal1 = row.m_contactNormal2 = zero;
  row.m_relpos1CrossNormal = row.m_relpos2CrossNormal = zero;
  const btQuaternion to_world = link.m_cachedWorldTransform.getRotation();
  if (link.m_jointType == btMultibodyLink::eRevolute) {
    row.m_relpos1CrossNormal = quatRotate(to_world, link.m_axes[0].m_topVec);
  } else if (link.m_jointType == btMultibodyLink::ePrismatic) {
    row.m_contactNormal1 = quatRotate(to_world, link.m_axes[0].m_bottomVec);
  }
}

}  // namespace wtc::bullet
