#include "wtc_wheels.hpp"

#include <vector>

#include "wtc/sim/engine.hpp"

namespace wtc::ode {

WtcWheels::WtcWheels(Plugin& plugin, const vehicle::VehicleDescription& vehicle, std::span<const WheelBody> bodies,
                     EffectSet effects, dJointGroupID contacts)
    : PluginWheels(plugin), contacts_(contacts) {
  const std::vector<int> wheels = vehicle.wheels();
  for (std::size_t k = 0; k < wheels.size(); ++k) {
    const vehicle::Body& body = vehicle.bodies[wheels[k]];
    RigidWheel wheel;
    wheel.body = bodies[k].body;
    wheel.geom = bodies[k].geom;
    wheel.axle_local = body.wheel->axle;
    wheel.description = sim::wheelDescription(body);
    wheel.effects = effects;
    wheel.inertia_source = InertiaSource::kDescription;  // the description is the one source of its inertia
    plugin.addWheel(wheel);
  }
}

}  // namespace wtc::ode
