#include "rigid_tread_rows.hpp"

#include <algorithm>

#include "soft_row.hpp"

namespace wtc::bullet {

void RigidTreadRows::set(const Point& p) {
  const auto found = std::find_if(points_.begin(), points_.end(), [&](const Point& q) { return q.point == p.point; });
  if (found != points_.end()) {
    *found = p;
  } else {
    points_.push_back(p);
  }
}

// The velocity along a friction row that the torques acting this step
// (btSolverBody::m_externalTorqueImpulse) add. Bullet 3.24's
// setupFrictionConstraint measures a friction row's velocity V with the
// external force's impulse but without the torque's, which the step adds to
// the body all the same (writeBackBodies): a soft row solved from that V
// would miss a driven wheel's torque for one step (measured: the saturated
// drive's first step got no traction in Bullet, 105 N in ODE).
static double torqueVelocity(const btSolverConstraint& row, const btAlignedObjectArray<btSolverBody>& bodies) {
  const btSolverBody& a = bodies[row.m_solverBodyIdA];
  const btSolverBody& b = bodies[row.m_solverBodyIdB];
  return (a.m_originalBody != nullptr ? row.m_relpos1CrossNormal.dot(a.m_externalTorqueImpulse) : 0.0) +
         (b.m_originalBody != nullptr ? row.m_relpos2CrossNormal.dot(b.m_externalTorqueImpulse) : 0.0);
}

void RigidTreadRows::soften(btConstraintArray& contacts, btConstraintArray& frictions,
                            const btAlignedObjectArray<btSolverBody>& bodies, bool two_directions) {
  if (points_.empty()) return;
  // A few points per wheel, and a group's rows are many: sort the points
  // and look each normal row's point up.
  std::sort(points_.begin(), points_.end(), [](const Point& a, const Point& b) { return a.point < b.point; });
  const int rows = two_directions ? 2 : 1;
  for (int j = 0; j < contacts.size(); ++j) {
    const btSolverConstraint& normal = contacts[j];
    const auto* point = static_cast<const btManifoldPoint*>(normal.m_originalContactPoint);
    const auto found = std::lower_bound(points_.begin(), points_.end(), point,
                                        [](const Point& a, const btManifoldPoint* b) { return a.point < b; });
    if (found == points_.end() || found->point != point) continue;
    for (int i = 0; i < rows && normal.m_frictionIndex + i < frictions.size(); ++i) {
      btSolverConstraint& row = frictions[normal.m_frictionIndex + i];
      // Bullet made it with rhs = D (v - V) (no friction anchor: the plugin
      // clears the flag on a tread point), V without the torques'
      // velocity, and its point's mu.
      row.m_friction = found->mu[i];
      row.m_lowerLimit = -found->mu[i];
      row.m_upperLimit = found->mu[i];
      if (!(row.m_jacDiagABInv > 0.0) || !(found->compliance[i] > 0.0)) continue;
      const double velocity_error = row.m_rhs / row.m_jacDiagABInv - torqueVelocity(row, bodies);
      const SoftRow soft = softRow(row.m_jacDiagABInv, velocity_error, found->compliance[i]);
      row.m_jacDiagABInv = soft.jac_diag_inv;
      row.m_rhs = soft.rhs;
      row.m_cfm = soft.cfm;
    }
  }
}

}  // namespace wtc::bullet
