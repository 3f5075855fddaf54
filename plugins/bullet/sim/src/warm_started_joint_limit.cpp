#include "warm_started_joint_limit.hpp"

#include <algorithm>

#include <BulletDynamics/ConstraintSolver/btContactSolverInfo.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodySolverConstraint.h>

#include "joint_row.hpp"

namespace wtc::bullet {
namespace {
constexpr double kDirection[2] = {1.0, -1.0};  // of the push away from the lower and the upper stop
}  // namespace

WarmStartedJointLimit::WarmStartedJointLimit(btMultiBody* body, int link, double lower, double upper)
    : btMultiBodyConstraint(body, nullptr, link, -1, 2, true, MULTIBODY_CONSTRAINT_LIMIT), bound_{lower, upper} {}

void WarmStartedJointLimit::finalizeMultiDof() {
  allocateJacobiansMultiDof();  // the rows' impulses; their Jacobians are made with the rows
  m_numDofsFinalized = m_jacSizeBoth;
}

int WarmStartedJointLimit::getIslandIdA() const { return islandOf(*m_bodyA); }

// Bullet's: q - lower, upper - q; its row exists when <= 0.
double WarmStartedJointLimit::penetration(int bound) const {
  const double q = m_bodyA->getJointPos(m_linkA);
  return bound == 0 ? q - bound_[0] : bound_[1] - q;
}

void WarmStartedJointLimit::prepare(double h) {
  h_ = h;
  const double cap = getMaxAppliedImpulse() / h;
  double torque = 0.0;
  for (int b = 0; b < 2; ++b) {
    feedforward_[b] = penetration(b) <= 0.0 ? std::min(last_reaction_[b], cap) : 0.0;
    torque += kDirection[b] * feedforward_[b];
  }
  if (torque != 0.0) m_bodyA->addJointTorque(m_linkA, torque);
}

void WarmStartedJointLimit::stepped() {
  for (int b = 0; b < 2; ++b) {
    last_reaction_[b] = row_made_[b] ? feedforward_[b] + getAppliedImpulse(b) / h_ : 0.0;
    feedforward_[b] = 0.0;
    row_made_[b] = false;
  }
}

void WarmStartedJointLimit::createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                                                 const btContactSolverInfo& info) {
  if (m_numDofsFinalized != m_jacSizeBoth) finalizeMultiDof();
  for (int b = 0; b < 2; ++b) {
    const double overlap = penetration(b);
    if (overlap > 0.0) continue;
    double rate = 0.0;
    btMultiBodySolverConstraint& row = appendJointRow(rows, data, *m_bodyA, m_linkA, kDirection[b], 0.0,
                                                      getMaxAppliedImpulse(), feedforward_[b] * h_, *this, b, rate);
    row_made_[b] = true;
    // Bullet's right-hand side: the rate along the row to zero, and the
    // overlap closed by erp of it a step.
    const bool split = info.m_splitImpulse && overlap <= info.m_splitImpulsePenetrationThreshold;
    const double erp = split ? info.m_erp2 : info.m_erp;
    const double position_impulse = -overlap * erp / info.m_timeStep * row.m_jacDiagABInv;
    const double velocity_impulse = -rate * row.m_jacDiagABInv;
    row.m_rhs = split ? velocity_impulse : position_impulse + velocity_impulse;
    row.m_rhsPenetration = split ? position_impulse : 0.0;
  }
}

}  // namespace wtc::bullet
