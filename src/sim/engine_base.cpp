#include "engine_base.hpp"

#include <utility>

#include "wtc/base/error.hpp"

namespace wtc::sim {

EngineBase::EngineBase(std::string name, const EngineSettings& settings, const vehicle::VehicleDescription& vehicle)
    : Engine(settings, vehicle), name_(std::move(name)), wheel_of_body_(vehicle.bodies.size(), -1) {
  const std::vector<int> wheels = vehicle.wheels();
  for (std::size_t k = 0; k < wheels.size(); ++k) wheel_of_body_[wheels[k]] = static_cast<int>(k);
}

std::size_t EngineBase::wheelIndex(int body) const {
  const int k = wheel_of_body_.at(body);
  if (k < 0) throw InvalidInputError(name_ + ": body " + std::to_string(body) + " is not a wheel");
  return static_cast<std::size_t>(k);
}

void EngineBase::requireOnePerBody(std::size_t count) const {
  if (count != vehicle().bodies.size()) {
    throw InvalidInputError(name_ + ": setVelocities: " + std::to_string(count) + " velocities for " +
                            std::to_string(vehicle().bodies.size()) + " bodies");
  }
}

bool EngineBase::solvesWheelDrive(int body) const {
  constexpr double kParallel = 1e-9;  // |axle x axis| of a wheel on its own axle
  const vehicle::Body& b = vehicle().bodies.at(body);
  return b.wheel && b.joint.actuator && b.joint.type == vehicle::JointType::kRevolute &&
         settings().mode == ContactMode::kForce && !settings().native_wheels &&
         (b.pose.linear() * b.wheel->axle).cross(b.joint.axis).norm() < kParallel;
}

}  // namespace wtc::sim
