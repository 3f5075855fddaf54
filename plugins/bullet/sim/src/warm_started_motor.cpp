#include "warm_started_motor.hpp"

#include <algorithm>
#include <limits>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodySolverConstraint.h>

#include "joint_row.hpp"

namespace wtc::bullet {

WarmStartedMotor::WarmStartedMotor(btMultiBody* body, int link) : btMultiBodyJointMotor(body, link, 0.0, 0.0) {
  m_bodyB = nullptr;  // before the Jacobians are sized (finalizeMultiDof): A's alone
}

int WarmStartedMotor::getIslandIdA() const { return islandOf(*m_bodyA); }

void WarmStartedMotor::setTarget(double rate, double cap, bool active, double h) {
  setVelocityTarget(rate);
  setMaxAppliedImpulse(active ? std::min(cap * h, std::numeric_limits<double>::max()) : 0.0);
  const double feedforward = active ? std::clamp(last_effort_, -cap, cap) : 0.0;
  m_bodyA->addJointTorque(m_linkA, feedforward - feedforward_);
  feedforward_ = feedforward;
  h_ = h;
}

void WarmStartedMotor::stepped() {
  // Off: no feedforward and no row (a zero cap). A row was made only after
  // a target set h_; without one (or for a body the solver skipped), none
  // of an older step's impulse.
  last_effort_ = feedforward_ + (row_made_ ? getAppliedImpulse(0) / h_ : 0.0);
  feedforward_ = 0.0;
  row_made_ = false;
}

// The joint-motor row (btMultiBodyJointMotor's, without body B): the
// impulse that brings the joint rate to the target, bounded by the cap less
// the feedforward.
void WarmStartedMotor::createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                                            const btContactSolverInfo&) {
  if (m_numDofsFinalized != m_jacSizeBoth) finalizeMultiDof();
  if (m_numDofsFinalized != m_jacSizeBoth || getMaxAppliedImpulse() == 0.0) return;  // off
  double rate = 0.0;
  btMultiBodySolverConstraint& row = appendJointRow(rows, data, *m_bodyA, m_linkA, 1.0, -getMaxAppliedImpulse(),
                                                    getMaxAppliedImpulse(), feedforward_ * h_, *this, 0, rate, shared_);
  row_made_ = true;
  row.m_rhs = (m_desiredVelocity - rate) * row.m_jacDiagABInv;
}

}  // namespace wtc::bullet
