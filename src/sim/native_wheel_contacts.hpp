#pragma once
// What an engine's own wheel contact (EngineWheels: the baseline a study
// compares WTC with) did to one wheel in a step, in WTC's terms, so that
// the baseline's wheels reach the sensors, recorders and summaries as WTC's
// do. An engine implementation keeps an EngineWheelSet: after each step it
// clears it, adds each contact the engine's solver acted on, and finishes
// it at the wheels' centres.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "wtc/tyre/tyre_model.hpp"
#include "wtc/tyre/wheel_forces.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::sim {

class EngineWheelContacts {
 public:
  /// Reserves room for kReservedContacts contacts (no allocation once warm).
  EngineWheelContacts();

  void clear();
  /// One contact: the point on the ground (world, m), the ground's normal
  /// there out of the ground (unit), the engine's penetration depth (m,
  /// > 0 when overlapping) and the force the engine applied on the wheel
  /// in the step (impulse / h, N).
  void add(const Eigen::Vector3d& ground_point, const Eigen::Vector3d& normal, double depth,
           const Eigen::Vector3d& force);
  /// The totals about the wheel centre O (world, m) with axle a (unit),
  /// split as WheelForces documents; no rolling moment (the engine has none).
  void finish(const Eigen::Vector3d& centre, const Eigen::Vector3d& axle);

  const WheelForces& forces() const { return forces_; }
  /// A state that never steps: no tread, no counts.
  const WheelState& state() const { return state_; }

 private:
  std::vector<ContactForce> contacts_;
  WheelForces forces_;
  WheelState state_;
};

class Engine;

/// One EngineWheelContacts per wheel body of a vehicle, in body order.
class EngineWheelSet {
 public:
  EngineWheelSet() = default;
  explicit EngineWheelSet(const vehicle::VehicleDescription& vehicle);

  bool empty() const { return wheels_.empty(); }
  std::size_t size() const { return wheels_.size(); }
  /// The body of wheel k.
  int body(std::size_t k) const { return bodies_[k]; }
  EngineWheelContacts& operator[](std::size_t k) { return wheels_[k]; }
  const EngineWheelContacts& operator[](std::size_t k) const { return wheels_[k]; }

  void clear();
  /// Finishes every wheel at its centre and axle as `engine` has them now.
  void finish(const Engine& engine);

 private:
  std::vector<EngineWheelContacts> wheels_;
  std::vector<int> bodies_;
};

}  // namespace wtc::sim
