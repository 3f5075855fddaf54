#pragma once
// WTC's wheels in the ODE sim engine: every wheel body registered with the
// plugin, which runs its tyre model in beginStep and takes its pairs with
// the terrain in the near callback (handlePair).
#include <span>

#include "ode_wheels.hpp"
#include "sim/plugin_wheels.hpp"
#include "wtc/ode/plugin.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::ode {

class WtcWheels final : public sim::PluginWheels<Plugin, OdeWheels> {
 public:
  /// Registers wheel k (the k-th of vehicle.wheels(), bodies[k]) with
  /// `plugin`, with `effects`, as the plugin's WheelId k; constraint mode's
  /// contact joints go into `contacts`.
  WtcWheels(Plugin& plugin, const vehicle::VehicleDescription& vehicle, std::span<const WheelBody> bodies,
            EffectSet effects, dJointGroupID contacts);

  /// The plugin's wheel-terrain pairs.
  bool collide(dGeomID a, dGeomID b) override { return plugin().handlePair(a, b, contacts_); }

 private:
  dJointGroupID contacts_;
};

}  // namespace wtc::ode
