#pragma once
// Implicit mode's tread rows for a wheel that is a btRigidBody (internal to
// wtc::bullet): Bullet's own two friction rows of each of the wheel's
// manifold points, made soft once Bullet's solver has made them.
//
// Why Bullet's rows and not WTC's own (a btTypedConstraint's): Bullet bounds
// a contact's friction rows at every sweep by m_friction times the impulse
// its normal row has just reached (btSequentialImpulseConstraintSolver::
// solveSingleIteration), which is the bound implicit mode wants; a typed
// constraint's rows have fixed bounds and are swept before the contacts. The
// directions and targets reach Bullet through the manifold point
// (m_lateralFrictionDir1/2 with BT_CONTACT_FLAG_LATERAL_FRICTION_INITIALIZED
// and SOLVER_ENABLE_FRICTION_DIRECTION_CACHING, m_contactMotion1/2, both
// rows with SOLVER_USE_2_FRICTION_DIRECTIONS): Bullet then makes each row
// with D its effective mass, rhs = D (v - V) and m_cfm = m_frictionCFM.
// What Bullet cannot take is the compliance: its friction CFM is one per
// point and unscaled (lambda += rhs - cfm lambda - D dV), so cfm = 1/(h K)
// would need D/(h K), about 100 at 0.4 ms, where the update diverges.
// soften() rewrites each row as the soft row (soft_row.hpp), and sets each
// row's own mu (Bullet gives both a point's m_combinedFriction).
//
// The plugin fills the table during the step's collision (the points of
// this step) and clears it before and after the step: a point is a key
// only while Bullet's manifold holds it.
#include <vector>

#include <BulletCollision/NarrowPhaseCollision/btManifoldPoint.h>
#include <BulletDynamics/ConstraintSolver/btSolverBody.h>
#include <BulletDynamics/ConstraintSolver/btSolverConstraint.h>

namespace wtc::bullet {

class RigidTreadRows {
 public:
  /// A manifold point's two tread rows: compliance 1 / (h K_i) (1/kg; 0: a
  /// rigid row) and bound mu_i over the normal impulse (dimensionless).
  struct Point {
    const btManifoldPoint* point = nullptr;
    double compliance[2] = {0.0, 0.0};
    double mu[2] = {0.0, 0.0};
  };

  RigidTreadRows() { points_.reserve(kReservedPoints); }
  void clear() { points_.clear(); }
  /// Sets the rows of p.point (a point written again replaces its entry:
  /// Bullet merged two contacts into it).
  void set(const Point& p);
  bool empty() const { return points_.empty(); }

  /// After Bullet's setup made the rows of a group: each listed point's
  /// normal row in `contacts` and its friction rows in `frictions` (the
  /// first at the normal row's m_frictionIndex, the second next to it when
  /// `two_directions`) become the soft rows; `bodies` the solver's bodies.
  void soften(btConstraintArray& contacts, btConstraintArray& frictions,
              const btAlignedObjectArray<btSolverBody>& bodies, bool two_directions);

 private:
  static constexpr int kReservedPoints = 64;  // no allocation in the step loop for up to 16 wheels
  std::vector<Point> points_;
};

}  // namespace wtc::bullet
