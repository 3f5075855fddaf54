#pragma once
// The engine's own wheel contact (EngineSettings::native_wheels: the
// baseline a study compares WTC with) in WTC's terms, so that the
// baseline's wheels reach the sensors, recorders and summaries as WTC's
// do: NativeWheels is the common part of each engine's native-wheels
// strategy. After each step the engine's strategy clears its wheels, adds
// each contact the engine's solver acted on, and finishes them at the
// wheels' centres.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "sim/wheel_contacts.hpp"
#include "wtc/sim/engine.hpp"
#include "wtc/tyre/tyre_model.hpp"
#include "wtc/tyre/wheel_forces.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::sim {

/// What the engine's solver did to one wheel in a step.
class NativeWheelContacts {
 public:
  /// Reserves room for kReservedContacts contacts (no allocation once warm).
  NativeWheelContacts();

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

/// One NativeWheelContacts per wheel body of a vehicle, in body order.
class NativeWheelSet {
 public:
  explicit NativeWheelSet(const vehicle::VehicleDescription& vehicle);

  std::size_t size() const { return wheels_.size(); }
  /// The body of wheel k.
  int body(std::size_t k) const { return bodies_[k]; }
  NativeWheelContacts& operator[](std::size_t k) { return wheels_[k]; }
  const NativeWheelContacts& operator[](std::size_t k) const { return wheels_[k]; }

  void clear();
  /// Finishes every wheel at its centre and axle as `engine` has them now.
  void finish(const Engine& engine);

 private:
  std::vector<NativeWheelContacts> wheels_;
  std::vector<int> bodies_;
};

/// The common part of an engine's native-wheels strategy: the wheels'
/// contacts as the engine's reader left them, no tyre model (so nothing
/// to tell a listener), and as WTC's time the plugin's, which still holds
/// the terrain. `Plugin` has contactSeconds(); `Base` is WheelContacts or
/// an engine's own strategy interface derived from it.
template <class Plugin, class Base = WheelContacts>
class NativeWheels : public Base {
 public:
  const WheelForces& forces(std::size_t k) const final { return wheels_[k].forces(); }
  const WheelState& state(std::size_t k) const final { return wheels_[k].state(); }
  /// The engine's own wheels run no tyre model: nothing to tell.
  void setListener(WheelListener*) final {}
  double contactSeconds() const final { return plugin_.contactSeconds(); }

  NativeWheelShape shape() const { return shape_; }

 protected:
  NativeWheels(const Engine& engine, Plugin& plugin, NativeWheelShape shape)
      : engine_(engine), plugin_(plugin), shape_(shape), wheels_(engine.vehicle()) {}

  const Engine& engine() const { return engine_; }
  Plugin& plugin() const { return plugin_; }
  NativeWheelSet& wheels() { return wheels_; }
  const NativeWheelSet& wheels() const { return wheels_; }

 private:
  const Engine& engine_;
  Plugin& plugin_;
  NativeWheelShape shape_;
  NativeWheelSet wheels_;
};

}  // namespace wtc::sim
