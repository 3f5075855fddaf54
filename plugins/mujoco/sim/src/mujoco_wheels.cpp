// The MuJoCo sim engine's wheel strategies (mujoco_wheels.hpp).
#include "mujoco_wheels.hpp"

#include <algorithm>

#include "src/conversions.hpp"

namespace wtc::mujoco {

WtcWheels::WtcWheels(Plugin& plugin, const vehicle::VehicleDescription& vehicle, std::span<const int> bodies,
                     EffectSet effects)
    : PluginWheels(plugin) {
  const std::vector<int> wheels = vehicle.wheels();
  for (std::size_t k = 0; k < wheels.size(); ++k) {
    const vehicle::Body& body = vehicle.bodies[wheels[k]];
    Wheel wheel;
    wheel.body = bodies[k];
    wheel.axle_local = body.wheel->axle;  // the body frame is its centre-of-mass frame, the wheel's centre
    wheel.description = sim::wheelDescription(body);
    wheel.effects = effects;
    wheel.inertia_source = InertiaSource::kDescription;  // the description is the one source of its inertia
    plugin.addWheel(wheel);
  }
}

NativeWheels::NativeWheels(const sim::Engine& engine, Plugin& plugin, std::vector<int> treads,
                           sim::NativeWheelShape shape)
    : sim::NativeWheels<Plugin, MujocoWheels>(engine, plugin, shape), treads_(std::move(treads)) {}

void NativeWheels::read(const mjModel& m, const mjData& d) {
  wheels().clear();
  for (int i = 0; i < d.ncon; ++i) {
    const mjContact& c = d.contact[i];
    if (c.efc_address < 0) continue;
    const auto wheel_of = [&](int geom) {
      const auto it = std::find(treads_.begin(), treads_.end(), geom);
      return it == treads_.end() ? -1 : static_cast<int>(it - treads_.begin());
    };
    const int as_second = wheel_of(c.geom2), as_first = wheel_of(c.geom1);
    const int k = as_second >= 0 ? as_second : as_first;
    if (k < 0) continue;
    // MuJoCo's frame: its normal from geom1 to geom2, the force in it on
    // geom2. Out of the ground, and on the wheel:
    const Eigen::Vector3d n = vec3(c.frame);
    const double sign = as_second >= 0 ? 1.0 : -1.0;
    mjtNum local[6];
    mj_contactForce(&m, &d, i, local);
    const Eigen::Vector3d force = sign * (mat3(c.frame).transpose() * vec3(local));
    const Eigen::Vector3d out = sign * n;
    // pos is midway between the surfaces, dist apart along the normal.
    const Eigen::Vector3d ground_point = vec3(c.pos) - out * (0.5 * c.dist);
    wheels()[static_cast<std::size_t>(k)].add(ground_point, out, -c.dist, force);
  }
  wheels().finish(engine());
}

}  // namespace wtc::mujoco
