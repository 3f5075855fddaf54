#pragma once
// The mobility events run (wtc::mobility): every event asked for, in every
// engine and mode asked for, on the study's worker pool (wtc::study::runPlan:
// one wtc-sim process per run) or as a job list (GNU parallel, a Slurm
// array), in rounds: the searches (step, grade, parked, side slope, gap)
// bisect, each round's trial depending on the last; the other events run
// once. Every run goes to <out>/runs/<key>/ with its scene in
// <out>/scenes/; a finished run is read back, never made again, so a batch
// resumes, and a job list is the next round's runs (run them, call again).
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "wtc/mobility/event_scenes.hpp"
#include "wtc/mobility/mobility_bounds.hpp"
#include "wtc/mobility/mobility_settings.hpp"
#include "wtc/sim/run_summary.hpp"

namespace wtc::mobility {

/// One run of a search: its value and whether it passed (and if not, how it failed).
struct Trial {
  double value = 0.0;
  bool passed = false;
  std::string failure;  ///< The scene's failed criteria ("slid", "tipped", ...), empty if it passed.
  std::string run;      ///< Its directory under <out>/runs.
};

/// One event in one engine and mode: what was measured beside its bound.
struct EventResult {
  std::string event, engine, mode;
  std::string quantity;  ///< "tallest step", "DP/W at i = 0.2", ...
  std::string unit;
  std::optional<double> measured;  ///< None: not measured (every run failed, or the event does not apply).
  std::string note;                ///< How it was found ("bisection to 0.01 m", "failed: ...").
  double bound = 0.0;
  std::optional<double> bound_lower;
  std::string governs;
  std::vector<Trial> trials;                 ///< A search's runs in order.
  double slip = -1.0;                        ///< The drawbar's driving slip i (-1 for other events).
  std::optional<double> torque_coefficient;  ///< The drawbar's sum |T| / (r_f W).
};

struct MobilityOutcome {
  std::vector<EventResult> results;  ///< Complete when pending_jobs == 0.
  std::size_t runs_made = 0;         ///< By this call.
  std::size_t pending_jobs = 0;      ///< Job-list mode: runs written to <out>/jobs.txt for the next round.
  VehicleBounds bounds;
};

struct MobilityOptions {
  std::filesystem::path out;
  std::filesystem::path wtc_sim;  ///< The wtc-sim program.
  int workers = 1;
  bool job_list = false;  ///< Write the next round's runs as <out>/jobs.txt instead of running them.
  std::function<void(const std::string&)> progress = {};
};

/// Runs (or lists) every event of settings.events for `vehicle`. Throws
/// InvalidInputError for settings the scenes refuse, before any run.
MobilityOutcome runMobility(const EventVehicle& vehicle, const MobilitySettings& settings,
                            const MobilityOptions& options);

/// Why a run of `event` does not count ("" when it does): crashed,
/// non-finite, diverged, its joints came apart beyond the run's bounds
/// (sim::jointsCameApart), or the scene's failed criteria in the event's
/// words ("slid", "tipped", "stopped short").
std::string trialFailure(const sim::RunSummary& summary, const std::string& event);

/// The event's measured quantity read from a finished run's directory
/// (drawbar: DP/W; coast: deceleration; braking: stopping distance; turn:
/// yaw rate); `torque` receives the drawbar's torque coefficient. Throws
/// InvalidInputError naming the file for a run without its series.
double measureRun(const EventVehicle& vehicle, const std::string& event, const MobilitySettings& settings,
                  const std::filesystem::path& run_dir, double* torque = nullptr);

}  // namespace wtc::mobility
