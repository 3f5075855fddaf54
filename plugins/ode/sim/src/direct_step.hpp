#pragma once
// ODE's direct step (dWorldStep) that never keeps a step its LCP gave up on
// (wtc::ode sim engine; issue 40, item 3). Design note:
//
// dWorldStep's Dantzig LCP (ODE's lcp.cpp, dSolveLCP) drives one bounded
// row after another into its valid region, each by a step s along a pivot
// direction. When the largest admissible s is <= 0 it prints "LCP internal
// error, s <= 0", leaves every row it had not reached without force (x = 0)
// and finishes the step: a drive, a wheel's motor, a joint's stop do nothing
// for that step.
//
// What made it give up in WTC's scenes (measured with an ODE built from
// github:thomasmarsh/ODE that prints the failing pivot; docs/hard-cases.md)
// is a row that starts Dantzig's solve in its set N (x at its bound 0) at
// w = 0 exactly. A later drive row whose push lowers that w (dw < 0,
// through the bodies they share) asks for s = -w / dw = 0: a degenerate
// pivot, which ODE's code treats as failure. Two kinds of such rows:
//   - a joint resting exactly on its stop (the robot's sliders start at
//     q = 0 = their lower stop; a free-falling robot keeps them there):
//     ODE adds the stop's row with rhs = -ERP q_err / h - J v = -0;
//   - a body's contact that repeats another (the chassis box against two
//     terrain pieces that share a face: the same point, normal and depth
//     twice): with its twin in C its w is the twin's, 0.
//
// A step's solve is therefore tried as it is first; only when ODE gave up
// is it solved again from the same state, so that every step ODE solves is
// solved exactly as before, bit for bit:
//   1. without those rows: the stops of the joints resting exactly on them
//      (q on the stop, rate exactly 0) released, the repeated contacts
//      disabled, for that step. A repeated contact adds nothing its twin
//      does not carry. Where a drive holds the joint or pushes it off its
//      stop (every case measured), the stop's force is 0 in the solution
//      and nothing changes; a drive pulling into it moves the joint past
//      the stop by at most its rate times h, which the stop's own ERP takes
//      back from the next step on;
//   2. if ODE still gives up (or no joint rested on a stop): the same rows
//      by dWorldQuickStep, which gives every row a force (projected
//      Gauss-Seidel does not stop early), instead of the rows ODE zeroed.
//      ODE's messages of that step are counted as before
//      (Engine::solverMessages, summary.json's warnings).
//
// Before all of this, a step is solved with the drives' rows that were
// within their caps taken as equations (drive_rows.hpp); it stands when
// ODE solved it and each of those drives came out within its cap, and is
// otherwise solved as above from the same state.
#include <ode/ode.h>

#include <array>
#include <functional>
#include <span>
#include <vector>

#include "drive_rows.hpp"
#include "wtc/ode/message_log.hpp"

namespace wtc::ode {

/// A hinge or slider joint with stops, as built (its stops at lower/upper).
struct StoppedJoint {
  dJointID joint = nullptr;
  double lower = 0.0;  ///< rad or m
  double upper = 0.0;  ///< rad or m
};

/// How a step's solve was kept.
enum class DirectStepOutcome {
  kSolved,                 ///< dWorldStep's first solve
  kDegenerateRowsLeftOut,  ///< ODE gave up; solved again without the degenerate rows (1.)
  kQuickStep,              ///< ODE gave up again, or had no such row: dWorldQuickStep's (2.)
};

class DirectStepper {
 public:
  /// Steps `world`, whose bodies are `bodies` (every body of the world) and
  /// whose joints with stops are `stopped` and whose drives are `drives`.
  /// `quick_step(h)` runs dWorldQuickStep on the world (the caller keeps
  /// its random seed).
  DirectStepper(dWorldID world, std::vector<dBodyID> bodies, std::vector<StoppedJoint> stopped, DriveRows drives,
                std::function<void(double)> quick_step);

  /// One step of `h` seconds. `duplicate_contacts` are contact joints of
  /// this step that repeat an earlier one of the same bodies (same point and
  /// normal: wtc::sim::kDuplicateContactM). ODE's messages of a kept failed
  /// solve go to `log` (as a MessageLog::Capture of it would have counted
  /// them); those of a solve done again are dropped.
  DirectStepOutcome step(double h, MessageLog& log, std::span<const dJointID> duplicate_contacts);

 private:
  struct BodyState {
    std::array<dReal, 3> position, linear_velocity, angular_velocity, force, torque;
    std::array<dReal, 4> quaternion;
  };
  struct ReleasedStop {
    dJointID joint;
    int parameter;  // dParamLoStop or dParamHiStop
    double value;
  };

  DirectStepOutcome solveCapped(double h, MessageLog& log, std::span<const dJointID> duplicate_contacts);
  void save();
  void restore();
  void findRestingStops();                  // into released_, before the step
  void setResting(bool released);           // released_'s stops open, or back where they were
  bool gaveUp(double h, MessageLog& said);  // one dWorldStep, its messages counted in `said`

  dWorldID world_;
  std::vector<dBodyID> bodies_;
  std::vector<StoppedJoint> stopped_;
  DriveRows drives_;
  std::function<void(double)> quick_step_;
  std::vector<BodyState> saved_;                      // the bodies before the step (sized once)
  std::vector<ReleasedStop> released_;                // the stops resting at the step's start (sized once)
  MessageLog drives_said_{MessageLog::Keep::kTotal};  // whether ODE gave up on a solve with drives released
  MessageLog attempt_;                                // ODE's messages of a step's first solve with every cap
  MessageLog retry_;                                  // and of its solve without the degenerate rows
};

}  // namespace wtc::ode
