// wtc-sim: runs one scene file in the engine it names (or the one given),
// writes the series, a summary and the figures. It parses, runs and
// writes; everything physical is in the libraries.
#include <unistd.h>
#include <cstdlib>

#include <CLI/CLI.hpp>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "app_files.hpp"
#include "wtc-sim/run_directory.hpp"
#include "wtc/base/error.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/replay.hpp"
#include "wtc/sim/run_summary_file.hpp"
#include "wtc/sim/scene_file.hpp"
#include "wtc/sim/scene_run.hpp"

namespace {

namespace fs = std::filesystem;

std::atomic<bool> g_stop{false};
extern "C" void onSignal(int) { g_stop = true; }

// A directory for this run that no earlier run used: `requested` if given
// (it must not exist or be empty; with --skip-done, kRedo: the files of
// the unfinished run of the same settings it holds are removed, and
// nothing else: run_directory.hpp), else runs/<scene>_<engine>_<mode>[_N].
// Its marker is written before anything else.
fs::path outputDirectory(const std::string& requested, wtc::apps::SkipDone skip, const std::string& key,
                         const wtc::sim::RunSummary& names, const std::string& scene_file) {
  fs::path dir;
  if (!requested.empty()) {
    dir = requested;
    wtc::apps::requireDirectoryOrNothing(requested);
    if (skip == wtc::apps::SkipDone::kRedo) {
      wtc::apps::removeRunFiles(dir);
    } else if (fs::exists(dir) && !fs::is_empty(dir)) {
      throw wtc::InvalidInputError("--out " + requested +
                                   ": the directory exists and is not empty (an earlier run's?)");
    }
    fs::create_directories(dir);
  } else {
    const std::string base = "runs/" + names.scene + "_" + names.engine + "_" + names.mode;
    dir = base;
    for (int n = 2; fs::exists(dir); ++n) dir = base + "_" + std::to_string(n);
    fs::create_directories(dir);
  }
  wtc::apps::writeMarker(dir, key, scene_file, names.scene, names.engine, names.mode);
  return dir;
}

// The replay page beside the run's data, with three.js copied in so the
// directory can be moved. Returns what went wrong, or "".
std::string writeReplayPage(const fs::path& dir) {
  const fs::path three = WTC_THREE_JS_DIR;
  const fs::path files[][2] = {{wtc::apps::ownFile("wtc-sim", "replay.html"), dir / "replay.html"},
                               {three / "build/three.min.js", dir / "three.min.js"},
                               {three / "examples/js/controls/OrbitControls.js", dir / "OrbitControls.js"}};
  for (const auto& [from, to] : files) {
    std::error_code error;
    fs::copy_file(from, to, fs::copy_options::overwrite_existing, error);
    if (error) return "cannot copy " + from.string() + " (is libjs-three installed?): " + error.message();
  }
  return {};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"wtc-sim: run a scene (scenes/*.yaml) in Bullet or ODE with WTC wheels"};
  std::string scene_file, engine, mode, out;
  double dt = 0.0, duration = 0.0;
  std::vector<std::string> sets, package_path;
  bool quiet = false, no_plots = false, no_replay = false, skip_done = false;
  app.add_option("scene", scene_file, "scene file (YAML)")->required();
  app.add_option("--engine", engine, "bullet, ode or ode_quick (overrides the scene's)");
  app.add_option("--mode", mode,
                 "force or constraint (WTC), engine_cylinder or engine_sphere (the engine's own wheel contact)");
  app.add_option("--dt", dt, "step (s)");
  app.add_option("--duration", duration, "simulated time (s)");
  app.add_option("--out", out, "output directory (new or empty; default runs/<scene>_<engine>_<mode>[_N])");
  app.add_option("--set", sets, "key.path=value: override any value of the scene (repeatable)");
  app.add_option("--package-path", package_path,
                 "folder in which package:// URIs of a URDF vehicle resolve, before WTC_PACKAGE_PATH (repeatable)");
  app.add_flag("--quiet", quiet, "no progress bar, no summary on stdout");
  app.add_flag("--no-plots", no_plots, "skip the figures");
  app.add_flag("--no-replay", no_replay, "skip the replay page (as a scene's output: {replay: false})");
  app.add_flag("--skip-done", skip_done,
               "with --out: do nothing if that directory holds a run of these settings that ended, redo an "
               "unfinished one (job lists: a batch resumes where it stopped); a directory holding anything "
               "but a run of its own (its .wtc-run marker) is refused, and nothing is removed");
  wtc::apps::addVersionFlag(app, "wtc-sim");
  if (const auto status = wtc::apps::parseCommandLine(app, argc, argv)) return *status;
  if (skip_done && out.empty()) {
    std::cerr << "wtc-sim: --skip-done needs --out (the directory that holds the run)\n";
    return 2;
  }

  if (!package_path.empty()) {
    // The vehicle reader takes its package path from WTC_PACKAGE_PATH
    // (wtc/vehicle/package_path.hpp): the folders given here go first.
    std::string path;
    for (const std::string& dir : package_path) path += (path.empty() ? "" : ":") + dir;
    if (const char* env = std::getenv("WTC_PACKAGE_PATH"); env != nullptr && *env != '\0')
      path += ":" + std::string(env);
    setenv("WTC_PACKAGE_PATH", path.c_str(), 1);
  }

