#pragma once
// Bullet's multibody solver without the friction rows of frictionless
// contacts (internal to the Bullet sim engine).
//
// Why: in constraint mode a WTC wheel that is a multibody link hands
// Bullet its contacts with no friction (m_combinedFriction = 0): their
// friction is WheelFrictionConstraint's own rows (the plugin's
// wheel_friction_constraint.hpp). Bullet's btMultiBodyConstraintSolver::
// convertMultiBodyContact still makes two friction rows for every contact
// point (SOLVER_USE_2_FRICTION_DIRECTIONS, which a multibody world keeps),
// each bounded by mu N = 0: each costs an articulated-body solve to set up
// (btMultiBody::calcAccelerationDeltasMultiDof) and a cone update in every
// sweep, and never applies an impulse (its bound is +-0, so its impulse and
// every velocity change it makes are zero: the solution is bit for bit the
// one with the rows).
//
// This solver converts a multibody manifold whose every point has no
// friction (sliding, rolling or spinning) into its normal rows alone, the
// rows btMultiBodyConstraintSolver makes (setupMultiBodyContactConstraint,
// Bullet 3.24), in the same order as every other manifold's; every other
// manifold goes to Bullet's own conversion. Bullet's finish reads a normal
// row's two friction rows (their impulses become the point's lateral
// impulses): those rows point at one pair of empty rows, added after the
// sweeps, with no body and no impulse.
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>

namespace wtc::bullet {

class FrictionlessContactSolver final : public btMultiBodyConstraintSolver {
 public:
  /// The friction rows this solver did not make in the last solve (two per
  /// frictionless contact point).
  int skippedFrictionRows() const { return skipped_; }

 protected:
  void convertContacts(btPersistentManifold** manifolds, int count, const btContactSolverInfo& info) override;
  btScalar solveGroupCacheFriendlyFinish(btCollisionObject** bodies, int count,
                                         const btContactSolverInfo& info) override;

 private:
  void convertNormalRows(btPersistentManifold& manifold, const btContactSolverInfo& info);
  btAlignedObjectArray<int> frictionless_rows_;  // indices in m_multiBodyNormalContactConstraints
  int skipped_ = 0;
};

}  // namespace wtc::bullet
