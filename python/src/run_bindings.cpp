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
  py::dict d;
  d["scene"] = s.scene;
  d["engine"] = s.engine;
  d["mode"] = s.mode;
  d["dt"] = s.dt;
  d["success"] = s.success;
  d["interrupted"] = s.interrupted;
  d["nan"] = s.nan;
  d["diverged"] = s.diverged;
  d["steps"] = s.steps;
  d["sim_time"] = s.sim_time;
  d["wall_time"] = s.wall_time;
  d["wtc_time"] = s.wtc_time;
  d["real_time_factor"] = s.real_time_factor;
  d["max_penetration"] = s.max_penetration;
  d["max_joint_gap"] = s.max_joint_gap;
  d["max_joint_angle"] = s.max_joint_angle;
  d["saturation_steps"] = s.saturation_steps;
  d["fields"] = s.fields;
  d["parameters"] = s.parameters;
  d["wheel_peak_slip"] = s.wheel_peak_slip;
  d["warnings"] = s.warnings;
  py::list failed;
  for (const sim::FailedCriterion& f : s.failed_criteria) failed.append(sim::describe(f));
  d["failed"] = failed;
  py::list drives;
  for (const auto& dr : s.drives) {
    py::dict one;
    one["name"] = dr.name;
    one["steps"] = dr.steps;
    one["saturated_steps"] = dr.saturated_steps;
    one["peak_effort"] = dr.peak_effort;
    one["mean_effort"] = dr.mean_effort;
    drives.append(one);
  }
  d["drives"] = drives;
  d["program"] = s.program;
  return d;
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
  return d;
}

}  // namespace

void bindRuns(py::module_& m) {
  m.def("_run", &run, py::arg("scene"), py::arg("out") = py::none(), py::arg("progress") = true,
        py::arg("plots") = true, py::arg("replay") = true,
        "Runs the scene whole and writes wtc-sim's outputs (wtc.run).");
}

}  // namespace wtc::python
