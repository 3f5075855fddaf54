#pragma once
// One scene, run from start to end (wtc::sim): the controller stepped, the series recorded and the run judged
// by the scene's own criterion. The runner (wtc-sim), the tests and the
// studies all run scenes through runScene.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "wtc/sim/run_observer.hpp"
#include "wtc/sim/run_summary.hpp"
#include "wtc/sim/scene.hpp"

namespace wtc::sim {

struct RunOptions {
  std::optional<std::filesystem::path> out_dir;   ///< Where the CSV series go (must exist); none: no files.
  std::function<void(double fraction)> progress;  ///< Called about every 1 % of the run.
  const std::atomic<bool>* stop = nullptr;        ///< Set (by a signal handler) to end the run early.
  RunObserver* observer = nullptr;                ///< Told the start and every step (a Replay), if set.
  /// Told at once what the summary will warn of later, where waiting would
  /// hide it (a wheel's first unstable tyre-spring step, with its numbers).
  std::function<void(const std::string& warning)> warn;
};

/// Runs `scene` in `engine` (built from it, e.g. by makeEngine, and not
/// stepped yet) for its duration, or until a non-finite state or a stop.
RunSummary runScene(const Scene& scene, Engine& engine, const RunOptions& options = {});

class Run;

/// runScene one stretch at a time (the Python package's Simulation steps
/// scenes so): the same steps, records, observers and summary. `scene` and
/// `engine` must outlive it.
class SceneRun {
 public:
  /// The controller made, the series' first row recorded (options.out_dir),
  /// the observer told the start.
  SceneRun(const Scene& scene, Engine& engine, const RunOptions& options = {});
  ~SceneRun();
  SceneRun(const SceneRun&) = delete;
  SceneRun& operator=(const SceneRun&) = delete;

  /// Up to `n` more steps, fewer at the scene's duration, a stop request
  /// (options.stop; the run may go on after it) or a non-finite or diverged
  /// state. Returns the steps taken.
  std::uint64_t advance(std::uint64_t n);
  /// At the scene's duration, or stopped by a non-finite or diverged state.
  bool ended() const;
  const Run& run() const;
  /// The run's summary as it stands: runScene's at the end; before it, the
  /// run so far, judged as an interrupted one.
  RunSummary summary() const;

 private:
  struct State;
  std::unique_ptr<State> s_;
};

}  // namespace wtc::sim
