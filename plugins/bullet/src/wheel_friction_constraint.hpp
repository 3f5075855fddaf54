#pragma once
// Constraint mode's friction for a wheel that is a multibody link (internal
// to wtc::bullet).
//
// Why not Bullet's own: btMultiBodyConstraintSolver::convertMultiBodyContact
// overwrites every contact's friction directions with btPlaneSpace1 (a frame
// fixed by the normal alone) before it looks at the plugin's direction, and
// caps each of its two rows at mu N: a pyramid in a frame unrelated to the
// slip. A skid-steering robot's scrubbing wheels then pushed where the slip
// law does not (issue 11: the robot turned 90.8 deg in 6 s against 273.4 deg
// in the other engine-mode pairs). So a multibody wheel's contacts reach
// Bullet with no friction of their own, and this constraint gives each one
// the row the rigid-body path has: one direction, along the traction (the
// engine contact's friction_direction), the relative velocity of the
// tread point P along it driven to zero within +-mu R_z h. R_z is the tyre
// model's normal force at the start of the step (the multibody solver
// cannot couple a constraint's bound to a contact's normal impulse).
//
// Implicit mode (solver_contact.hpp): the tread's rows, soft (soft_row.hpp:
// lambda = h K (v - V+) at the fixed point, a contraction at any step). A
// contact's second row runs across the first, bounded by friction_across.
#include <span>
#include <vector>

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>

#include "wtc/adapter/solver_contact.hpp"
#include "wtc/tyre/wheel_forces.hpp"

namespace wtc::bullet {

class WheelFrictionConstraint final : public btMultiBodyConstraint {
 public:
  /// At most `rows` rows (a contact has one, or two in implicit mode); the
  /// contacts beyond are left free.
  WheelFrictionConstraint(btMultiBody* multibody, int link, int rows);

  /// This step's rows: each contact's, bounded by its mu times its load
  /// (SolverContact::load), step h.
  void set(std::span<const SolverContact> contacts, double h);
  /// The force (N, world) the solver applied on the wheel at contact i of
  /// the last set(), along its rows; zero for a contact without a row.
  /// (Not const: this Bullet's getAppliedImpulse is not.)
  btVector3 appliedForce(std::size_t i, double h);

  /// Where a contact's manifold point is once Bullet has collided the wheel
  /// (the wheel's manifold and, per contact, the point's index or -1;
  /// plugin_state.hpp): ContactSolver bounds a row by that point's normal
  /// impulse.
  void setContactPoints(btPersistentManifold* const* manifold, const std::vector<int>* points);
  /// Row r's contact's manifold point, or null.
  const btManifoldPoint* contactPoint(int row) const;
  /// Row r's mu: its bound over its contact's normal force (dimensionless).
  double friction(int row) const { return active_[static_cast<std::size_t>(row)].mu; }
  /// Whether ContactSolver bounds row r by its contact's normal impulse
  /// (implicit mode's rows; constraint mode's keep the start-of-step bound).
  bool followsNormal(int row) const { return active_[static_cast<std::size_t>(row)].compliance > 0.0; }

  void finalizeMultiDof() override;
  int getIslandIdA() const override;
  int getIslandIdB() const override { return -1; }  // the static terrain
  void createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                            const btContactSolverInfo& info) override;
  void debugDraw(btIDebugDraw*) override {}

 private:
  struct Row {
    btVector3 point, direction;
    double limit;       // impulse (N s)
    double velocity;    // v along direction (m/s); 0 for rigid friction
    double compliance;  // 1 / (h K) (1/kg); 0 for rigid friction
    double mu;          // the bound over the normal force
    std::size_t contact;
  };
  void add(const Row& row);
  std::vector<Row> active_;
  btPersistentManifold* const* manifold_ = nullptr;
  const std::vector<int>* points_ = nullptr;
};

}  // namespace wtc::bullet
