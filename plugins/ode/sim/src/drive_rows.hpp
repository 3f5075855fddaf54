#pragma once
// The drives' rows of ODE's direct step taken as equations first (wtc::ode
// sim engine; issue 40, item 1; issue 41). Design note:
//
// A joint's drive (dJointAMotor / dJointLMotor) is one row of dWorldStep's
// LCP, bounded by the drive's cap: |lambda| <= fmax. Dantzig's solver
// (ODE's lcp.cpp) factors the rows without bounds (the joints' equality
// rows) together, once, and then brings each bounded row in by pivoting,
// each pivot two triangular solves through the factor: a drive costs what
// a contact row costs. Most steps, no drive is at its cap.
//
// A row whose force is strictly within its bounds satisfies the same
// condition as a row without bounds (its residual w = 0), so a solution
// of the problem with a drive's bounds removed whose force is within the
// cap solves the problem with them: the step is the same step (up to
// rounding). So a step is first solved with the drives not at their caps
// lately unbounded (fmax = dInfinity: ODE adds the row with lo = -inf,
// hi = inf, and its solver factors it with the equality rows). If any such
// drive's force came out over its cap, or ODE gave up on that solve, the
// step is solved again from the same state with every cap in place,
// exactly as before. A drive found at or over its cap stays capped for a
// while (drive_rows.cpp's kCappedHoldS): a drive working at its cap comes
// off it and back within milliseconds, and each return over it would be a
// step solved twice.
// What it saves, measured: docs/performance.md ("ODE's drive rows").
#include <ode/ode.h>

#include <vector>

namespace wtc::ode {

/// A one-axis AMotor's torque or LMotor's force along its axis on the
/// first body it joins, from its feedback after a step (N m or N).
double motorForce(dJointID motor, const dJointFeedback& feedback);

class DriveRows {
 public:
  /// A one-axis AMotor or LMotor whose feedback is `feedback` (set with
  /// dJointSetFeedback: its force is read after the step).
  void add(dJointID motor, const dJointFeedback* feedback);

  /// Before a step: the drives switched on and not at their cap lately
  /// lose their bounds for this solve. Whether any did.
  bool release();
  /// After the step solved by release(): every cap back in place, and
  /// whether each released drive's force was within its cap (the step
  /// stands). A drive found over it is capped for the next steps.
  bool restore();
  /// After a step of `h` seconds kept: which drives are at their cap
  /// (capped for the next steps).
  void noteCaps(double h);

 private:
  struct Drive {
    dJointID motor = nullptr;
    const dJointFeedback* feedback = nullptr;
    double cap = 0.0;         // fmax while released (N m or N)
    bool released = false;    // this step's solve had it unbounded
    double capped_for = 0.0;  // s: not released while > 0 (at or over its cap lately)
  };

  std::vector<Drive> drives_;
};

}  // namespace wtc::ode
