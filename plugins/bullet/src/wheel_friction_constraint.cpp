#include "wheel_friction_constraint.hpp"

#include <algorithm>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include "conversions.hpp"
#include "soft_row.hpp"

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

void WheelFrictionConstraint::add(const Row& row) {
  if (active_.size() >= static_cast<std::size_t>(getNumRows())) return;
  internalSetAppliedImpulse(static_cast<int>(active_.size()), 0.0);
  active_.push_back(row);
}

void WheelFrictionConstraint::set(std::span<const SolverContact> contacts, double h) {
  active_.clear();
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const SolverContact& c = contacts[i];
    const double load = c.load;  // R_z (N)
    const auto compliance = [&](int row) {
      return c.friction_damping[row] > 0.0 ? 1.0 / (h * c.friction_damping[row]) : 0.0;
    };
    const btVector3 point = toBt(c.tread_point);
    add({point, toBt(c.friction_direction), std::max(c.friction * load * h, 0.0), c.friction_velocity[0], compliance(0),
         c.friction, i});
    if (c.friction_across > 0.0) {
      add({point, toBt(c.normal.cross(c.friction_direction)), std::max(c.friction_across * load * h, 0.0),
           c.friction_velocity[1], compliance(1), c.friction_across, i});
    }
  }
}

void WheelFrictionConstraint::setContactPoints(btPersistentManifold* const* manifold, const std::vector<int>* points) {
  manifold_ = manifold;
  points_ = points;
}

const btManifoldPoint* WheelFrictionConstraint::contactPoint(int row) const {
  if (manifold_ == nullptr || *manifold_ == nullptr || points_ == nullptr) return nullptr;
  const std::size_t contact = active_[static_cast<std::size_t>(row)].contact;
  if (contact >= points_->size()) return nullptr;
  const int index = (*points_)[contact];
  if (index < 0 || index >= (*manifold_)->getNumContacts()) return nullptr;
  return &(*manifold_)->getContactPoint(index);
}

btVector3 WheelFrictionConstraint::appliedForce(std::size_t i, double h) {
  btVector3 force(0, 0, 0);
  for (std::size_t k = 0; k < active_.size(); ++k) {
    if (active_[k].contact == i) force += active_[k].direction * (getAppliedImpulse(static_cast<int>(k)) / h);
  }
  return force;
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
    const double velocity = fillMultiBodyConstraint(row, data, nullptr, nullptr, none, r.direction, r.point, r.point,
                                                    0.0, info, -r.limit, r.limit, false, 1.0, true, r.velocity);
    if (r.compliance > 0.0) {  // the tread's soft row (soft_row.hpp)
      const SoftRow soft = softRow(row.m_jacDiagABInv, r.velocity - velocity, r.compliance);
      row.m_jacDiagABInv = soft.jac_diag_inv;
      row.m_rhs = soft.rhs;
      row.m_cfm = soft.cfm;
    }
  }
}

}  // namespace wtc::bullet
