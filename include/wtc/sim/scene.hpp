#pragma once
// A scene (wtc::sim): everything one run needs, engine-free — the engine
// and its settings, the terrain, the vehicle and where it starts, the
// effects, the controller, what to record and how the scene judges its own
// success. wtc::sim::loadScene reads one from YAML (scenes/README.md).
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "wtc/sim/drawbar.hpp"
#include "wtc/sim/engine.hpp"
#include "wtc/sim/tilt_table.hpp"
#include "wtc/tyre/ground_memory.hpp"
#include "wtc/vehicle/controller.hpp"
#include "wtc/vehicle/vehicle_effects.hpp"

namespace wtc::sim {

struct OutputSettings {
  double rate_hz = 100.0;  ///< Rows per simulated second in the CSV series (> 0; at most one per step).
  bool plots = true;       ///< Draw the figures after the run (when matplotlib is installed).
  bool replay = true;      ///< Write the replay page (replay.html, replay_data.js) beside the series.
  double replay_fps = 30;  ///< Frames per simulated second on the replay page (> 0).
};

/// The scene's own criterion; a run succeeds when it ends without a
/// non-finite state and every criterion given holds at its end.
struct SuccessCriteria {
  std::optional<double> min_distance;  ///< The vehicle's first body moved at least this far, horizontally (m).
  std::optional<double> max_distance;  ///< And at most this far (m).
  /// The first body moved at least this far forward: along its own x axis
  /// at the start, projected on the horizontal (m; going back counts
  /// negative, so a vehicle sliding down a grade does not pass).
  std::optional<double> min_advance;
  /// At the end the first body moves at most this fast (m/s, horizontal): it
  /// holds (a parked vehicle that settled), rather than slides.
  std::optional<double> max_final_speed;
  double max_tilt_deg = 45.0;  ///< Every root's z axis within this of the vertical (deg).
  /// At the end every wheel's centre at least this high (world z, m): on top of a ledge.
  std::optional<double> min_wheel_height;
  /// The first body turned at least this far about the vertical, either way
  /// (|yaw change| over the run, deg): a turn in place that turned.
  std::optional<double> min_turn_deg;
};

struct Scene {
  std::string name;
  std::string description;
  std::string source;  ///< The file it came from (for messages and the summary).
  EngineSettings engine;
  double duration_seconds = 0.0;
  std::shared_ptr<const Terrain> terrain;
  /// The ruts the run starts on (scene key ground_memory_from: a file
  /// wtc::io::writeGroundMemoryCsv wrote, as wtc-sim does at a run's end),
  /// over the terrain's soil regions; null: fresh soil.
  std::shared_ptr<const GroundMemory> start_ruts;
  vehicle::VehicleDescription vehicle;
  Eigen::Isometry3d placement{Eigen::Isometry3d::Identity()};  ///< The vehicle frame V in the world.
  /// The vehicle's velocity at the start (m/s, in V), its wheels rolling
  /// (startVelocities); zero: at rest, and the engines are not told.
  Eigen::Vector3d start_velocity_V{Eigen::Vector3d::Zero()};
  std::optional<Drawbar> drawbar;  ///< A drawbar rig pulling the vehicle, if any.
  /// A tilt table turning the ground (gravity) slowly, if any: the run ends
  /// soon after the vehicle tips or slides (tilt_table.hpp).
  std::optional<TiltTable> tilt_table;
  vehicle::VehicleEffects vehicle_effects;
  std::string controller_type;  ///< "none", "schedule", ...
  /// A fresh controller for one run (controllers keep state).
  std::function<std::unique_ptr<vehicle::Controller>()> make_controller;
  OutputSettings output;
  SuccessCriteria success;
  std::map<std::string, double> parameters;  ///< The scene's named numbers, after overrides.
  /// What reading the scene found that the user should hear of (a mesh's
  /// degenerate triangles skipped); a run's summary starts with them.
  std::vector<std::string> warnings;
};

}  // namespace wtc::sim
