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
#include "runner/run_outputs.hpp"
#include "vehicle/controllers/controller_types.hpp"
#include "wtc-sim/run_directory.hpp"
#include "wtc/base/error.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/scene_file.hpp"
#include "wtc/sim/scene_run.hpp"

namespace {

namespace fs = std::filesystem;

std::atomic<bool> g_stop{false};
extern "C" void onSignal(int) { g_stop = true; }

// `controller: {type: python, ...}` (the Python package's, docs/python.md):
// wtc-sim has no Python to run it in, and says where to run it instead.
wtc::vehicle::ControllerFactory refusePythonController(const wtc::io::detail::YamlReader& in, const YAML::Node& node,
                                                       const wtc::vehicle::VehicleDescription& /*vehicle*/) {
  in.fail(node,
          "controller: type python is a controller written in Python, which wtc-sim cannot run; run the "
          "scene from Python: python3 -m wtc run " +
              in.path().string() + " (docs/python.md)");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"wtc-sim: run a scene (scenes/*.yaml) in any engine of the table (" + wtc::sim::engineNameList() +
               ") with WTC wheels"};
  std::string scene_file, engine, mode, out;
  double dt = 0.0, duration = 0.0;
  std::vector<std::string> sets, package_path;
  bool quiet = false, no_plots = false, no_replay = false, skip_done = false;
  app.add_option("scene", scene_file, "scene file (YAML)")->required();
  app.add_option("--engine", engine, wtc::sim::engineNameList() + " (overrides the scene's)");
  app.add_option("--mode", mode,
                 "force, constraint or implicit (WTC), engine_cylinder or engine_sphere (the engine's own wheel contact)");
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

  wtc::vehicle::addControllerType({"python", &refusePythonController});
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
    scene = wtc::sim::loadScene(scene_file, overrides, wtc::sim::requireEngine);
  } catch (const std::exception& e) {
    std::cerr << "wtc-sim: " << e.what() << '\n';
    return 2;
  }

  try {
    const auto engine_ptr = wtc::sim::makeEngine(scene.engine, *scene.terrain, scene.vehicle, scene.placement);
    wtc::apps::OutputRequest request;
    request.out = out;
    request.skip = skip;
    request.settings_key = key;
    request.scene_file = fs::absolute(scene_file);
    request.replay = !no_replay;
    request.plots = !no_plots;
    request.program = wtc::apps::programIdentity();

    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    wtc::sim::RunOptions options;
    options.stop = &g_stop;
    const bool bar = !quiet && isatty(STDERR_FILENO);
    if (bar) {
      options.progress = [](double f) {
        const int filled = static_cast<int>(f * 40.0);
        std::fprintf(stderr, "\r[%-40s] %3d%%", std::string(filled, '#').c_str(), static_cast<int>(f * 100.0));
        std::fflush(stderr);
      };
      request.on_run_end = [] { std::fprintf(stderr, "\n"); };
    }
    // Said on stderr when it happens, even with --quiet (a warning, not progress).
    options.warn = [bar](const std::string& warning) {
      std::fprintf(stderr, "%swtc-sim: warning: %s\n", bar ? "\n" : "", warning.c_str());
    };
    request.warn = [](const std::string& warning) { std::cerr << "wtc-sim: warning: " << warning << '\n'; };
    const wtc::apps::RunOutcome outcome = wtc::apps::runWithOutputs(scene, *engine_ptr, request, options);
    if (!quiet) std::fputs(wtc::apps::runReport(outcome).c_str(), stdout);
    return outcome.summary.success ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "wtc-sim: " << e.what() << '\n';
    return 2;
  }
}
