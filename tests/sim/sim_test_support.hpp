#pragma once
// What the sim tests share: the shipped vehicles, a flat ground, and the
// engine settings every test runs in.
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "wtc/sim/engine.hpp"
#include "wtc/sim/scene_file.hpp"
#include "wtc/terrain/terrain.hpp"

namespace wtc::sim {

/// "bullet force": how GoogleTest prints a test's engine settings.
void PrintTo(const EngineSettings& settings, std::ostream* out);

}  // namespace wtc::sim

namespace wtc::testing {

vehicle::VehicleDescription shippedVehicle(const std::string& file);  // under vehicles/
/// A 20 m x 20 m slab, top face z = 0, one material (mu_max 0.8).
Terrain flatGround();
/// Whether a list of engines takes the engines' variants (<engine>_<variant>,
/// src/sim/engine_entry.hpp: ODE's ode_quick) too.
enum class Variants { kIncluded, kLeftOut };
/// The engine table's names (sim::engineNames), with or without variants.
std::vector<std::string> everyEngineName(Variants variants = Variants::kIncluded);
/// Every engine of the engine table, in every WTC contact mode it serves
/// (sim::servesWheels): what a vehicle must run in.
std::vector<sim::EngineSettings> everyEngine(Variants variants = Variants::kIncluded);
/// everyEngine's engines and modes by name, as a scene's overrides take them
/// ({"bullet", "force"}, ...).
std::vector<std::pair<std::string, std::string>> everyEngineByName(Variants variants = Variants::kIncluded);
/// Every engine of the table with its own wheel contact
/// (EngineSettings::native_wheels), cylinder and sphere.
std::vector<sim::EngineSettings> everyNativeWheelBaseline();
std::string label(const sim::EngineSettings& settings);

/// The step the scene tests run implicit mode at (s): five times the
/// shipped scenes' 0.4 ms, for a fifth of the cost. Implicit mode is stable
/// at any step and tends to force mode as it shrinks (docs/tyre-model.md);
/// at this step it meets the tolerances the other modes meet at 0.4 ms.
inline constexpr const char* kImplicitModeStep = "0.002";
/// `overrides`, with dt = kImplicitModeStep after them when they set mode
/// implicit.
std::vector<sim::Override> atImplicitModeStep(std::vector<sim::Override> overrides);

}  // namespace wtc::testing
