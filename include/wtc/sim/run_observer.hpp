#pragma once
// Something told of a run as it goes (a replay, a live view): runScene
// calls it at the start and after every step (RunOptions::observer).
namespace wtc::sim {

class Run;

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  /// `run` at the start (no step yet) and after each step; valid for the call.
  virtual void observe(const Run& run) = 0;
};

}  // namespace wtc::sim
