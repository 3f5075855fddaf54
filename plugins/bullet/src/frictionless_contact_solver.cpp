#include "wtc/bullet/frictionless_contact_solver.hpp"

#include <tuple>

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

namespace wtc::bullet {
namespace {

// A manifold on a multibody whose points all have no friction: Bullet's
// friction rows for them would all be bounded by zero.
bool frictionless(const btPersistentManifold& manifold) {
  if (btMultiBodyLinkCollider::upcast(manifold.getBody0()) == nullptr &&
      btMultiBodyLinkCollider::upcast(manifold.getBody1()) == nullptr) {
    return false;  // rigid bodies: Bullet's rigid-body rows
  }
  for (int j = 0; j < manifold.getNumContacts(); ++j) {
    const btManifoldPoint& p = manifold.getContactPoint(j);
    if (p.m_combinedFriction != 0 || p.m_combinedRollingFriction != 0 || p.m_combinedSpinningFriction != 0) {
      return false;
    }
  }
  return true;
}

}  // namespace

void FrictionlessContactSolver::convertContacts(btPersistentManifold** manifolds, int count,
                                                const btContactSolverInfo& info) {
  last_.swap(points_);
  points_.clear();
  next_last_ = 0;
  skipped_ = 0;
  warm_started_ = 0;
  // One manifold at a time, in order, so that the normal rows keep
  // Bullet's order; the multibody constraints' rows once, at the end.
  const int constraints = m_tmpNumMultiBodyConstraints;
  m_tmpNumMultiBodyConstraints = 0;
  for (int i = 0; i < count; ++i) {
    if (frictionless(*manifolds[i])) {
      convertNormalRows(*manifolds[i], info);
    } else {
      btMultiBodyConstraintSolver::convertContacts(&manifolds[i], 1, info);
    }
  }
  m_tmpNumMultiBodyConstraints = constraints;
  btMultiBodyConstraintSolver::convertContacts(nullptr, 0, info);
}

// btMultiBodyConstraintSolver::convertMultiBodyContact (Bullet 3.24) without
// its friction rows; the point's side effects kept (its friction
// directions, its flag, its warm-start reset out of range).
void FrictionlessContactSolver::convertNormalRows(btPersistentManifold& manifold, const btContactSolverInfo& info) {
  const btMultiBodyLinkCollider* a = btMultiBodyLinkCollider::upcast(manifold.getBody0());
  const btMultiBodyLinkCollider* b = btMultiBodyLinkCollider::upcast(manifold.getBody1());
  btMultiBody* body_a = a != nullptr ? a->m_multiBody : nullptr;
  btMultiBody* body_b = b != nullptr ? b->m_multiBody : nullptr;
  auto* object_a = const_cast<btCollisionObject*>(manifold.getBody0());
  auto* object_b = const_cast<btCollisionObject*>(manifold.getBody1());
  const int solver_a = body_a != nullptr ? -1 : getOrInitSolverBody(*object_a, info.m_timeStep);
  const int solver_b = body_b != nullptr ? -1 : getOrInitSolverBody(*object_b, info.m_timeStep);
  const bool caching = (info.m_solverMode & SOLVER_ENABLE_FRICTION_DIRECTION_CACHING) != 0;
  for (int j = 0; j < manifold.getNumContacts(); ++j) {
    btManifoldPoint& p = manifold.getContactPoint(j);
    if (!(p.getDistance() <= manifold.getContactProcessingThreshold())) {
      p.m_appliedImpulse = 0;  // Bullet's reset of what a warm start would read
      p.m_prevRHS = 0;
      continue;
    }
    points_.push_back({&manifold, j, m_multiBodyNormalContactConstraints.size(), 0, 0});
    btMultiBodySolverConstraint& row = m_multiBodyNormalContactConstraints.expandNonInitializing();
    row.m_orgConstraint = nullptr;
    row.m_orgDofIndex = -1;
    row.m_solverBodyIdA = solver_a;
    row.m_solverBodyIdB = solver_b;
    row.m_multiBodyA = body_a;
    if (body_a != nullptr) row.m_linkA = a->m_link;
    row.m_multiBodyB = body_b;
    if (body_b != nullptr) row.m_linkB = b->m_link;
    row.m_originalContactPoint = &p;
    btScalar relaxation = 1;
    setupMultiBodyContactConstraint(row, p.m_normalWorldOnB, p.m_appliedImpulse, p, info, relaxation, false);
    if (warm_start_) {
      if (const Point* last = lastOf(manifold, j)) warmStart(row, last->impulse, last->rhs, info);
    }
    row.m_frictionIndex = -1;  // the empty pair, in the finish
    btPlaneSpace1(p.m_normalWorldOnB, p.m_lateralFrictionDir1, p.m_lateralFrictionDir2);
    p.m_lateralFrictionDir1.normalize();
    p.m_lateralFrictionDir2.normalize();
    if (!caching || (p.m_contactPointFlags & BT_CONTACT_FLAG_LATERAL_FRICTION_INITIALIZED) == 0) {
      if ((info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) != 0 &&
          (info.m_solverMode & SOLVER_DISABLE_VELOCITY_DEPENDENT_FRICTION_DIRECTION) != 0) {
        p.m_contactPointFlags |= BT_CONTACT_FLAG_LATERAL_FRICTION_INITIALIZED;
      }
    } else if (!warm_start_) {
      row.m_appliedImpulse = 0;
      row.m_appliedPushImpulse = 0;
    }
    skipped_ += (info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) != 0 ? 2 : 1;
  }
}

// The points come in the last solve's order while the manifolds do (the
// wheels refill theirs each step): the search starts after the last match
// and goes round once, so a step's lookups are linear in its points, not
// quadratic.
const FrictionlessContactSolver::Point* FrictionlessContactSolver::lastOf(const btPersistentManifold& manifold,
                                                                          int index) {
  for (std::size_t n = 0; n < last_.size(); ++n) {
    const std::size_t i = (next_last_ + n) % last_.size();
    if (last_[i].manifold == &manifold && last_[i].index == index) {
      next_last_ = i + 1;
      return &last_[i];
    }
  }
  return nullptr;
}

// Bullet 3.24's articulated warm start of a contact row
// (setupMultiBodyContactConstraint), without its rigid-body branch (a
// WTC contact's other body is the static terrain).
void FrictionlessContactSolver::warmStart(btMultiBodySolverConstraint& row, btScalar impulse_before,
                                          btScalar rhs_before, const btContactSolverInfo& info) {
  row.m_appliedImpulse = 0;
  if (btFabs(rhs_before) > 1e-5 && rhs_before < 2 * row.m_rhs && row.m_rhs < 2 * rhs_before) {
    row.m_appliedImpulse =
        btMax(btScalar(0), impulse_before / rhs_before * row.m_rhs * info.m_articulatedWarmstartingFactor);
  }
  if (row.m_appliedImpulse == 0) return;
  ++warm_started_;
  const btScalar impulse = row.m_appliedImpulse;
  for (const auto& [body, jacobian, velocities] :
       {std::tuple{row.m_multiBodyA, row.m_jacAindex, row.m_deltaVelAindex},
        std::tuple{row.m_multiBodyB, row.m_jacBindex, row.m_deltaVelBindex}}) {
    if (body == nullptr) continue;
    btScalar* response = &m_data.m_deltaVelocitiesUnitImpulse[jacobian];
    body->applyDeltaVeeMultiDof2(response, impulse);  // the velocity change (Bullet applies it after the solve)
    applyDeltaVee(response, impulse, velocities, body->getNumDofs() + 6);  // what the sweeps see
  }
}

btScalar FrictionlessContactSolver::solveGroupCacheFriendlyFinish(btCollisionObject** bodies, int count,
                                                                  const btContactSolverInfo& info) {
  if (!points_.empty()) {
    const int empty = m_multiBodyFrictionContactConstraints.size();
    for (int k = 0; k < 2; ++k) {
      btMultiBodySolverConstraint& none = m_multiBodyFrictionContactConstraints.expand();  // no body, no constraint
      none.m_appliedImpulse = 0;
      none.m_appliedPushImpulse = 0;
      none.m_frictionIndex = -1;
    }
    for (Point& point : points_) {
      btMultiBodySolverConstraint& row = m_multiBodyNormalContactConstraints[point.row];
      row.m_frictionIndex = empty;
      point.impulse = row.m_appliedImpulse;  // the warm start's, next solve
      point.rhs = row.m_rhs;
    }
  }
  return btMultiBodyConstraintSolver::solveGroupCacheFriendlyFinish(bodies, count, info);
}

}  // namespace wtc::bullet
