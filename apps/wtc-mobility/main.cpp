// wtc-mobility: what a vehicle can do. Runs the standard mobility events
// (docs/mobility.md) for any vehicle file, in every engine and mode asked
// for, on all cores (wtc::study's worker pool: one wtc-sim process per
// run) or as a job list for GNU parallel or a Slurm array, the searches in
// rounds; writes report.md, report.json and the figures. It parses, runs
// and writes; the events are wtc::mobility.
//
// A program of its own rather than a command of wtc-study: its input is a
// vehicle, not a study file, and its searches choose each run from the
// last one (rounds), which a study's fixed plan of runs does not; it shares
// the study's runner and job lines.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <thread>

#include "app_files.hpp"
#include "wtc/base/error.hpp"
#include "wtc/mobility/mobility_report.hpp"
#include "wtc/mobility/mobility_run.hpp"
#include "wtc/vehicle/vehicle_file.hpp"

namespace {

namespace fs = std::filesystem;

fs::path wtcSim(const std::string& given) {
  if (!given.empty()) return fs::absolute(given);
  const fs::path beside = fs::canonical("/proc/self/exe").parent_path() / "wtc-sim";
  if (!fs::exists(beside)) {
    throw wtc::InvalidInputError("no wtc-sim beside wtc-mobility (" + beside.string() + "): give --wtc-sim");
  }
  return beside;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"wtc-mobility: the mobility events for a vehicle, beside their bounds from mechanics"};
  app.require_subcommand(1);
  std::string vehicle_file, settings_file, out, wtc_sim;
  std::vector<std::string> engines, modes, events;
  int workers = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  bool no_plots = false;
  for (CLI::App* sub : {app.add_subcommand("run", "make the runs, round by round, on --workers processes; report"),
                        app.add_subcommand("jobs",
                                           "write the next round's runs to <out>/jobs.txt (run them, call "
                                           "again until none is left); report what is finished")}) {
    sub->add_option("vehicle", vehicle_file,
                    "vehicle file (YAML; a URDF robot through a vehicle file that names it and its wheels: "
                    "docs/urdf.md)")
        ->required();
    sub->add_option("--settings", settings_file,
                    "settings file (default: every default, apps/wtc-mobility/settings.yaml)");
    sub->add_option("--out", out, "output directory (default mobility/<vehicle name>)");
    sub->add_option("--engine", engines, "engines (default: the settings')");
    sub->add_option("--mode", modes, "modes (default: the settings')");
    sub->add_option("--event", events, "events (default: the settings')");
    sub->add_option("--wtc-sim", wtc_sim, "the wtc-sim that makes the runs (default: the one beside)");
    sub->add_flag("--no-plots", no_plots, "skip the figures");
  }
  app.get_subcommand("run")->add_option("--workers", workers, "simulations at once, at least 1 (default: the cores)");
  wtc::apps::addVersionFlag(app, "wtc-mobility");
  if (const auto status = wtc::apps::parseCommandLine(app, argc, argv)) return *status;
  if (workers < 1) {
    std::cerr << "wtc-mobility: --workers " << workers << ": must be at least 1 (simulations at once)\n";
    return 2;
  }
  try {
    wtc::mobility::MobilitySettings settings;
    if (!settings_file.empty()) settings = wtc::mobility::loadMobilitySettings(settings_file);
    if (!engines.empty()) settings.engines = engines;
    if (!modes.empty()) settings.modes = modes;
    if (!events.empty()) settings.events = events;
    wtc::mobility::validate(settings);
    wtc::mobility::EventVehicle vehicle;
    vehicle.file = fs::absolute(vehicle_file);
    vehicle.description = wtc::vehicle::loadVehicle(vehicle.file);
    vehicle.statics = wtc::mobility::describeStatics(vehicle.description);
    const fs::path dir = out.empty() ? fs::path("mobility") / vehicle.description.name : fs::path(out);
    if (fs::exists(dir) && !fs::is_directory(dir)) {
      throw wtc::InvalidInputError("--out " + dir.string() + ": exists and is not a directory (the report's folder)");
    }
    fs::create_directories(dir);

    wtc::mobility::MobilityOptions options;
    options.out = fs::absolute(dir);
    options.wtc_sim = wtcSim(wtc_sim);
    options.workers = workers;
    options.job_list = app.got_subcommand("jobs");
    options.progress = [](const std::string& line) {
      std::printf("wtc-mobility: %s\n", line.c_str());
      std::fflush(stdout);
    };
    const wtc::mobility::MobilityOutcome outcome = wtc::mobility::runMobility(vehicle, settings, options);
    std::string command = "wtc-mobility";
    for (int i = 1; i < argc; ++i) command += " " + std::string(argv[i]);
    wtc::mobility::writeReport(vehicle, settings, outcome, options.out, command);
    if (outcome.pending_jobs > 0) {
      std::printf(
          "wtc-mobility: %zu runs of the next round in %s; run them (parallel < jobs.txt), then call "
          "again\n",
          outcome.pending_jobs, (dir / "jobs.txt").c_str());
      return 0;
    }
    std::printf("wtc-mobility: %zu runs made; report: %s\n", outcome.runs_made, (dir / "report.md").c_str());
    if (!no_plots && !wtc::apps::runPlotScript(wtc::apps::ownFile("wtc-mobility", "plot_mobility.py"), dir)) {
      std::fprintf(stderr, "wtc-mobility: warning: figures not drawn (python3 with matplotlib is needed)\n");
    }
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "wtc-mobility: " << e.what() << '\n';
    return 2;
  }
}
