#pragma once
// wtc::bullet: WTC wheels in any Bullet world (btDiscreteDynamicsWorld, or
// btMultiBodyDynamicsWorld with wheels as btMultiBody links). The adapter
// does nothing physical itself: it reads poses and velocities from Bullet,
// asks the core (wtc::TyreModel), and hands the core's contacts and forces
// back to Bullet. docs/bullet-plugin.md has the details and the validation.
//
// How it plugs in:
//  - The terrain becomes one static collision object (TerrainObject), added
//    to the world; every pair but wheel-terrain collides with it as usual.
//  - A registered wheel's shape becomes a WheelShape wrapping its own; the
//    dispatcher sends wheel-terrain pairs to WTC's collision algorithm, and
//    every other pair of the wheel to Bullet's algorithm for the original.
//  - The world's internal pre-tick callback runs every wheel's tyre model
//    at the start of each internal step (substeps included), with that
//    step's length.
// Force mode: the tyre forces go to the bodies as impulses F h in the
// pre-tick. Bullet applies gravity once per stepSimulation and clears the
// accumulated forces only after all substeps, so a force added at every
// substep would pile up; an impulse acts on exactly one substep. Multibody
// links get addLinkForce/addLinkTorque, which Bullet clears every substep.
// Constraint mode: the algorithm writes WTC's contacts into the pair's
// manifold with the tyre's stiffness and damping (Bullet's soft contact, an
// implicit spring) and the slip law's friction coefficient and direction.
// Implicit mode: as constraint mode, and the tread as two compliant friction
// rows per contact (docs/tyre-model.md). The world's solver must be WTC's: a
// wtc::bullet::RigidContactSolver (rigid_contact_solver.hpp) in a
// btDiscreteDynamicsWorld, a wtc::bullet::ContactSolver (contact_solver.hpp)
// in a btMultiBodyDynamicsWorld; addWheel refuses a wheel otherwise. A
// multibody link's rows are WTC's own constraint's; a btRigidBody's are
// Bullet's two friction rows of its manifold point, made soft by the solver
// (the plugin then sets SOLVER_USE_2_FRICTION_DIRECTIONS, world-wide).
// Rolling resistance is an explicit moment in every mode.
//
// The plugin owns the world's internal pre-tick callback and its world user
// info; chain your own per-step code through setPreTickCallback (before the
// wheels) and setPostWheelsCallback (after them). Wheels are kept awake
// (DISABLE_DEACTIVATION): the tread state needs every step.
//
// Wheel drives in closed form (force mode): after the wheels, the tyre's
// wrench of the step is on each wheel, so a velocity drive with an effort
// cap needs no solver row: its torque for the step is
//   T = I (rate* - rate) / h - tau_axle,  |T| <= cap
// (wtc::vehicle::wheelDriveTorque), with tau_axle from axleTorque() and T
// applied with addAxleTorque(), both in the post-wheels callback. The sim
// engine drives its wheels so (docs/bullet-plugin.md, Wheel drives).
//
// Bodies on soft soil (addSoilBody; docs/soft-soil.md, "A body on the
// soil"): a registered body's underside meets the terrain's soil pieces as
// the soil's pressure and shear (wtc::BodyOnSoil), applied in the pre-tick
// after the wheels, as the wheels' wrench is; its rigid contacts with those
// pieces are dropped. The plugin then wraps the dispatcher's near callback
// (the one it finds at the first addSoilBody, chained): after the pair is
// processed, a soil body's manifold points on a piece with a soil go.
#include <functional>
#include <memory>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "wtc/adapter/wheel_listener.hpp"
#include "wtc/adapter/wheel_spec.hpp"
#include "wtc/bullet/terrain_object.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"
#include "wtc/terrain/terrain.hpp"
#include "wtc/tyre/body_soil.hpp"
#include "wtc/tyre/contact_mode.hpp"
#include "wtc/tyre/ground_memory.hpp"
#include "wtc/tyre/tyre_model.hpp"

class btMultiBody;

