#include "wtc/bullet/rigid_contact_solver.hpp"

#include "rigid_tread_rows.hpp"

namespace wtc::bullet {

RigidContactSolver::RigidContactSolver() : tread_rows_(std::make_unique<RigidTreadRows>()) {}

RigidContactSolver::~RigidContactSolver() = default;

btScalar RigidContactSolver::solveGroupCacheFriendlySetup(btCollisionObject** bodies, int num_bodies,
                                                          btPersistentManifold** manifolds, int num_manifolds,
                                                          btTypedConstraint** constraints, int num_constraints,
                                                          const btContactSolverInfo& info, btIDebugDraw* debug_drawer) {
  const btScalar result = btSequentialImpulseConstraintSolver::solveGroupCacheFriendlySetup(
      bodies, num_bodies, manifolds, num_manifolds, constraints, num_constraints, info, debug_drawer);
  tread_rows_->soften(m_tmpSolverContactConstraintPool, m_tmpSolverContactFrictionConstraintPool, m_tmpSolverBodyPool,
                      (info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) != 0);
  return result;
}

}  // namespace wtc::bullet
