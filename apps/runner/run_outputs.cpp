#include "runner/run_outputs.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <system_error>
#include <vector>

#include "app_files.hpp"
#include "wtc/base/error.hpp"
#include "wtc/io/ground_memory_file.hpp"
#include "wtc/sim/replay.hpp"
#include "wtc/sim/run.hpp"
#include "wtc/sim/run_summary_file.hpp"

namespace wtc::apps {
namespace {

namespace fs = std::filesystem;

// The replay page beside the run's data, with three.js copied in so the
// directory can be moved. Returns what went wrong, or "".
std::string writeReplayPage(const fs::path& dir) {
  const fs::path three = WTC_THREE_JS_DIR;
  const fs::path files[][2] = {{ownFile("wtc-sim", "replay.html"), dir / "replay.html"},
                               {three / "build/three.min.js", dir / "three.min.js"},
                               {three / "examples/js/controls/OrbitControls.js", dir / "OrbitControls.js"}};
  for (const auto& [from, to] : files) {
    std::error_code error;
    fs::copy_file(from, to, fs::copy_options::overwrite_existing, error);
    if (error) return "cannot copy " + from.string() + " (is libjs-three installed?): " + error.message();
  }
  return {};
}

// Tells two observers of a run (the replay and the caller's) each step.
class BothObservers final : public sim::RunObserver {
 public:
  BothObservers(sim::RunObserver* first, sim::RunObserver* second) : first_(first), second_(second) {}
  void observe(const sim::Run& run) override {
    if (first_ != nullptr) first_->observe(run);
    if (second_ != nullptr) second_->observe(run);
  }

 private:
  sim::RunObserver* first_;
  sim::RunObserver* second_;
};

}  // namespace

fs::path makeOutputDirectory(const OutputRequest& request, const sim::Scene& scene) {
  const std::string engine = scene.engine.engine, mode = std::string(sim::modeName(scene.engine));
  fs::path dir;
  if (!request.out.empty()) {
    dir = request.out;
    requireDirectoryOrNothing(request.out);
    if (request.skip == SkipDone::kRedo) {
      removeRunFiles(dir);
    } else if (fs::exists(dir) && !fs::is_empty(dir)) {
      throw InvalidInputError("--out " + request.out + ": the directory exists and is not empty (an earlier run's?)");
    }
    fs::create_directories(dir);
  } else {
    const std::string base = "runs/" + scene.name + "_" + engine + "_" + mode;
    dir = base;
    for (int n = 2; fs::exists(dir); ++n) dir = base + "_" + std::to_string(n);
    fs::create_directories(dir);
  }
  writeMarker(dir, request.settings_key, request.scene_file.string(), scene.name, engine, mode);
  return dir;
}

RunOutcome runWithOutputs(const sim::Scene& scene, sim::Engine& engine, const OutputRequest& request,
                          sim::RunOptions options) {
  RunOutcome outcome;
  outcome.dir = makeOutputDirectory(request, scene);
  const fs::path& dir = outcome.dir;
  options.out_dir = dir;
  // A summary from the start: a run killed before its end (SIGKILL, a
  // power cut) leaves one that says so; the end replaces it whole.
  sim::writeRunStarted(dir / "summary.json", scene);
  std::optional<sim::Replay> replay;
  outcome.replay_said = "replay.html";
  if (!request.replay || !scene.output.replay) {
    outcome.replay_said = !request.replay ? "no replay (--no-replay)" : "no replay (output.replay: false)";
  } else {
    replay.emplace(scene, scene.output.replay_fps);
  }
  BothObservers observers(replay ? &*replay : nullptr, options.observer);
  options.observer = &observers;
  try {
    outcome.summary = sim::runScene(scene, engine, options);
  } catch (const std::exception& e) {
    // The caller reports the error; the summary says the run is over.
    sim::writeRunFailed(dir / "summary.json", e.what());
    throw;
  }
  sim::RunSummary& summary = outcome.summary;
  summary.program = request.program;
  if (request.on_run_end) request.on_run_end();
  sim::writeRunSummary(dir / "summary.json", summary);
  // The ruts, for a run that starts on them (a scene's ground_memory_from).
  if (const GroundMemory* memory = sim::groundMemory(engine)) {
    io::writeGroundMemoryCsv(dir / "ground_memory.csv", *memory);
    outcome.ruts_file = "ground_memory.csv";
  }
  const auto warn = [&request](const std::string& w) {
    if (request.warn) request.warn(w);
  };
  if (replay) {
    replay->write(dir / "replay_data.js", summary);
    if (const std::string problem = writeReplayPage(dir); !problem.empty()) {
      warn("replay page not written: " + problem);
    }
  }
  for (const std::string& w : summary.warnings) warn(w);

  outcome.figures = "skipped (--no-plots)";
  if (request.plots && scene.output.plots) {
    // plot_run.py reads each drive's joint (its units) from summary.json.
    outcome.figures = runPlotScript(ownFile("wtc-sim", "plot_run.py"), dir)
                          ? "drawn"
                          : "not drawn (python3 with matplotlib is needed; see above)";
  }
  return outcome;
}

std::string runReport(const RunOutcome& outcome) {
  const sim::RunSummary& summary = outcome.summary;
  std::string text;
  char line[512];
  const auto add = [&](int n) { text.append(line, static_cast<std::size_t>(std::clamp(n, 0, int(sizeof line) - 1))); };
  char headline[64] = "success";
  if (summary.interrupted) {
    std::snprintf(headline, sizeof headline, "INTERRUPTED at t = %.3f s", summary.sim_time);
  } else if (!summary.success) {
    std::snprintf(headline, sizeof headline, "FAILED");
  }
  text += summary.scene + " in " + summary.engine + " (" + summary.mode + " mode, dt ";
  add(std::snprintf(line, sizeof line, "%g s): %s\n", summary.dt, headline));
  for (const sim::FailedCriterion& f : summary.failed_criteria) text += "  failed: " + sim::describe(f) + "\n";
  add(std::snprintf(line, sizeof line,
                    "  %.3f s simulated in %.3f s wall: %.1fx real time, %llu steps, %.1f %% of the wall time in WTC\n",
                    summary.sim_time, summary.wall_time, summary.real_time_factor,
                    static_cast<unsigned long long>(summary.steps), 100.0 * summary.wtcShare()));
  for (const auto& [key, value] : summary.fields) {
    text += "  " + key;
    add(std::snprintf(line, sizeof line, ": %.4g\n", value));
  }
  text += "  outputs: " + outcome.dir.string() + " (series, summary.json, " +
          (outcome.ruts_file.empty() ? "" : outcome.ruts_file + ", ") + outcome.replay_said + "; figures " +
          outcome.figures + ")\n";
  return text;
}

}  // namespace wtc::apps
