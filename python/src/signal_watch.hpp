#pragma once
// Ctrl-C during a run whose engine steps without the GIL: Python's own
// SIGINT handler only marks the signal, and the mark is acted on when
// Python next runs (PyErr_CheckSignals, main thread, GIL held). The watch
// does that between steps, at most every kSignalCheckSeconds of wall time
// (a clock read per step, the GIL taken about 50 times a second: nothing a
// step of tens of microseconds notices), and when the handler raised
// (KeyboardInterrupt) it keeps the exception and sets the run's stop flag,
// so the run ends as wtc-sim's does on SIGINT: outputs written, the summary
// interrupted. The caller then raises the kept exception.
#include <atomic>
#include <chrono>
#include <optional>

#include "bindings.hpp"
#include "wtc/sim/run_observer.hpp"

namespace wtc::python {

/// Wall time between two looks at Python's signals (s).
inline constexpr double kSignalCheckSeconds = 0.02;

class SignalWatch final : public sim::RunObserver {
 public:
  /// Stops the run through `stop` (the run's RunOptions::stop).
  explicit SignalWatch(std::atomic<bool>& stop) : stop_(stop), next_(std::chrono::steady_clock::now()) {}
  /// Called without the GIL, after each step.
  void observe(const sim::Run& run) override;
  /// A look now, GIL held (Simulation.step between its steps).
  bool check();
  /// Raises what the signal's handler raised, if it did (GIL held).
  void raiseIfSignalled();

 private:
  std::atomic<bool>& stop_;
  std::chrono::steady_clock::time_point next_;
  std::optional<py::error_already_set> raised_;
};

}  // namespace wtc::python
