#include "wtc_wheels.hpp"

#include <vector>

#include "src/conversions.hpp"
#include "wtc/sim/engine.hpp"

namespace wtc::bullet {

WtcWheels::WtcWheels(Plugin& plugin, const vehicle::VehicleDescription& vehicle, std::span<const WheelLink> links,
                     EffectSet effects)
    : PluginWheels(plugin) {
  const std::vector<int> bodies = vehicle.wheels();
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const vehicle::Body& body = vehicle.bodies[bodies[k]];
    MultiBodyWheel wheel;
    wheel.multibody = links[k].multibody;
    wheel.link = links[k].link;
    wheel.axle_local = toBt(body.wheel->axle);
    wheel.description = sim::wheelDescription(body);
    wheel.effects = effects;
    wheel.inertia_source = InertiaSource::kDescription;  // the description is the one source of its inertia
    plugin.addWheel(wheel);
  }
}

}  // namespace wtc::bullet
