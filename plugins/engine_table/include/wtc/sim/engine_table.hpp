#pragma once
// The engine table (wtc::sim_engines): every engine built into this WTC, by
// the name scenes give it, each registered from its own folder
// (plugins/<engine>, declared once with wtc_add_engine), so that the
// runner, the study, the tests and the benchmarks need not know them.
// docs/architecture.md ("Engines"): what an engine adds.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Geometry>

#include "wtc/sim/engine.hpp"

namespace wtc::sim {

/// The names of the engines built in, in the order plugins/CMakeLists.txt
/// declares them: "bullet", "ode", "ode_quick".
std::vector<std::string_view> engineNames();
/// The same as words: "bullet, ode, ode_quick or mujoco" (messages, help).
std::string engineNameList();

/// Whether the table has settings.engine and that engine serves the
/// settings' wheel contact: its WTC contact mode (an engine may serve only
/// some: MuJoCo's friction rows cannot take implicit mode's tread), or its
/// own wheels (every engine serves them).
bool servesWheels(const EngineSettings& settings);

/// Throws InvalidInputError "<settings.engine_where>: unknown engine
/// 'physx' (expected bullet, ode or ode_quick)" unless the table has
/// settings.engine, and "<settings.engine_where>: engine 'mujoco' does not
/// serve contact mode implicit (<why>); it serves force or constraint"
/// unless it serves the settings' wheels (servesWheels).
void requireEngine(const EngineSettings& settings);

/// Builds `vehicle` on `terrain` (which must outlive the engine) in the
/// engine settings.engine names, its frame placed at `placement`. Throws
/// InvalidInputError for a name the table does not have (requireEngine)
/// and for settings or a vehicle the engine refuses.
std::unique_ptr<Engine> makeEngine(const EngineSettings& settings, const Terrain& terrain,
                                   const vehicle::VehicleDescription& vehicle, const Eigen::Isometry3d& placement);

}  // namespace wtc::sim
