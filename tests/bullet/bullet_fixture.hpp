#pragma once
// A Bullet world with WTC plugged in, and wheel bodies, for the validation
// scenes of the Bullet plugin. Gravity -9.81 m/s^2 along z; the wheel is a
// cylinder (radius r_f, width w) whose axle is its local y axis.
#include <memory>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "wheel_sim.hpp"
#include "wtc/bullet/plugin.hpp"
#include "wtc/bullet/rigid_contact_solver.hpp"
#include "wtc/terrain/terrain.hpp"

namespace wtc::testing {

/// A disc-like wheel body: mass (kg), axial inertia m r^2 / 2, at `centre`.
struct BulletWheel {
  BulletWheel(btDiscreteDynamicsWorld& world, double mass, const btVector3& centre, double free_radius = 0.19,
              double tread_width = 0.12);
  ~BulletWheel();
  btDiscreteDynamicsWorld& world;
  btCylinderShape shape;
  btDefaultMotionState motion;
  std::unique_ptr<btRigidBody> body;
};

/// Members in construction order; the plugin goes first, then the bodies
/// it points at, then the world.
struct BulletWorld {
  explicit BulletWorld(const Terrain& terrain, ContactMode mode);
  /// A wheel body owned by this world.
  BulletWheel& addWheelBody(double mass, const btVector3& centre);
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  bullet::RigidContactSolver solver;  // Bullet's, with implicit mode's tread rows (identical in the other modes)
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
  std::vector<std::unique_ptr<BulletWheel>> bodies;
  std::unique_ptr<bullet::Plugin> plugin;
};

/// Registers `wheel` with the defaults of the robot's wheel; the plugin reads
/// its mass and axial inertia from the body (a free wheel's spin).
bullet::WheelId addWheel(BulletWorld& w, BulletWheel& wheel, EffectSet effects = EffectSet::full(),
                         const TyreParameters& tyre = {});

}  // namespace wtc::testing