  std::vector<wtc::sim::Override> overrides;
  wtc::apps::SkipDone skip = wtc::apps::SkipDone::kRun;
  wtc::sim::Scene scene;
  std::string key;
  try {
    if (!engine.empty()) overrides.push_back({"engine", engine});
    if (!mode.empty()) overrides.push_back({"mode", mode});
    if (app.count("--dt")) overrides.push_back({"dt", wtc::formatNumber(dt)});
    if (app.count("--duration")) overrides.push_back({"duration", wtc::formatNumber(duration)});
    for (const std::string& s : sets) overrides.push_back(wtc::sim::parseOverride(s));
    key = wtc::apps::settingsKey(scene_file, overrides);
    if (skip_done) skip = wtc::apps::skipDone(out, key);
    if (skip == wtc::apps::SkipDone::kSkip) {
      if (!quiet) std::printf("%s: finished earlier, skipped\n", out.c_str());
      return 0;
    }
    scene = wtc::sim::loadScene(scene_file, overrides);
  } catch (const std::exception& e) {
    std::cerr << "wtc-sim: " << e.what() << '\n';
    return 2;
  }

  try {
    const auto engine_ptr = wtc::sim::makeEngine(scene.engine, *scene.terrain, scene.vehicle, scene.placement);
    wtc::sim::RunSummary names;
    names.scene = scene.name;
    names.engine = scene.engine.engine;
    names.mode = std::string(wtc::sim::modeName(scene.engine));
    const fs::path dir = outputDirectory(out, skip, key, names, fs::absolute(scene_file).string());

    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    wtc::sim::RunOptions options;
    options.out_dir = dir;
    options.stop = &g_stop;
    const bool bar = !quiet && isatty(STDERR_FILENO);
    if (bar) {
      options.progress = [](double f) {
        const int filled = static_cast<int>(f * 40.0);
        std::fprintf(stderr, "\r[%-40s] %3d%%", std::string(filled, '#').c_str(), static_cast<int>(f * 100.0));
        std::fflush(stderr);
      };
    }
    // A summary from the start: a run killed before its end (SIGKILL, a
    // power cut) leaves one that says so; the end replaces it whole.
    wtc::sim::writeRunStarted(dir / "summary.json", scene);
    // Said on stderr when it happens, even with --quiet (a warning, not progress).
    options.warn = [bar](const std::string& warning) {
      std::fprintf(stderr, "%swtc-sim: warning: %s\n", bar ? "\n" : "", warning.c_str());
    };
    std::optional<wtc::sim::Replay> replay;
    std::string replay_said = "replay.html";
    if (no_replay || !scene.output.replay) {
      replay_said = no_replay ? "no replay (--no-replay)" : "no replay (output.replay: false)";
    } else {
      replay.emplace(scene, scene.output.replay_fps);
      options.observer = &*replay;
    }
    wtc::sim::RunSummary summary = wtc::sim::runScene(scene, *engine_ptr, options);
    summary.program = wtc::apps::programIdentity();
    if (bar) std::fprintf(stderr, "\n");
    wtc::sim::writeRunSummary(dir / "summary.json", summary);
    if (replay) {
      replay->write(dir / "replay_data.js", summary);
      if (const std::string problem = writeReplayPage(dir); !problem.empty()) {
        std::cerr << "wtc-sim: warning: replay page not written: " << problem << '\n';
      }
    }
    for (const std::string& w : summary.warnings) std::cerr << "wtc-sim: warning: " << w << '\n';

    std::string figures = "skipped (--no-plots)";
    if (!no_plots && scene.output.plots) {
      // The drives on sliding joints: their travel (m) and force (N) get axes of their own.
      std::string prismatic;
      for (const int b : scene.vehicle.actuated()) {
        if (scene.vehicle.bodies[b].joint.type != wtc::vehicle::JointType::kPrismatic) continue;
        prismatic += (prismatic.empty() ? "" : ",") + scene.vehicle.bodies[b].name;
      }
      figures = wtc::apps::runPlotScript(wtc::apps::ownFile("wtc-sim", "plot_run.py"), dir, {"--prismatic", prismatic})
                    ? "drawn"
                    : "not drawn (python3 with matplotlib is needed; see above)";
    }
    if (!quiet) {
      char headline[64] = "success";
      if (summary.interrupted) {
        std::snprintf(headline, sizeof headline, "INTERRUPTED at t = %.3f s", summary.sim_time);
      } else if (!summary.success) {
        std::snprintf(headline, sizeof headline, "FAILED");
      }
      std::printf("%s in %s (%s mode, dt %g s): %s\n", summary.scene.c_str(), summary.engine.c_str(),
                  summary.mode.c_str(), summary.dt, headline);
      for (const wtc::sim::FailedCriterion& f : summary.failed_criteria) {
        std::printf("  failed: %s\n", wtc::sim::describe(f).c_str());
      }
      std::printf("  %.3f s simulated in %.3f s wall: %.1fx real time, %llu steps, %.1f %% of the wall time in WTC\n",
                  summary.sim_time, summary.wall_time, summary.real_time_factor,
                  static_cast<unsigned long long>(summary.steps), 100.0 * summary.wtcShare());
      for (const auto& [key, value] : summary.fields) std::printf("  %s: %.4g\n", key.c_str(), value);
      std::printf("  outputs: %s (series, summary.json, %s; figures %s)\n", dir.c_str(), replay_said.c_str(),
                  figures.c_str());
    }
    return summary.success ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "wtc-sim: " << e.what() << '\n';
    return 2;
  }
}
