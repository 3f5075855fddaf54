#pragma once
// WTC's wheels in the Bullet sim engine (a sim::WheelContacts strategy):
// every wheel link registered with the plugin, which runs its tyre model
// in Bullet's pre-tick and answers for it.
#include <span>

#include "sim/plugin_wheels.hpp"
#include "wheel_links.hpp"
#include "wtc/bullet/plugin.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::bullet {

class WtcWheels final : public sim::PluginWheels<Plugin> {
 public:
  /// Registers wheel k (the k-th of vehicle.wheels(), link links[k]) with
  /// `plugin`, with `effects`, as the plugin's WheelId k.
  WtcWheels(Plugin& plugin, const vehicle::VehicleDescription& vehicle, std::span<const WheelLink> links,
            EffectSet effects);
};

}  // namespace wtc::bullet
