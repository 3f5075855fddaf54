#pragma once
// wtc::bullet::ContactSolver: Bullet's multibody constraint solver with
// implicit mode's tread rows bounded by the normal impulse the solver has
// reached for their contact, at every iteration, as Bullet bounds its own
// friction rows (|lambda_i| <= mu_i lambda_n), and as ODE bounds them
// (dContactApprox1). A btMultiBodyConstraint's rows have fixed bounds: with
// the tyre model's R_z at the start of the step, a tread row could push
// with mu R_z at a contact the solver unloads within the step (a wheel
// leaving the ground, a load moving to another contact). Implicit mode
// refuses a multibody world whose solver is not one of these.
//
// Its rigid wheels' tread rows (btRigidBody wheels in the multibody world)
// are Bullet's own friction rows made soft, as RigidContactSolver makes
// them (rigid_contact_solver.hpp).
//
// It is a FrictionlessContactSolver: it makes no friction rows for the
// frictionless contacts of WTC's multibody wheels.
//
// Usage: construct it in place of btMultiBodyConstraintSolver:
//   wtc::bullet::ContactSolver solver;
//   btMultiBodyDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
// Constraint mode's rows keep their bounds from the start of the step.
#include <memory>
#include <utility>
#include <vector>

#include "wtc/bullet/frictionless_contact_solver.hpp"

namespace wtc::bullet {

class WheelFrictionConstraint;  // the plugin's own rows (internal)
class RigidTreadRows;           // the plugin's table of a rigid wheel's rows (internal)

class ContactSolver : public FrictionlessContactSolver {
 public:
  /// `warm_start`: FrictionlessContactSolver's, for the normal rows of WTC's
  /// multibody wheels.
  explicit ContactSolver(bool warm_start = false);
  ~ContactSolver() override;
  /// The rows the plugin hands this solver for the step's rigid wheels (internal).
  RigidTreadRows& treadRows() { return *tread_rows_; }

 protected:
  btScalar solveGroupCacheFriendlySetup(btCollisionObject** bodies, int num_bodies, btPersistentManifold** manifolds,
                                        int num_manifolds, btTypedConstraint** constraints, int num_constraints,
                                        const btContactSolverInfo& info, btIDebugDraw* debug_drawer) override;
  btScalar solveSingleIteration(int iteration, btCollisionObject** bodies, int num_bodies,
                                btPersistentManifold** manifolds, int num_manifolds, btTypedConstraint** constraints,
                                int num_constraints, const btContactSolverInfo& info,
                                btIDebugDraw* debug_drawer) override;

 private:
  struct Bound {
    int row;     // in m_multiBodyNonContactConstraints
    int normal;  // in m_multiBodyNormalContactConstraints
    double mu;   // dimensionless
  };
  std::vector<Bound> bounds_;
  std::vector<std::pair<const void*, int>> normals_;                    // manifold point -> normal row, sorted
  std::vector<std::pair<int, const WheelFrictionConstraint*>> treads_;  // tread row -> its constraint
  std::unique_ptr<RigidTreadRows> tread_rows_;
};

}  // namespace wtc::bullet
