#pragma once
// The per-step report of an engine adapter (wtc::bullet, wtc::ode): one
// call per wheel per internal step, after the wheel's tyre model ran and
// before the engine integrates the step. A listener interface with
// do-nothing defaults (not a global callback), shared by both adapters.
#include "wtc/tyre/explicit_stability.hpp"
#include "wtc/tyre/wheel_forces.hpp"

namespace wtc {

/// A wheel registered with an adapter: dense, in registration order.
using WheelId = int;

class WheelListener {
 public:
  virtual ~WheelListener() = default;
  /// `forces` stays valid until the wheel's next step.
  virtual void onWheelStep(WheelId wheel, const WheelForces& forces, double step_seconds) {
    (void)wheel, (void)forces, (void)step_seconds;
  }
  /// Instead of onWheelStep when the wheel's body state (pose or velocity)
  /// was not finite: the adapter applied no tyre force and no contact this
  /// step, and counts it (WheelState::nonFiniteSteps).
  virtual void onWheelSkipped(WheelId wheel, double step_seconds) { (void)wheel, (void)step_seconds; }
  /// Once per wheel, at its first step whose explicit tyre spring is beyond
  /// the step's stability limit (force mode): describe(stability) gives
  /// h sqrt(c/m) against the limit and the largest stable step. Later such
  /// steps are counted (WheelState::unstableSteps), not reported again.
  virtual void onFirstUnstableStep(WheelId wheel, const SpringStability& stability) { (void)wheel, (void)stability; }
};

}  // namespace wtc
