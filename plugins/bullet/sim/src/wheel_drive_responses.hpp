#pragma once
// The responses of the wheel drives' rows, two wheels on one parent for
// one articulated-body solve.
//
// A drive row's Jacobian is e_w, the wheel joint's coordinate, and its
// response is M^-1 e_w: one articulated-body solve
// (btMultiBody::calcAccelerationDeltasMultiDof) a row, a step. For a wheel
// w that is a leaf link on a revolute joint of world axis a, with its
// centre of mass on the axis and a a principal axis of its inertia
// (moment J about it):
//   M^-1 e_w = e_w / J - M^-1 J_p^T a,
// J_p^T a the generalised force of a pure torque a on w's parent p.
// Proof: the torque a on w itself has the generalised force
// J_w^T a = J_p^T a + e_w (w turns about a relative to p), and
// M (e_w / J) = J_w^T (I_w a) / J = J_w^T a, since e_w moves w alone and
// only about a (its centre stays on the axis); so M^-1 (J_p^T a + e_w) =
// e_w / J. Two wheels on one parent with parallel axles (a robot's left
// and right wheels) share M^-1 J_p^T a, up to its sign: one solve for both
// drives instead of two. The response is Bullet's to rounding.
//
// The shared solves hold for one solver setup: forget() them before each
// engine step (the multibody's mass matrix changes with its pose).
#include <vector>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>

namespace wtc::bullet {

class WheelDriveResponses {
 public:
  /// Whether the drive of `body`'s link `link` can share its parent's
  /// solve: a leaf link on a revolute joint, its centre of mass on the
  /// axis and the axis a principal axis of its inertia
  /// (tolerance::kSharedDriveSolveRelative).
  static bool applies(const btMultiBody& body, int link);

  /// Forgets this step's shared solves (their poses have moved).
  void forget() { used_ = 0; }

  /// Writes M^-1 (sign e_link) to `response` (getNumDofs() + 6 values) for
  /// a link applies() accepted, from its parent's shared solve if a wheel
  /// on the same parent with a parallel axle made one this step, otherwise
  /// from one new solve (then kept).
  void fill(btMultiBodyJacobianData& data, const btMultiBody& body, int link, double sign, btScalar* response);

  /// The articulated-body solves the shared responses saved since
  /// construction.
  long long solvesSaved() const { return saved_; }

 private:
  struct Shared {
    const btMultiBody* body;
    int parent;                      // -1: the base
    btVector3 axis;                  // world, unit
    std::vector<btScalar> response;  // M^-1 J_p^T axis
  };
  std::vector<Shared> shared_;  // the first used_ are this step's; kept to reuse their memory
  std::size_t used_ = 0;
  std::vector<btScalar> force_;  // scratch: J_p^T axis
  long long saved_ = 0;
};

}  // namespace wtc::bullet
