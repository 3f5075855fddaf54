#pragma once
// wtc::bullet::RigidContactSolver: Bullet's sequential-impulse solver with
// implicit mode's tread rows for wheels that are btRigidBody objects.
//
// Implicit mode (ContactMode::kImplicit) gives each contact two compliant
// friction rows, R_i = K_i (v_i - V_i+) within mu_i times the normal force
// (wtc/adapter/solver_contact.hpp). Bullet's own solver takes a friction
// row's CFM unscaled, where the tread's compliance would diverge; this
// solver makes the wheel's friction rows soft rows after Bullet has made
// them (plugins/bullet/src/rigid_tread_rows.hpp), and Bullet bounds them at
// every sweep by mu_i times the normal impulse the sweep has reached.
// Implicit mode refuses a rigid wheel whose world's solver is not this one
// (in a btMultiBodyDynamicsWorld: wtc::bullet::ContactSolver, which does the
// same for its rigid wheels). Other contacts and constraints are Bullet's.
//
// Usage: construct it in place of btSequentialImpulseConstraintSolver, and
// keep it the world's solver while the plugin has wheels:
//   wtc::bullet::RigidContactSolver solver;
//   btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
#include <memory>

#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>

namespace wtc::bullet {

class RigidTreadRows;  // the plugin's table of tread rows (internal)

class RigidContactSolver : public btSequentialImpulseConstraintSolver {
 public:
  RigidContactSolver();
  ~RigidContactSolver() override;
  /// The rows the plugin hands this solver for the step (internal).
  RigidTreadRows& treadRows() { return *tread_rows_; }

 protected:
  btScalar solveGroupCacheFriendlySetup(btCollisionObject** bodies, int num_bodies, btPersistentManifold** manifolds,
                                        int num_manifolds, btTypedConstraint** constraints, int num_constraints,
                                        const btContactSolverInfo& info, btIDebugDraw* debug_drawer) override;

 private:
  std::unique_ptr<RigidTreadRows> tread_rows_;
};

}  // namespace wtc::bullet
