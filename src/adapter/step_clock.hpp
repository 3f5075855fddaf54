#pragma once

#include <chrono>

namespace wtc {

/// The wall time a plugin spends in its own per-step work (reading the
/// wheels' state, finding their contacts, the tyre model, handing the
/// result to the engine), summed over its steps: what WTC costs a
/// simulation, beside what the engine costs. Two readings of the steady
/// clock per timed section (Bullet's plugin: its pre- and post-tick; ODE's:
/// its beginStep and each wheel-terrain pair its near callback hands it).
class StepClock {
 public:
  /// Times its own lifetime into `clock`.
  class Section {
   public:
    explicit Section(StepClock& clock) : clock_(clock), start_(std::chrono::steady_clock::now()) {}
    ~Section() { clock_.seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
    Section(const Section&) = delete;
    Section& operator=(const Section&) = delete;

   private:
    StepClock& clock_;
    std::chrono::steady_clock::time_point start_;
  };

  double seconds() const { return seconds_; }  ///< summed (s)

 private:
  double seconds_ = 0.0;
};

}  // namespace wtc
