#pragma once
// Scene files (YAML): scenes/README.md has the reference, scenes/*.yaml are
// the shipped ones. In short:
//
//   name: robot_straight
//   parameters: {wheel_rate: 2.0}     # named numbers; "$wheel_rate" anywhere below
//   engine: bullet                    # bullet | ode | ode_quick
//   mode: force                       # force | constraint
//   dt: 0.0004                        # step (s)
//   duration: 5                       # (s)
//   solver_iterations: 50             # optional
//   solver_residual: 1.0e-6           # optional (Bullet)
//   terrain: ../terrains/flat.yaml    # a terrain file, or the file's body inline
//   vehicle: {file: ../vehicles/six_wheel_robot.yaml, translation: [0, 0, 0]}
//   effects: [full]                   # tyre effects and actuator_limits, hitch_damping
//   controller: {type: schedule, schedules: [...]}
//   output: {rate_hz: 100, plots: true}
//   success: {min_distance: 1.0, max_tilt_deg: 45}
//
// Paths are relative to the scene file. Overrides (`--set key.path=value`)
// change the document before it is read: the path's parts are map keys or
// list indices, the value is YAML (numbers, strings, lists); a first part
// that is not a key of the document but a parameter's name sets that
// parameter. Errors are InvalidInputError "<file>:<line>:<col>: <key>: <problem>";
// an error in an override's value names the override instead of a line
// ("scene.yaml: --set dt=-1: dt: must be > 0 s"), and a terrain or vehicle
// file that fails is named at the scene's line and key, then its own
// message ("scene.yaml:4:10: vehicle: /dev/zero: not a regular file ...").
// Files: regular files within wtc/io/file_limits.hpp's caps; no key twice
// in a mapping (docs/bad-input.md).
#include <filesystem>
#include <functional>
#include <span>
#include <string>

#include "wtc/sim/scene.hpp"

namespace wtc::sim {

struct Override {
  std::string path;   ///< "controller.schedules.0.points"
  std::string value;  ///< YAML text: "2.5", "[[0, 0], [1, 2]]"
};

/// "key.path=value" as --set gives it. Throws InvalidInputError naming the
/// text when there is no '=' or the path is empty.
Override parseOverride(const std::string& text);

/// Told the scene's engine settings as soon as they are read, before the
/// terrain and the vehicle are built: a caller that knows the engines
/// passes the engine table's sim::requireEngine, so that a misspelt engine
/// is refused at once, not after a large terrain's load. This reader lies a
/// layer below the table and cannot ask it itself.
using EngineCheck = std::function<void(const EngineSettings& settings)>;

/// Reads, overrides, checks and builds (terrain and vehicle loaded);
/// `check_engine`, if given, judges the engine settings first.
sim::Scene loadScene(const std::filesystem::path& path, std::span<const Override> overrides = {},
                     const EngineCheck& check_engine = {});

}  // namespace wtc::sim
