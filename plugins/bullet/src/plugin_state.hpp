#pragma once
// The state behind wtc::bullet::Plugin, shared with its collision algorithm
// and its sim engine (internal to wtc::bullet and wtc::bullet_sim).
#include <memory>
#include <unordered_map>
#include <vector>

#include <BulletDynamics/Featherstone/btMultiBody.h>

#include "adapter/mounted_wheel.hpp"
#include "adapter/step_clock.hpp"
#include "conversions.hpp"
#include "field_body_algorithm.hpp"
#include "rigid_tread_rows.hpp"
#include "soil_bodies.hpp"
#include "wheel_friction_constraint.hpp"
#include "wheel_shape.hpp"
#include "wtc/tyre/ground_memory.hpp"
#include "wtc/bullet/plugin.hpp"
#include "wtc/bullet/terrain_object.hpp"

namespace wtc::bullet {

struct Wheel {
  Wheel(const WheelDescription& description, EffectSet effects, ContactMode mode)
      : mounted(description, effects, mode) {}

  btRigidBody* body = nullptr;       // a rigid wheel, or
  btMultiBody* multibody = nullptr;  // a multibody link
  int link = -1;
  btCollisionObject* collider = nullptr;
  btVector3 axle_local, centre_local;
  MountedWheel mounted;                                 // tyre model, state, this step's result and engine contacts
  std::unique_ptr<WheelShape> shape;                    // replaces the collider's shape while registered
  std::unique_ptr<btCylinderShape> cap_cylinder;        // the cut sphere's caps (wheel_terrain_algorithm.cpp)
  std::unique_ptr<btCompoundShape> cap_shape;           // cap_cylinder at the wheel's centre, along its axle
  btVector3 link_force{0, 0, 0}, link_torque{0, 0, 0};  // multibody: what this substep added
  double joint_torque = 0.0;                            // multibody: Plugin::addAxleTorque's this substep (N m)
  // Constraint mode: the manifold the collision algorithm wrote this
  // substep's contacts into (null until it runs), and the manifold point of
  // each of mounted.last().contacts (-1: none, or one an earlier contact
  // of the step already took); the post-tick reads the impulses there.
  btPersistentManifold* manifold = nullptr;
  bool wheel_is_body0 = true;
  std::vector<int> manifold_point;
  std::vector<Eigen::Vector3d> solved_forces;  // scratch for MountedWheel::setSolvedForces
  // Constraint mode, a multibody link: its contacts' friction
  // (wheel_friction_constraint.hpp), in the world while the wheel is.
  std::unique_ptr<WheelFrictionConstraint> friction;
};

// A multibody's link velocities (link frames, index 0 the base, i + 1 link
// i), computed once per internal step for all its links and shared by the
// plugin's wheels (their tyre models, in the pre-tick) and the sim engine
// (its bodies' velocities after the step): Bullet's state does not change
// between the end of one internal step and the start of the next.
struct LinkVelocities {
  const btMultiBody* multibody = nullptr;
  btAlignedObjectArray<btVector3> angular, linear;
  bool valid = false;  // computed since the last internal step ended
};

namespace detail {

struct PluginState {
  PluginState(btDiscreteDynamicsWorld& world, const Terrain& terrain, ContactMode mode);
  ~PluginState();
  /// The state of `plugin` (for its collision algorithm and its sim engine).
  static PluginState& of(const Plugin& plugin) { return *plugin.state_; }

  WheelId add(std::unique_ptr<Wheel> wheel, const char* where);
  void preTick(double step_seconds);
  /// Every wheel's tyre model and wrench for the step (timed: clock).
  void stepWheels(double step_seconds);
  void postTick(double step_seconds);
  void readSolvedForces(Wheel& wheel, double step_seconds);
  int wheelOf(const btCollisionObject* object) const;
  /// Wheel `id`, which must be a multibody link on a revolute joint
  /// (InvalidInputError naming `where` and the wheel otherwise).
  Wheel& revoluteLink(WheelId id, const char* where) const;
  /// `multibody`'s link velocities now, computed at most once per internal
  /// step (the post-tick marks them stale).
  const LinkVelocities& linkVelocities(const btMultiBody& multibody);

  btDiscreteDynamicsWorld& world;
  btCollisionDispatcher* dispatcher;
  TerrainObject terrain;
  // The soil regions' memory, which every wheel reads and presses (null
  // in a wheel's state when the terrain has none).
  GroundMemory ground_memory;
  ContactMode mode;
  std::vector<std::unique_ptr<Wheel>> wheels;
  std::unordered_map<const btCollisionObject*, int> wheel_of;
  std::unique_ptr<btCollisionAlgorithmCreateFunc> create;
  // A convex body against a compact field's tile, each convex type both
  // ways (field_body_algorithm.hpp).
  std::vector<std::unique_ptr<btCollisionAlgorithmCreateFunc>> field_body_creates;
  WheelListener* listener = nullptr;
  std::function<void(double)> pre_tick;
  std::function<void(double)> post_wheels;
  std::vector<LinkVelocities> link_velocities;  // per multibody asked for
  // Implicit mode: the world's solver's table of rigid wheels' tread rows
  // (rigid_tread_rows.hpp), during an internal step; null otherwise.
  RigidTreadRows* tread_rows = nullptr;
  StepClock clock;  // preTick and postTick, the caller's callback not included
  SoilBodies soil_bodies{*this};  // bodies on soft soil (addSoilBody)
};

}  // namespace detail
}  // namespace wtc::bullet
