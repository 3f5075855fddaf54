#pragma once
// What wtc-sim does around a run, in one place that wtc-sim and the Python
// package (python/, `wtc.run`) both call, so that a run from either writes
// the same files: the output directory and its marker
// (wtc-sim/run_directory.hpp), summary.json written at the start and
// replaced at the end, the replay page with three.js copied beside it, and
// the figures drawn by plot_run.py. The physics is runScene's (wtc::sim);
// this adds files only. A library of the apps' own (layer runner,
// cmake/layers.txt), below wtc-sim and the bindings, above everything they
// run.
#include <filesystem>
#include <functional>
#include <string>

#include "wtc-sim/run_directory.hpp"
#include "wtc/sim/run_summary.hpp"
#include "wtc/sim/scene.hpp"
#include "wtc/sim/scene_run.hpp"

namespace wtc::apps {

/// Where and what a run writes (wtc-sim's command line, or wtc.run's
/// arguments).
struct OutputRequest {
  /// The directory (new or empty; with skip kRedo, an unfinished run of the
  /// same settings); "" for runs/<scene>_<engine>_<mode>[_N] under the
  /// working directory.
  std::string out;
  SkipDone skip = SkipDone::kRun;
  std::string settings_key;          ///< settingsKey(scene file, overrides), for the marker.
  std::filesystem::path scene_file;  ///< The scene file, absolute (for the marker).
  bool replay = true;                ///< False: no replay page (--no-replay).
  bool plots = true;                 ///< False: no figures (--no-plots).
  std::string program;               ///< The running program's build (RunSummary::program).
  /// Called when the run has ended, before anything is written after it
  /// (wtc-sim ends its progress bar's line there).
  std::function<void()> on_run_end;
  /// Told each warning the writing gives (a replay page not written) and
  /// then each of the summary's warnings, in that order.
  std::function<void(const std::string& warning)> warn;
};

/// What a run with its outputs gave.
struct RunOutcome {
  sim::RunSummary summary;
  std::filesystem::path dir;  ///< Where the outputs are.
  std::string replay_said;    ///< "replay.html", or why there is none.
  std::string figures;        ///< "drawn", or why not.
  /// "ground_memory.csv" where the terrain has soil regions (the run's
  /// ruts, wtc/io/ground_memory_file.hpp), or empty.
  std::string ruts_file;
};

/// The run's directory (created, its marker written first): the design
/// note of wtc-sim/run_directory.hpp. Throws InvalidInputError for a
/// requested directory that may not be used.
std::filesystem::path makeOutputDirectory(const OutputRequest& request, const sim::Scene& scene);

/// Runs `scene` in `engine` (built from it, not stepped yet) with
/// `options` (progress, stop, warn, observer: the caller's; out_dir is set
/// here) and writes every output into makeOutputDirectory(request).
RunOutcome runWithOutputs(const sim::Scene& scene, sim::Engine& engine, const OutputRequest& request,
                          sim::RunOptions options);

/// What wtc-sim prints after a run (and `python3 -m wtc run`, from the
/// same text): the headline (success, FAILED, INTERRUPTED at t), each
/// failed criterion, the clock, the scene's figures and where the outputs
/// are, a line each.
std::string runReport(const RunOutcome& outcome);

}  // namespace wtc::apps
