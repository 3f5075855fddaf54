#include "wtc/bullet/contact_solver.hpp"

#include <algorithm>
#include <utility>

#include "wheel_friction_constraint.hpp"

namespace wtc::bullet {

// After Bullet has made every row: each tread row that follows its normal
// is paired with the normal row of its contact's manifold point.
btScalar ContactSolver::solveGroupCacheFriendlySetup(btCollisionObject** bodies, int num_bodies,
                                                     btPersistentManifold** manifolds, int num_manifolds,
                                                     btTypedConstraint** constraints, int num_constraints,
                                                     const btContactSolverInfo& info, btIDebugDraw* debug_drawer) {
  const btScalar result = btMultiBodyConstraintSolver::solveGroupCacheFriendlySetup(
      bodies, num_bodies, manifolds, num_manifolds, constraints, num_constraints, info, debug_drawer);
  bounds_.clear();
  std::vector<std::pair<const void*, int>> normals;
  for (int j = 0; j < m_multiBodyNormalContactConstraints.size(); ++j) {
    normals.emplace_back(m_multiBodyNormalContactConstraints[j].m_originalContactPoint, j);
  }
  std::sort(normals.begin(), normals.end());
  for (int k = 0; k < m_multiBodyNonContactConstraints.size(); ++k) {
    const btMultiBodySolverConstraint& row = m_multiBodyNonContactConstraints[k];
    const auto* tread = dynamic_cast<const WheelFrictionConstraint*>(row.m_orgConstraint);
    if (tread == nullptr || !tread->followsNormal(row.m_orgDofIndex)) continue;
    const void* point = tread->contactPoint(row.m_orgDofIndex);
    const auto found = std::lower_bound(normals.begin(), normals.end(), std::make_pair(point, -1));
    if (point == nullptr || found == normals.end() || found->first != point) continue;
    bounds_.push_back({k, found->second, tread->friction(row.m_orgDofIndex)});
  }
  return result;
}

// Each sweep starts from the normal impulses the last one reached (the
// first from none: the rows' first sweep is bounded by zero).
btScalar ContactSolver::solveSingleIteration(int iteration, btCollisionObject** bodies, int num_bodies,
                                             btPersistentManifold** manifolds, int num_manifolds,
                                             btTypedConstraint** constraints, int num_constraints,
                                             const btContactSolverInfo& info, btIDebugDraw* debug_drawer) {
  for (const Bound& b : bounds_) {
    const double normal = std::max<double>(m_multiBodyNormalContactConstraints[b.normal].m_appliedImpulse, 0.0);
    btMultiBodySolverConstraint& row = m_multiBodyNonContactConstraints[b.row];
    row.m_lowerLimit = -b.mu * normal;
    row.m_upperLimit = b.mu * normal;
  }
  return btMultiBodyConstraintSolver::solveSingleIteration(iteration, bodies, num_bodies, manifolds, num_manifolds,
                                                           constraints, num_constraints, info, debug_drawer);
}

}  // namespace wtc::bullet
