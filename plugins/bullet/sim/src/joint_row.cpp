#include "joint_row.hpp"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <BulletDynamics/Featherstone/btMultiBodySolverConstraint.h>

#include "wheel_drive_responses.hpp"

namespace wtc::bullet {

btMultiBodySolverConstraint& appendJointRow(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                                            btMultiBody& body, int link, double sign, double lower, double upper,
                                            double applied, btMultiBodyConstraint& origin, int origin_row, double& rate,
                                            WheelDriveResponses* shared) {
  const int n = body.getNumDofs() + 6;  // the base's 6, then the joints'
  const btMultibodyLink& l = body.getLink(link);
  const int dof = 6 + l.m_dofOffset;

  btMultiBodySolverConstraint& row = rows.expand();
  row.m_orgConstraint = &origin;
  row.m_orgDofIndex = origin_row;
  row.m_multiBodyA = &body;
  row.m_linkA = link;  // no body B, no solver body: their ids stay -1

  row.m_deltaVelAindex = body.getCompanionId();  // the multibody's velocity change, shared by its rows
  if (row.m_deltaVelAindex < 0) {
    row.m_deltaVelAindex = data.m_deltaVelocities.size();
    body.setCompanionId(row.m_deltaVelAindex);
    data.m_deltaVelocities.resize(data.m_deltaVelocities.size() + n);
  }
  row.m_jacAindex = data.m_jacobians.size();
  data.m_jacobians.resize(row.m_jacAindex + n);  // zeros
  data.m_jacobians[row.m_jacAindex + dof] = sign;
  data.m_deltaVelocitiesUnitImpulse.resize(row.m_jacAindex + n);
  btScalar* response = &data.m_deltaVelocitiesUnitImpulse[row.m_jacAindex];
  if (shared != nullptr) {
    shared->fill(data, body, link, sign, response);
  } else {
    body.calcAccelerationDeltasMultiDof(&data.m_jacobians[row.m_jacAindex], response, data.scratch_r, data.scratch_v);
  }

  const double inverse_mass = sign * response[dof];                             // J M^-1 J^T
  row.m_jacDiagABInv = inverse_mass > SIMD_EPSILON ? 1.0 / inverse_mass : 0.0;  // Bullet's: off when singular
  rate = sign * body.getVelocityVector()[dof];
  row.m_rhs = 0.0;
  row.m_rhsPenetration = 0.0;
  row.m_cfm = 0.0;
  row.m_friction = 0.0;
  row.m_appliedImpulse = 0.0;
  row.m_appliedPushImpulse = 0.0;
  row.m_lowerLimit = lower - applied;
  row.m_upperLimit = upper - applied;

  // The reaction the solver records on the link (its constraint force), as
  // Bullet's joint constraints have it: a torque about a revolute axis, a
  // force along a prismatic one.
  const btVector3 zero(0, 0, 0);
  row.m_angularComponentA = row.m_angularComponentB = zero;
  row.m_contactNormal1 = row.m_contactNormal2 = zero;
  row.m_relpos1CrossNormal = row.m_relpos2CrossNormal = zero;
  const btQuaternion to_world = l.m_cachedWorldTransform.getRotation();
  if (l.m_jointType == btMultibodyLink::eRevolute) {
    row.m_relpos1CrossNormal = sign * quatRotate(to_world, l.m_axes[0].m_topVec);
  } else if (l.m_jointType == btMultibodyLink::ePrismatic) {
    row.m_contactNormal1 = sign * quatRotate(to_world, l.m_axes[0].m_bottomVec);
  }
  return row;
}

int islandOf(const btMultiBody& body) {
  if (const btMultiBodyLinkCollider* base = body.getBaseCollider()) return base->getIslandTag();
  for (int i = 0; i < body.getNumLinks(); ++i) {
    if (const btMultiBodyLinkCollider* c = body.getLink(i).m_collider) return c->getIslandTag();
  }
  return -1;
}

}  // namespace wtc::bullet
