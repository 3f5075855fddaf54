#pragma once
// Bullet's own wheels in the Bullet sim engine (a sim::WheelContacts
// strategy, the native-wheel baseline): the wheel links keep their
// collision shapes (cylinder or sphere, NativeWheelShape) against the
// terrain's hulls, with Bullet's contact and the Coulomb friction of the
// piece's mu; after each step the impulses Bullet's solver applied there
// are read back as the wheels' forces.
#include <span>
#include <vector>

#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>

#include "sim/native_wheel_contacts.hpp"
#include "wheel_links.hpp"
#include "wtc/bullet/plugin.hpp"

namespace wtc::bullet {

// What a native wheel's contact needs to know of the ground (the wheel
// collider's user pointer): the Coulomb coefficient of each material.
struct NativeWheelGround {
  const TerrainObject* terrain = nullptr;
  std::vector<double> mu;  // per material id
};

class NativeWheels final : public sim::NativeWheels<Plugin> {
 public:
  /// Flags wheel k's collider (links[k]) for the friction of the piece it
  /// meets; `terrain` is the plugin's.
  NativeWheels(const sim::Engine& engine, Plugin& plugin, btMultiBodyDynamicsWorld& world, const Terrain& terrain,
               std::span<const WheelLink> links, sim::NativeWheelShape shape);

  /// What Bullet's solver did at each wheel-terrain point of the step.
  void stepped() override;

 private:
  // The wheel whose collider is `collider`, or -1.
  int wheelOf(const btMultiBodyLinkCollider* collider) const;

  btMultiBodyDynamicsWorld& world_;
  std::vector<const btMultiBodyLinkCollider*> colliders_;  // per wheel
  NativeWheelGround ground_;                               // the wheels' colliders point here
};

}  // namespace wtc::bullet
