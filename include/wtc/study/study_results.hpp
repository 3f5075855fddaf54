#pragma once
// A study's results (wtc::study): each run read back from its directory and
// measured against its scenario's reference run, the Pareto front of error
// against wall time, and the tables. The same whether the runs were made in
// this process or by a job list on other machines.
#include <filesystem>
#include <map>
#include <optional>
#include <vector>

#include "wtc/sim/scene_run.hpp"
#include "wtc/study/study_plan.hpp"

namespace wtc::study {

/// One run against its reference. Series are compared at the run's
/// recorded instants, the reference interpolated linearly between its own.
struct RunResult {
  const PlannedRun* run = nullptr;
  sim::RunSummary summary;
  /// The first body's centre (the chassis, the tug) against the reference's:
  /// RMS over the run, and at the last instant both reached (m).
  double rms_position_error = 0.0;
  double final_position_error = 0.0;
  /// The largest |pitch| of any body that is not a wheel (deg), and its
  /// difference from the reference's.
  double peak_pitch_deg = 0.0;
  double peak_pitch_error_deg = 0.0;
  /// The largest force on one wheel (N), and the RMS over instants and
  /// wheels of |F - F_ref| (N): what the contact forces do, not only where
  /// the vehicle goes.
  double peak_wheel_force = 0.0;
  double rms_wheel_force_error = 0.0;
  /// The path controller's RMS tracking error (m), where there is one.
  std::optional<double> path_error;
  /// Not beaten on both wall time and RMS position error by another
  /// successful run of the same scenario (failed runs are never on it).
  bool on_front = false;
};

/// Reads every run of `plan` from `out` (runs/<key>/). Throws
/// InvalidInputError naming each run that has not finished.
std::vector<RunResult> gatherResults(const StudyPlan& plan, const std::filesystem::path& out);

/// The builds of wtc-sim that made `results` (RunSummary::program; runs
/// without one are left out), with their run counts. More than one: the
/// figures mix program versions (a run's key covers its settings, not the
/// program), and the tables say so.
std::map<std::string, int> programsOf(const std::vector<RunResult>& results);

/// results.csv: one row per run, every figure (for plots and scripts).
void writeResultsCsv(const std::filesystem::path& file, const std::vector<RunResult>& results);
/// A Markdown table per scenario, fastest run first, the front marked.
void writeResultsMarkdown(const std::filesystem::path& file, const StudyPlan& plan,
                          const std::vector<RunResult>& results);

}  // namespace wtc::study
