#pragma once

#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>

namespace wtc::bullet {

class WheelDriveResponses;

// A velocity-controlled drive of one revolute or prismatic joint whose
// solve starts from the last step's effort, with one articulated-body solve
// a step.
//
// Warm start: Bullet's multibody solver starts every joint-motor row from
// zero impulse each step (btMultiBodyConstraint::fillMultiBodyConstraint),
// and a drive holding a wheel against the tyre's traction then needs many
// Gauss-Seidel sweeps to build its torque up again. Here the last effort is
// applied first as a joint torque (integrated with the other external
// forces), and the row solves only for the change, within the limits
// shifted by what is already applied: the total, feedforward + row, stays
// in [-max, max], and the solution the solver converges to is the same.
//
// One solve: btMultiBodyJointMotor names the multibody as both its bodies
// A and B, so Bullet computes each row's response twice, M^-1 J_A^T and
// M^-1 J_B^T, the second for J_B = 0 (the joint coordinate's Jacobian is
// e_dof on A alone). This drive has no body B and fills its row itself:
// the same row, half the articulated-body solves, and no B terms in the
// solver's sweeps.
class WarmStartedMotor final : public btMultiBodyJointMotor {
 public:
  WarmStartedMotor(btMultiBody* body, int link);

  // This step's target: rate (rad/s or m/s), effort cap (N m or N; an
  // infinite one is the largest finite impulse), off when !active. The
  // last effort, within this cap, is applied first; a second target before
  // the step replaces the first, it does not add to it.
  void setTarget(double rate, double cap, bool active, double h);

  // After the engine's step (which cleared the joint torques): the effort
  // the drive applied in it, feedforward + row.
  void stepped();

  double effort() const { return last_effort_; }  // (N m or N)

  // A wheel's drive: its row's response from `shared` (a solve shared with
  // the wheel on the same parent, wheel_drive_responses.hpp), which must
  // accept this link (WheelDriveResponses::applies) and outlive the motor.
  void shareResponses(WheelDriveResponses* shared) { shared_ = shared; }

  void createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                            const btContactSolverInfo& info) override;
  // The multibody's island (islandOf), not the link's own collider's:
  // btMultiBodyJointMotor files a motor on a link without a collider (a
  // steering knuckle, a link of a mesh-less chain) under island -1, which
  // the island solver never solves, and the drive did nothing (issue 52
  // row 1: a steered car's knuckles never moved in Bullet).
  int getIslandIdA() const override;
  int getIslandIdB() const override { return getIslandIdA(); }  // no body B: A's island

 private:
  double feedforward_ = 0.0;  // applied this step, not yet stepped (N m or N)
  double last_effort_ = 0.0;  // (N m or N)
  double h_ = 0.0;            // the step the impulses are over (s)
  bool row_made_ = false;     // this step: the solver has the row and set its impulse
  WheelDriveResponses* shared_ = nullptr;
};

}  // namespace wtc::bullet
