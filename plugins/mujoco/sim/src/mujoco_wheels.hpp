#pragma once
// How the MuJoCo sim engine's wheels meet the ground (internal to
// wtc::mujoco_sim), chosen once when the engine is built: WTC's wheels
// through wtc::mujoco::Plugin, or MuJoCo's own (the native-wheel baseline:
// the tread geoms collide with the ground geoms, mjcf_model.hpp).
#include <span>

#include "sim/native_wheel_contacts.hpp"
#include "sim/plugin_wheels.hpp"
#include "wtc/mujoco/plugin.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::mujoco {

class MujocoWheels : public sim::WheelContacts {
 public:
  /// Called by the engine after each step with the step's data (contacts,
  /// efc_force): the place to read what MuJoCo did.
  virtual void read(const mjModel& m, const mjData& d) = 0;
};

/// WTC's wheels: wheel k (the k-th of vehicle.wheels()) registered with the
/// plugin as its WheelId k, on MuJoCo body bodies[k].
class WtcWheels final : public sim::PluginWheels<Plugin, MujocoWheels> {
 public:
  WtcWheels(Plugin& plugin, const vehicle::VehicleDescription& vehicle, std::span<const int> bodies, EffectSet effects);
  void read(const mjModel&, const mjData&) override {}
};

/// MuJoCo's own wheels: after each step, the contacts of each wheel's tread
/// geom (treads[k]) and the forces MuJoCo applied at them.
class NativeWheels final : public sim::NativeWheels<Plugin, MujocoWheels> {
 public:
  NativeWheels(const sim::Engine& engine, Plugin& plugin, std::vector<int> treads, sim::NativeWheelShape shape);
  void read(const mjModel& m, const mjData& d) override;

 private:
  std::vector<int> treads_;
};

}  // namespace wtc::mujoco
