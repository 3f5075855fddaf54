#include "bullet_fixture.hpp"

#include "wtc/terrain/terrain_primitives.hpp"

namespace wtc::testing {

BulletWorld::BulletWorld(const Terrain& terrain, ContactMode mode) {
  world.setGravity(btVector3(0, 0, -kGravityMps2));
  plugin = std::make_unique<bullet::Plugin>(world, terrain, mode);
}

BulletWheel& BulletWorld::addWheelBody(double mass, const btVector3& centre) {
  bodies.push_back(std::make_unique<BulletWheel>(world, mass, centre));
  return *bodies.back();
}

BulletWheel::BulletWheel(btDiscreteDynamicsWorld& w, double mass, const btVector3& centre, double r, double width)
    : world(w), shape(btVector3(r, 0.5 * width, r)), motion(btTransform(btQuaternion::getIdentity(), centre)) {
  const btVector3 inertia(0.25 * mass * r * r + mass * width * width / 12, 0.5 * mass * r * r,
                          0.25 * mass * r * r + mass * width * width / 12);
  body = std::make_unique<btRigidBody>(btRigidBody::btRigidBodyConstructionInfo(mass, &motion, &shape, inertia));
  world.addRigidBody(body.get());
}

BulletWheel::~BulletWheel() { world.removeRigidBody(body.get()); }

bullet::WheelId addWheel(BulletWorld& w, BulletWheel& wheel, EffectSet effects, const TyreParameters& tyre) {
  bullet::RigidWheel spec;
  spec.body = wheel.body.get();
  spec.description.tyre = tyre;
  spec.effects = effects;
  return w.plugin->addWheel(spec);
}

}  // namespace wtc::testing
