#pragma once
// What every sim engine does alike (internal to wtc::sim and the engines):
// the wheel bodies numbered as the vehicle's wheels(), and the wheels'
// reports answered by the engine's WheelContacts strategy (WTC's wheels
// through its plugin, or its own), chosen once in the engine's constructor.
// An engine derives from EngineBase instead of Engine and implements the
// bodies, joints, motors and the step.
#include <cstddef>
#include <string>
#include <vector>

#include "sim/wheel_contacts.hpp"
#include "wtc/sim/engine.hpp"

namespace wtc::sim {

class EngineBase : public Engine {
 public:
  const WheelForces& wheelForces(int body) const final { return wheels_->forces(wheelIndex(body)); }
  const WheelState& wheelState(int body) const final { return wheels_->state(wheelIndex(body)); }
  void setWheelListener(WheelListener* listener) final { wheels_->setListener(listener); }
  double contactSeconds() const final { return wheels_->contactSeconds(); }

 protected:
  /// `name` starts the messages about bodies ("wtc::bullet sim engine").
  EngineBase(std::string name, const EngineSettings& settings, const vehicle::VehicleDescription& vehicle);

  /// The engine's wheel strategy, once, in its constructor; it must outlive
  /// every call above (the engine owns it).
  void useWheels(WheelContacts& wheels) { wheels_ = &wheels; }

  /// The index k in vehicle().wheels() of wheel body `body`. Throws
  /// InvalidInputError for a body that is not a wheel, std::out_of_range
  /// for one the vehicle does not have.
  std::size_t wheelIndex(int body) const;

  /// Throws InvalidInputError unless `count` velocities are one per body
  /// (setVelocities).
  void requireOnePerBody(std::size_t count) const;

  /// Whether the drive of body `body` is a wheel's that the engine solves
  /// in closed form (vehicle::wheelDriveTorque) instead of as a row of its
  /// solver: force mode with WTC's wheels (the tyre's torque is on the wheel
  /// before the step, and the solver adds no contact to it), a revolute
  /// joint about the wheel's own axle. One rule for every engine.
  bool solvesWheelDrive(int body) const;

 private:
  std::string name_;
  std::vector<int> wheel_of_body_;  // per body: its index in vehicle().wheels(), or -1
  WheelContacts* wheels_ = nullptr;
};

}  // namespace wtc::sim
