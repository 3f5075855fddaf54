#pragma once
// Each mobility event's trial as a normal wtc-sim scene (wtc::mobility):
// the terrain inline (the settings' ground), the vehicle file placed and,
// where the event asks, moving, a schedule (or the vehicle's own climbing
// controller), and the scene's success criteria as the event's pass/fail
// (docs/mobility-bounds.md, "Test rigs"; docs/mobility.md). The engine,
// mode and step are left to the runner's overrides, so one scene file
// serves every engine and mode; a user opens and replays it with wtc-sim.
#include <filesystem>
#include <string>

#include "wtc/mobility/mobility_settings.hpp"
#include "wtc/mobility/vehicle_statics.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::mobility {

/// What the scenes need of a vehicle: its file (absolute) and description.
struct EventVehicle {
  std::filesystem::path file;
  vehicle::VehicleDescription description;
  VehicleStatics statics;
};

/// The value that asks for a held event's tilt table (parked, side_slope:
/// one run, sim::TiltTable) instead of a slope of `value` degrees.
inline constexpr double kTiltTableValue = -1.0;
/// Whether `event` at `value` is a tilt table's run.
inline bool isTiltTable(const std::string& event, double value) {
  return value == kTiltTableValue && (event == "parked" || event == "side_slope");
}

/// The scene's name: <vehicle>_<event>[_<value>], or <vehicle>_<event>_tilt_table.
std::string sceneName(const EventVehicle& v, const std::string& event, double value);

/// The YAML text of `event`'s scene at `value` (step: height m; grade,
/// parked, side_slope: degrees, or kTiltTableValue for the tilt table up
/// to the search's top at TiltSettings::rate_deg_s; drawbar: driving slip
/// i; gap: width m; coast, braking, turn: ignored). Throws InvalidInputError for an unknown
/// event, or one the vehicle cannot do (turn: not skid-steered; every
/// event: no driven wheel).
std::string eventScene(const EventVehicle& v, const std::string& event, double value, const MobilitySettings& settings);

/// Whether the vehicle has a climbing controller of its own (the climb
/// controller accepts it: the six-wheel robot's bodies and drives).
bool hasClimbingController(const vehicle::VehicleDescription& v);

/// Whether the vehicle is skid-steered: every wheel driven, on one track
/// (turning in place applies).
bool isSkidSteered(const VehicleStatics& v);

}  // namespace wtc::mobility
