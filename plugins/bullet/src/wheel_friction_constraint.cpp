#include "wheel_friction_constraint.hpp"

#include <algorithm>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include "conversions.hpp"

namespace wtc::bullet {

WheelFrictionConstraint::WheelFrictionConstraint(btMultiBody* multibody, int link, int rows)
    : btMultiBodyConstraint(multibody, nullptr, link, -1, rows, false, MAX_MULTIBODY_CONSTRAINT_TYPE) {
  active_.reserve(static_cast<std::size_t>(rows));  // no allocation in the step loop
  finalizeMultiDof();
}

void WheelFrictionConstraint::finalizeMultiDof() {
  allocateJacobiansMultiDof();
  m_numDofsFinalized = m_jacSizeBoth;
}

int WheelFrictionConstraint::getIslandIdA() const {
  const btMultiBodyLinkCollider* collider = m_bodyA->getLink(m_linkA).m_collider;
  return collider != nullptr ? collider->getIslandTag() : -1;
}

void WheelFrictionConstraint::set(std::span<const SolverContact> contacts, std::span<const ContactForce> model,
                                  double h) {
  active_.clear();
  const std::size_t n = std::min({contacts.size(), model.size(), static_cast<std::size_t>(getNumRows())});
  for (std::size_t i = 0; i < n; ++i) {
    const SolverContact& c = contacts[i];
    active_.push_back(
        {toBt(c.tread_point), toBt(c.friction_direction), std::max(c.friction * model[i].normal_force * h, 0.0)});
    internalSetAppliedImpulse(static_cast<int>(i), 0.0);
  }
}

btVector3 WheelFrictionConstraint::appliedForce(std::size_t i, double h) {
  if (i >= active_.size()) return {0, 0, 0};
  return active_[i].direction * (getAppliedImpulse(static_cast<int>(i)) / h);
}

void WheelFrictionConstraint::createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                                                   const btContactSolverInfo& info) {
  const btVector3 none(0, 0, 0);
  for (std::size_t i = 0; i < active_.size(); ++i) {
    const Row& r = active_[i];
    btMultiBodySolverConstraint& row = rows.expandNonInitializing();
    row.m_orgConstraint = this;
    row.m_orgDofIndex = static_cast<int>(i);
    row.m_relpos1CrossNormal.setZero();
    row.m_contactNormal1.setZero();
    row.m_relpos2CrossNormal.setZero();
    row.m_contactNormal2.setZero();
    row.m_angularComponentA.setZero();
    row.m_angularComponentB.setZero();
    row.m_solverBodyIdA = data.m_fixedBodyId;
    row.m_solverBodyIdB = data.m_fixedBodyId;
    // The link's velocity at P along the direction, to zero (a friction
    // row: no positional error), within the Coulomb bound.
    fillMultiBodyConstraint(row, data, nullptr, nullptr, none, r.direction, r.point, r.point, 0.0, info, -r.limit,
                            r.limit, false, 1.0, true);
  }
}

}  // namespace wtc::bullet
