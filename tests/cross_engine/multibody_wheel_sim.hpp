#pragma once
// The robot's wheel (r_f = 0.19 m, w = 0.12 m) as link 0 of a btMultiBody:
// a 3.7 kg wheel on a revolute joint about y at the centre of a floating
// base, 21 kg on one contact in all, in Bullet's multibody solver, with a
// WTC plugin in the given mode. The multibody's own velocity damping (0.04
// by default) is off: it is the body's, not the contact row's.
#include <memory>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <btBulletDynamicsCommon.h>

#include "wheel_sim.hpp"
#include "wtc/bullet/contact_solver.hpp"
#include "wtc/bullet/plugin.hpp"

namespace wtc::testing {

struct MultiBodyWheelSim {
  static constexpr double kRadius = 0.19, kWidth = 0.12;                                   // r_f, tread width (m)
  static constexpr double kMass = 21.0, kWheelMass = 3.7, kBaseMass = kMass - kWheelMass;  // kg

  /// The base's principal moments of inertia (kg m^2): 1 by default; a huge
  /// one keeps the base from turning, so that the tread point's velocity is
  /// the base's and the spin's alone.
  MultiBodyWheelSim(const Terrain& terrain, double height, const TyreParameters& tyre,
                    ContactMode mode = ContactMode::kConstraint, double base_inertia = 1.0) {
    world.setGravity(btVector3(0, 0, -kGravityMps2));
    const double across = 0.25 * kWheelMass * kRadius * kRadius + kWheelMass * kWidth * kWidth / 12;
    const btVector3 inertia(across, 0.5 * kWheelMass * kRadius * kRadius, across);
    multibody =
        std::make_unique<btMultiBody>(1, kBaseMass, btVector3(base_inertia, base_inertia, base_inertia), false, false);
    multibody->setBasePos(btVector3(0, 0, height));
    multibody->setupRevolute(0, kWheelMass, inertia, -1, btQuaternion::getIdentity(), btVector3(0, 1, 0),
                             btVector3(0, 0, 0), btVector3(0, 0, 0), true);
    multibody->finalizeMultiDof();
    multibody->setLinearDamping(0.0);
    multibody->setAngularDamping(0.0);
    world.addMultiBody(multibody.get());
    collider = std::make_unique<btMultiBodyLinkCollider>(multibody.get(), 0);
    collider->setCollisionShape(&shape);
    collider->setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(0, 0, height)));
    world.addCollisionObject(collider.get(), btBroadphaseProxy::DefaultFilter, btBroadphaseProxy::AllFilter);
    multibody->getLink(0).m_collider = collider.get();
    plugin = std::make_unique<bullet::Plugin>(world, terrain, mode);
    bullet::MultiBodyWheel spec;
    spec.multibody = multibody.get();
    spec.link = 0;
    spec.description.inertia = {kWheelMass, inertia.y()};
    spec.description.tyre = tyre;
    plugin->addWheel(spec);
  }
  ~MultiBodyWheelSim() {
    plugin.reset();
    world.removeCollisionObject(collider.get());
    world.removeMultiBody(multibody.get());
  }
  MultiBodyWheelSim(const MultiBodyWheelSim&) = delete;
  MultiBodyWheelSim& operator=(const MultiBodyWheelSim&) = delete;

  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  bullet::ContactSolver solver;  // as btMultiBodyConstraintSolver, with implicit mode's bounds
  btMultiBodyDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
  btCylinderShape shape{btVector3(kRadius, 0.5 * kWidth, kRadius)};
  std::unique_ptr<btMultiBody> multibody;
  std::unique_ptr<btMultiBodyLinkCollider> collider;
  std::unique_ptr<bullet::Plugin> plugin;
};

}  // namespace wtc::testing
