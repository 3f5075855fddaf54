// wtc.run: a scene run whole, with the outputs wtc-sim writes (the same
// code: apps/runner/run_outputs.hpp), the engine stepping without the GIL.
#include <dlfcn.h>

#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <atomic>
#include <cstdio>

#include "bindings.hpp"
#include "io/content_hash.hpp"
#include "runner/run_outputs.hpp"
#include "signal_watch.hpp"
#include "wtc/base/error.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/run_summary_file.hpp"

namespace wtc::python {
namespace {

namespace fs = std::filesystem;

// This build of the module: FNV-1a of its own file (as wtc-sim records
// its executable's), "" if it cannot be read.
std::string moduleIdentity() {
  static const std::string identity = [] {
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&moduleIdentity), &info) == 0 || info.dli_fname == nullptr) return std::string();
    try {
      return io::fileDigest(info.dli_fname);
    } catch (const InvalidInputError&) {
      return std::string();
    }
  }();
  return identity;
}

}  // namespace

py::dict summaryDict(const sim::RunSummary& s) {
  // summary.json's own text (sim::runSummaryText), read by Python's json:
  // one writer for the file and the dict.
  return py::module_::import("json").attr("loads")(sim::runSummaryText(s));
}

namespace {

// Prints wtc-sim's progress bar on stderr.
void progressBar(double f) {
  const int filled = static_cast<int>(f * 40.0);
  std::fprintf(stderr, "\r[%-40s] %3d%%", std::string(filled, '#').c_str(), static_cast<int>(f * 100.0));
  std::fflush(stderr);
}

void warnOnStderr(const std::string& warning) { std::fprintf(stderr, "wtc: warning: %s\n", warning.c_str()); }

// progress: True (the bar), False or None (nothing), or a callable(fraction).
py::dict run(const LoadedScene& loaded, const std::optional<fs::path>& out, const py::object& progress, bool plots,
             bool replay) {
  const sim::Scene& scene = loaded.scene;
  const auto engine = sim::makeEngine(scene.engine, *scene.terrain, scene.vehicle, scene.placement);
  apps::OutputRequest request;
  request.out = out ? out->string() : std::string();
  request.settings_key = apps::settingsKey(loaded.file, loaded.overrides);
  request.scene_file = fs::absolute(loaded.file);
  request.replay = replay;
  request.plots = plots;
  request.program = moduleIdentity();
  request.warn = warnOnStderr;

  std::atomic<bool> stop{false};
  SignalWatch watch(stop);
  sim::RunOptions options;
  options.stop = &stop;
  options.observer = &watch;
  options.warn = warnOnStderr;
  py::function callback;
  if (PyCallable_Check(progress.ptr())) {
    callback = py::reinterpret_borrow<py::function>(progress);
    options.progress = [&callback](double f) {
      py::gil_scoped_acquire gil;
      callback(f);
    };
  } else if (progress.is(py::bool_(true))) {
    options.progress = progressBar;
    request.on_run_end = [] { std::fprintf(stderr, "\n"); };
  }
  apps::RunOutcome outcome;
  {
    py::gil_scoped_release nogil;
    outcome = apps::runWithOutputs(scene, *engine, request, options);
  }
  watch.raiseIfSignalled();
  py::dict d = summaryDict(outcome.summary);
  d["out"] = outcome.dir;
  d["replay"] = outcome.replay_said;
  d["figures"] = outcome.figures;
  if (!outcome.ruts_file.empty()) d["ground_memory"] = outcome.dir / outcome.ruts_file;
  d["report"] = apps::runReport(outcome);
  return d;
}

}  // namespace

void bindRuns(py::module_& m) {
  m.def("_run", &run, py::arg("scene"), py::arg("out") = py::none(), py::arg("progress") = true,
        py::arg("plots") = true, py::arg("replay") = true,
        "Runs the scene whole and writes wtc-sim's outputs (wtc.run).");
}

}  // namespace wtc::python
