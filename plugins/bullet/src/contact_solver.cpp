#include "wtc/bullet/contact_solver.hpp"

#include <algorithm>
#include <utility>

#include "rigid_tread_rows.hpp"
#include "wheel_friction_constraint.hpp"

namespace wtc::bullet {

ContactSolver::ContactSolver(bool warm_start)
    : FrictionlessContactSolver(warm_start), tread_rows_(std::make_unique<RigidTreadRows>()) {}

ContactSolver::~ContactSolver() = default;

// After Bullet has made every row: each tread row that follows its normal
// is paired with the normal row of its contact's manifold point.
btScalar ContactSolver::solveGroupCacheFriendlySetup(btCollisionObject** bodies, int num_bodies,
                                                     btPersistentManifold** manifolds, int num_manifolds,
                                                     btTypedConstraint** constraints, int num_constraints,
                                                     const btContactSolverInfo& info, btIDebugDraw* debug_drawer) {
  const btScalar result = FrictionlessContactSolver::solveGroupCacheFriendlySetup(
      bodies, num_bodies, manifolds, num_manifolds, constraints, num_constraints, info, debug_drawer);
  // The rigid wheels' rows are Bullet's (rigid_tread_rows.hpp).
  tread_rows_->soften(m_tmpSolverContactConstraintPool, m_tmpSolverContactFrictionConstraintPool, m_tmpSolverBodyPool,
                      (info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) != 0);
  bounds_.clear();
  // The tread rows, in one pass: a constraint's rows are contiguous, so a
  // constraint is cast once. Kept from step to step (members): no allocation
  // once warm.
  treads_.clear();
  const btMultiBodyConstraint* seen = nullptr;
  const WheelFrictionConstraint* tread = nullptr;
  for (int k = 0; k < m_multiBodyNonContactConstraints.size(); ++k) {
    const btMultiBodySolverConstraint& row = m_multiBodyNonContactConstraints[k];
    if (row.m_orgConstraint != seen) {
      seen = row.m_orgConstraint;
      tread = dynamic_cast<const WheelFrictionConstraint*>(seen);
    }
    if (tread != nullptr && tread->followsNormal(row.m_orgDofIndex)) treads_.emplace_back(k, tread);
  }
  if (treads_.empty()) return result;
  normals_.clear();
  for (int j = 0; j < m_multiBodyNormalContactConstraints.size(); ++j) {
    normals_.emplace_back(m_multiBodyNormalContactConstraints[j].m_originalContactPoint, j);
  }
  std::sort(normals_.begin(), normals_.end());
  for (const auto& [k, constraint] : treads_) {
    const int row = m_multiBodyNonContactConstraints[k].m_orgDofIndex;
    const void* point = constraint->contactPoint(row);
    const auto found = std::lower_bound(normals_.begin(), normals_.end(), std::make_pair(point, -1));
    if (point == nullptr || found == normals_.end() || found->first != point) continue;
    bounds_.push_back({k, found->second, constraint->friction(row)});
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
  return FrictionlessContactSolver::solveSingleIteration(iteration, bodies, num_bodies, manifolds, num_manifolds,
                                                         constraints, num_constraints, info, debug_drawer);
}

}  // namespace wtc::bullet
