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

}  // namespace wtc::sim
