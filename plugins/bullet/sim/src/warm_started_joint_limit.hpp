#pragma once

#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>

namespace wtc::bullet {

// The bounds of one revolute or prismatic joint coordinate, q in
// [lower, upper], whose solve starts from the last step's reaction.
//
// Bullet's btMultiBodyJointLimitConstraint makes a row for a bound the
// joint is at or beyond when the step starts and starts it from zero
// impulse; a joint held against its stop under load (a retracted slider
// carrying a section) then rebuilds its reaction over many Gauss-Seidel
// sweeps each step, as the drives did (WarmStartedMotor). Here a bound
// whose row this step will make (the same test, on the joint position at
// the start of the step, which the solver sees unchanged) gets the last
// step's reaction first, as a joint torque, and its row solves for the
// change within [0, max] shifted by it: the total stays a push away from
// the stop, and the solution is the same. The rows are Bullet's (same
// Baumgarte term, erp / h of the overlap), on the multibody alone
// (appendJointRow).
class WarmStartedJointLimit final : public btMultiBodyConstraint {
 public:
  WarmStartedJointLimit(btMultiBody* body, int link, double lower, double upper);

  // Before the engine's step of h: the last reaction of each bound whose
  // row the step will make, applied as a joint torque. Once a step.
  void prepare(double h);
  // After it: each bound's reaction in it (N m or N, >= 0, away from the stop).
  void stepped();

  void finalizeMultiDof() override;
  int getIslandIdA() const override;
  int getIslandIdB() const override { return getIslandIdA(); }  // no body B: A's island
  void createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                            const btContactSolverInfo& info) override;
  void debugDraw(btIDebugDraw*) override {}

 private:
  // Of the joint past bound 0 (lower) or 1 (upper), negative when past it:
  // the step makes the bound's row when <= 0.
  double penetration(int bound) const;

  double bound_[2];                       // lower, upper (rad or m)
  double feedforward_[2] = {0.0, 0.0};    // applied this step, away from each stop (N m or N)
  double last_reaction_[2] = {0.0, 0.0};  // (N m or N)
  bool row_made_[2] = {false, false};
  double h_ = 0.0;  // the step the impulses are over (s)
};

}  // namespace wtc::bullet