namespace wtc::bullet {
namespace detail {
struct PluginState;
}  // namespace detail

using WheelId = wtc::WheelId;
using WheelListener = wtc::WheelListener;

/// Where a wheel sits on its Bullet body (wtc/adapter/wheel_spec.hpp: what
/// the wheel is and where its inertia comes from).
struct WheelMounting : WheelSpec {
  btVector3 axle_local{0, 1, 0};    ///< Axle direction in the body (or link) frame.
  btVector3 centre_local{0, 0, 0};  ///< Wheel centre O in the body (or link) frame (m).
};

/// A wheel that is its own btRigidBody (on a hinge to its carrier, typically).
struct RigidWheel : WheelMounting {
  btRigidBody* body = nullptr;  ///< The wheel (not owned).
};

/// A wheel that is link `link` of a btMultiBody.
struct MultiBodyWheel : WheelMounting {
  btMultiBody* multibody = nullptr;  ///< Not owned; the link must have a collider.
  int link = -1;
};

/// A body whose underside meets soft soil (wtc/tyre/body_soil.hpp): a
/// btRigidBody, or a btMultiBody's link (link -1: its base).
struct SoilBody {
  btRigidBody* body = nullptr;
  btMultiBody* multibody = nullptr;
  int link = -1;
  /// Its shape in its frame (the rigid body's or the link's: the centre of
  /// mass frame; m), one or more convex hulls.
  std::vector<ConvexPolyhedron> hulls;
};
using SoilBodyId = int;

class Plugin {
 public:
  /// Adds `terrain` (which must outlive the plugin) to `world` and takes
  /// over the world's pre-tick callback. The dispatcher must be a
  /// btCollisionDispatcher (it is, unless replaced).
  Plugin(btDiscreteDynamicsWorld& world, const Terrain& terrain, ContactMode mode = ContactMode::kForce);
  ~Plugin();
  Plugin(const Plugin&) = delete;
  Plugin& operator=(const Plugin&) = delete;

  /// Registers a wheel (validated: InvalidInputError names the problem;
  /// in implicit mode, a world whose solver is not WTC's).
  WheelId addWheel(const RigidWheel& wheel);
  WheelId addWheel(const MultiBodyWheel& wheel);

  /// Registers a body whose underside meets the terrain's soil pieces as
  /// soft soil (InvalidInputError: no body, both or neither kind given, a
  /// link out of range or without a collider, a static body, a registered
  /// wheel or soil body, hulls BodyOnSoil refuses). In a soil region it
  /// reads and presses the ground's memory.
  SoilBodyId addSoilBody(const SoilBody& body);
  /// What the soil did to it in the last internal step.
  const BodySoilForces& soilForces(SoilBodyId body) const;
  int soilBodyCount() const;

  /// The last internal step's result and state of a wheel.
  const WheelForces& forces(WheelId wheel) const;
  /// What acted on the wheel in the last internal step: forces() in force
  /// mode; in the engine-solved modes the forces Bullet's solver applied at each
  /// contact (impulse / h), their wrench and the rolling moment
  /// (wtc::MountedWheel::applied). Report these, not forces(), as the
  /// contact forces of a constraint-mode run.
  const WheelForces& applied(WheelId wheel) const;
  const WheelState& state(WheelId wheel) const;
  /// What the terrain's soil regions remember (wtc/tyre/ground_memory.hpp):
  /// every wheel reads and presses it; empty without a region. Writable
  /// between steps: ruts a run left, read back (wtc/io/ground_memory_file.hpp).
  const GroundMemory& groundMemory() const;
  GroundMemory& groundMemory();
  int wheelCount() const;
  /// Wall time (s) the plugin's own per-step work took since construction:
  /// reading the wheels' state, their contacts, the tyre model and handing
  /// the result to the engine (wtc::StepClock), the engine's solve not
  /// included. Against the simulation's wall time: WTC's share of a step.
  double contactSeconds() const;

  ContactMode mode() const;
  btCollisionObject& terrainObject();
  /// The terrain's Bullet shapes (which piece a contact of the terrain met).
  const TerrainObject& terrainShapes() const;
  /// Called at each internal step, for each wheel, after its tyre model ran
  /// (before Bullet integrates the step); null: none.
  void setListener(WheelListener* listener);
  /// Called at the start of every internal step, before the wheels.
  void setPreTickCallback(std::function<void(double step_seconds)> callback);
  /// Called at every internal step after every wheel's tyre model ran and
  /// its wrench is on its body (after the listener), before Bullet solves
  /// and integrates the step; null: none. Call order in a step: pre-tick
  /// callback, wheels, this, Bullet's solve and integration.
  void setPostWheelsCallback(std::function<void(double step_seconds)> callback);

  /// For a wheel that is a multibody link on a revolute joint (its axle):
  /// the torque about the joint's axis on the link now (N m, the sense of
  /// btMultiBody::getJointVel), the link's external torque about its axis
  /// plus the joint's own torque. In the post-wheels callback that is the
  /// tyre's torque of this step and whatever else was added: tau_axle of
  /// vehicle::wheelDriveTorque. InvalidInputError for a rigid wheel or a
  /// link whose joint is not revolute.
  double axleTorque(WheelId wheel) const;
  /// Adds `torque` (N m) about the wheel link's joint axis for this internal
  /// step alone: on the wheel, and its opposite on the parent link
  /// (btMultiBody::addJointTorque), taken back after the step as the tyre's
  /// wrench is (this Bullet clears multibody forces once per stepSimulation,
  /// not per substep). Same preconditions as axleTorque.
  void addAxleTorque(WheelId wheel, double torque);

 private:
  // The plugin's state, shared with its collision algorithm and its sim
  // engine (plugins/bullet/src/plugin_state.hpp), which reach it through
  // PluginState::of.
  friend struct detail::PluginState;
  std::unique_ptr<detail::PluginState> state_;
};

}  // namespace wtc::bullet
