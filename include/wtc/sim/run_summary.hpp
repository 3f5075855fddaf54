#pragma once
// What a run of a scene came to (wtc::sim): runScene's result, written to
// summary.json (run_summary_file.hpp) and read back by the study.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "wtc/sim/sim_constants.hpp"

namespace wtc::sim {

struct DriveSummary {
  std::string name;
  std::string joint;                  ///< "revolute" (efforts in N m, travel in rad) or "prismatic" (N, m).
  std::uint64_t steps = 0;            ///< Steps with the drive on.
  std::uint64_t saturated_steps = 0;  ///< Of those, steps at a limit.
  double peak_effort = 0.0;           ///< (N m or N).
  double mean_effort = 0.0;           ///< Mean |effort| over the steps with the drive on (N m or N).
};

/// Why a run is not a success: a criterion of its scene it missed, or what
/// happened to it. Each run that did not succeed has at least one.
struct FailedCriterion {
  /// The scene's success key (min_distance, max_distance, max_tilt_deg,
  /// min_wheel_height) or what the run did: nan, diverged, interrupted
  /// (stopped, or killed, before its duration), crashed (its process died),
  /// controller (the controller failed), energy (the vehicle's energy grew
  /// without a source: EnergyBalance), bounds (a body's centre left the
  /// terrain's box).
  std::string criterion;
  std::optional<double> limit;     ///< In `unit`; none where there is no number (nan, controller).
  std::optional<double> measured;  ///< What the run had, in `unit`.
  std::string unit;                ///< "m", "deg", "s" or "J"; empty without numbers.
  std::string detail;              ///< In words: when, which body, the controller's reason.
};

/// One line: "min_distance: 1.2 m (limit 3 m)", then the detail.
std::string describe(const FailedCriterion& failed);

struct RunSummary {
  std::string scene, engine, mode;
  /// Which build of the program made the run (wtc-sim: FNV-1a of its own
  /// executable, 16 hex digits); empty when unknown. A study's run key
  /// covers the settings, not the program: wtc::study warns when the runs
  /// it gathers come from different builds.
  std::string program;
  double dt = 0.0, sim_time = 0.0;
  double wall_time = 0.0;         ///< Of the stepping loop, recording included (s).
  double real_time_factor = 0.0;  ///< sim_time / wall_time.
  /// Of wall_time, the time WTC's plugin took (Engine::contactSeconds):
  /// finding the contacts, the tyre model, reading and writing the wheels
  /// (s); wtc_time / wall_time is WTC's share of the run.
  double wtc_time = 0.0;
  double wtcShare() const { return wall_time > 0.0 ? wtc_time / wall_time : 0.0; }
  std::uint64_t steps = 0;
  bool success = false;
  /// Why it did not succeed (empty for a success).
  std::vector<FailedCriterion> failed_criteria;
  bool nan = false;          ///< A body state went non-finite (the run stopped there).
  bool diverged = false;     ///< A body went beyond Run::diverged's bounds (the run stopped there).
  bool interrupted = false;  ///< Stopped on request (RunOptions::stop) before its duration.
  /// Its process died (a signal: an engine's assertion); written by a
  /// study's runner over the summary the run left (wtc::study::runPlan).
  bool crashed = false;
  double max_penetration = 0.0;        ///< The deepest tyre deflection Z of any contact (m).
  double max_joint_gap = 0.0;          ///< (m), vehicle::jointError over the run.
  double max_joint_angle = 0.0;        ///< (rad).
  std::uint64_t saturation_steps = 0;  ///< Summed over the drives.
  std::vector<DriveSummary> drives;
  std::vector<std::string> warnings;
  /// The largest slip ratio each wheel had in contact while its centre
  /// moved at 0.1 m/s or more, by wheel name.
  std::map<std::string, double> wheel_peak_slip;
  /// The scene's own figures: distance_m (horizontal, first body),
  /// final_speed_mps, yaw_change_deg, max_tilt_deg; with a hitch,
  /// hitch_force_peak_N (horizontal) and hitch_force_mean_x_N (along the
  /// tug, positive pulling); on ground that remembers,
  /// soil_memory_touched_nodes and soil_memory_bytes (GroundMemory at the
  /// end); and the controller's (Controller::summarize).
  std::map<std::string, double> fields;
  std::map<std::string, double> parameters;  ///< The scene's, after overrides.
};

/// Whether the run's joints came apart beyond the bounds of
/// sim_constants.hpp (kJointGapBoundM, kJointAngleBoundRad).
inline bool jointsCameApart(const RunSummary& summary) {
  return summary.max_joint_gap > kJointGapBoundM || summary.max_joint_angle > kJointAngleBoundRad;
}

}  // namespace wtc::sim
