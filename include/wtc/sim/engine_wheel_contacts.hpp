#pragma once
// What an engine's own wheel contact (EngineWheels: the baseline a study
// compares WTC with) did to one wheel in a step, in WTC's terms, so that
// the baseline's wheels reach the sensors, recorders and summaries as WTC's
// do. An engine implementation clears it before a step, adds each contact
// the engine's solver acted on, and finishes it at the wheel centre.
#include <vector>

#include <Eigen/Core>

#include "wtc/tyre_model.hpp"
#include "wtc/wheel_forces.hpp"

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

}  // namespace wtc::sim
