#pragma once
// wtc::bullet::FrictionlessContactSolver: Bullet's multibody solver without
// the friction rows of frictionless contacts, optionally starting their
// normal rows from the last step's impulses. Use it in place of
// btMultiBodyConstraintSolver for WTC wheels that are multibody links in
// constraint mode; ContactSolver (contact_solver.hpp, implicit mode) is one.
//
// Why: a WTC wheel that is a multibody link hands Bullet its contacts with
// no friction (m_combinedFriction = 0): their friction is
// WheelFrictionConstraint's own rows. Bullet's btMultiBodyConstraintSolver::
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
//
// Usage:
//   wtc::bullet::FrictionlessContactSolver solver(/*warm_start=*/true);
//   btMultiBodyDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
#include <vector>

#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>

namespace wtc::bullet {

class FrictionlessContactSolver : public btMultiBodyConstraintSolver {
 public:
  /// With `warm_start`, a frictionless manifold's normal rows start from
  /// the impulse its point of the same index had at the last solve
  /// (Bullet's rule for its articulated warm start: scaled by the ratio of
  /// the right-hand sides and m_articulatedWarmstartingFactor, none when
  /// they differ by more than 2x), counted in the row's impulse so that its
  /// bound (>= 0) holds for the total. (Bullet 3.24's own warm start of a
  /// multibody contact, SOLVER_USE_ARTICULATED_WARMSTARTING, applies the
  /// start's velocity change and then, with friction directions cached,
  /// zeroes the row's impulse: the contact cannot push less than its start.)
  explicit FrictionlessContactSolver(bool warm_start = false) : warm_start_(warm_start) {}

  /// The friction rows this solver did not make in the last solve (two per
  /// frictionless contact point).
  int skippedFrictionRows() const { return skipped_; }
  /// The normal rows the last solve started from a nonzero impulse.
  int warmStartedRows() const { return warm_started_; }

 protected:
  void convertContacts(btPersistentManifold** manifolds, int count, const btContactSolverInfo& info) override;
  btScalar solveGroupCacheFriendlyFinish(btCollisionObject** bodies, int count,
                                         const btContactSolverInfo& info) override;

 private:
  void convertNormalRows(btPersistentManifold& manifold, const btContactSolverInfo& info);
  void warmStart(btMultiBodySolverConstraint& row, btScalar impulse_before, btScalar rhs_before,
                 const btContactSolverInfo& info);
  // A frictionless manifold's point: its row (an index in
  // m_multiBodyNormalContactConstraints) and, after the solve, its impulse
  // and right-hand side. The last solve's are the warm start's (a guess:
  // matched by manifold and point index, as WTC's wheels refill their
  // manifold each step; with several solves a step, one island's).
  struct Point {
    const btPersistentManifold* manifold;
    int index, row;
    btScalar impulse, rhs;
  };
  // The last solve's entry of a manifold's point, or null.
  const Point* lastOf(const btPersistentManifold& manifold, int index);
  std::vector<Point> points_, last_;
  std::size_t next_last_ = 0;  // where lastOf starts looking
  bool warm_start_;
  int skipped_ = 0;
  int warm_started_ = 0;
};

}  // namespace wtc::bullet
