#include "wtc/sim/engine.hpp"

#include <cmath>
#include <utility>

#include "wtc/base/error.hpp"
#include "wtc/tyre/traction_law.hpp"

namespace wtc::sim {

std::string_view modeName(const EngineSettings& settings) {
  if (!settings.native_wheels) return contactModeName(settings.mode);
  switch (*settings.native_wheels) {
    case NativeWheelShape::kCylinder:
      return "engine_cylinder";
    case NativeWheelShape::kSphere:
      return "engine_sphere";
  }
  return "?";
}

void parseMode(std::string_view name, EngineSettings& settings, const std::string& where) {
  static constexpr std::pair<std::string_view, std::pair<ContactMode, std::optional<NativeWheelShape>>> kModes[] = {
      {"force", {ContactMode::kForce, std::nullopt}},
      {"constraint", {ContactMode::kConstraint, std::nullopt}},
      {"implicit", {ContactMode::kImplicit, std::nullopt}},
      {"engine_cylinder", {ContactMode::kForce, NativeWheelShape::kCylinder}},
      {"engine_sphere", {ContactMode::kForce, NativeWheelShape::kSphere}}};
  for (const auto& [mode_name, mode] : kModes) {
    if (name != mode_name) continue;
    settings.mode = mode.first;
    settings.native_wheels = mode.second;
    return;
  }
  throw InvalidInputError(where + ": '" + std::string(name) +
                          "' (expected force, constraint, implicit, engine_cylinder or engine_sphere)");
}

std::vector<double> nativeWheelFrictions(const Terrain& terrain) {
  std::vector<double> mu;
  for (const Material& m : terrain.materials()) mu.push_back(tractionPeak(m));
  return mu;
}

bool treadIsSphere(const EngineSettings& settings, const WheelGeometry& geometry) {
  return settings.native_wheels == NativeWheelShape::kSphere || geometry.tread_width >= 2.0 * geometry.free_radius;
}

void validate(const EngineSettings& settings, const std::string& where) {
  if (!std::isfinite(settings.step_seconds) || settings.step_seconds <= 0.0) {
    throw InvalidInputError(where + ": step " + formatNumber(settings.step_seconds) + " s must be finite and > 0");
  }
  if (settings.solver_iterations <= 0) {
    throw InvalidInputError(where + ": solver_iterations " + std::to_string(settings.solver_iterations) +
                            " must be > 0");
  }
  if (!std::isfinite(settings.solver_residual) || settings.solver_residual <= 0.0) {
    throw InvalidInputError(where + ": solver_residual " + formatNumber(settings.solver_residual) +
                            " (m/s)^2 must be finite and > 0");
  }
}

Eigen::Isometry3d startPose(const vehicle::VehicleDescription& vehicle, int body, const Eigen::Isometry3d& placement) {
  return placement * vehicle.bodies[body].pose;
}

WheelDescription wheelDescription(const vehicle::Body& body) {
  WheelDescription w;
  w.geometry = body.wheel->geometry;
  w.tyre = body.wheel->tyre;
  // A drive on the wheel's joint is an engine velocity motor: it holds the
  // spin to the carrier, and the contact moves the carrier too.
  const bool held = body.joint.actuator.has_value();
  w.inertia = bodyInertia(body.mass, body.inertia.asDiagonal(), body.wheel->axle, held, "wtc::sim: wheel body");
  return w;
}

}  // namespace wtc::sim
