// wtc::bullet::Plugin: registration, the pre-tick (one tyre-model step per
// wheel per internal step) and how its results reach the bodies. Design
// note in include/wtc/bullet/plugin.hpp.
#include "wtc/bullet/plugin.hpp"

#include "wtc/bullet/contact_solver.hpp"
#include "wtc/bullet/rigid_contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include "adapter/cap_cylinder.hpp"
#include "base/scratch_capacity.hpp"
#include "plugin_state.hpp"
#include "wheel_terrain_algorithm.hpp"
#include "wtc/base/error.hpp"

namespace wtc::bullet {
namespace {

// Bullet rounds a convex shape's edges by its margin (0.04 m by default):
// the caps' cylinder keeps 0.5 % of r_f (1 mm on the robot's wheel), so its
// rims are the caps' edges within that.
constexpr double kCapShapeMarginRatio = 0.005;

[[noreturn]] void fail(const char* where, const std::string& what) {
  throw InvalidInputError(std::string(where) + ": " + what);
}

void preTickCallback(btDynamicsWorld* world, btScalar step_seconds) {
  static_cast<detail::PluginState*>(world->getWorldUserInfo())->preTick(step_seconds);
}

void postTickCallback(btDynamicsWorld* world, btScalar step_seconds) {
  static_cast<detail::PluginState*>(world->getWorldUserInfo())->postTick(step_seconds);
}

// The table of rigid wheels' tread rows of `solver`, if it is WTC's
// (rigid_tread_rows.hpp); null for any other solver.
RigidTreadRows* rigidTreadRowsOf(btConstraintSolver* solver) {
  if (auto* rigid = dynamic_cast<RigidContactSolver*>(solver)) return &rigid->treadRows();
  if (auto* multibody = dynamic_cast<ContactSolver*>(solver)) return &multibody->treadRows();
  return nullptr;
}

// Where the wheel is and how it moves, in the world frame.
struct Kinematics {
  btVector3 centre, axle, com;
  WheelMotion motion;
};

Kinematics rigidKinematics(const Wheel& w) {
  const btTransform& t = w.body->getWorldTransform();  // the centre-of-mass frame
  Kinematics k;
  k.com = t.getOrigin();
  k.centre = t * w.centre_local;
  k.axle = t.getBasis() * w.axle_local;
  k.motion.velocity = toEigen(w.body->getVelocityInLocalPoint(k.centre - k.com));
  k.motion.angular_velocity = toEigen(w.body->getAngularVelocity());
  return k;
}

// `velocities` holds the link velocities of the wheel's multibody (link
// frames, index 0 the base, i + 1 link i); the collider's frame is the
// link's.
Kinematics multiBodyKinematics(const Wheel& w, const LinkVelocities& velocities) {
  const btTransform& t = w.collider->getWorldTransform();
  Kinematics k;
  k.com = t.getOrigin();
  k.centre = t * w.centre_local;
  k.axle = t.getBasis() * w.axle_local;
  const btVector3 spin = t.getBasis() * velocities.angular[w.link + 1];
  const btVector3 com_velocity = t.getBasis() * velocities.linear[w.link + 1];
  k.motion.velocity = toEigen(com_velocity + spin.cross(k.centre - k.com));
  k.motion.angular_velocity = toEigen(spin);
  return k;
}

// The wrench (force F through O, torque T about O) on the wheel for one
// step of length h: impulses on a rigid body (they act on this substep
// only); link force and torque on a multibody, taken back in the post-tick
// when Bullet keeps them for the next substep (see postTick).
void applyWrench(Wheel& w, const Kinematics& k, const btVector3& force, const btVector3& torque_about_centre,
                 double h) {
  const btVector3 torque = torque_about_centre + (k.centre - k.com).cross(force);
  if (w.body != nullptr) {
    w.body->applyCentralImpulse(force * h);
    w.body->applyTorqueImpulse(torque * h);
  } else {
    w.multibody->addLinkForce(w.link, force);
    w.multibody->addLinkTorque(w.link, torque);
    w.link_force = force;
    w.link_torque = torque;
  }
}

}  // namespace

detail::PluginState::PluginState(btDiscreteDynamicsWorld& w, const Terrain& t, ContactMode m)
    : world(w),
      dispatcher(dynamic_cast<btCollisionDispatcher*>(w.getDispatcher())),
      terrain(t),
      ground_memory(t),
      mode(m) {
  if (dispatcher == nullptr) fail("wtc::bullet::Plugin", "the world's dispatcher is not a btCollisionDispatcher");
  world.addCollisionObject(&terrain.object(), btBroadphaseProxy::StaticFilter,
                           btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
  create = std::make_unique<WheelTerrainAlgorithm::CreateFunc>(*this);
  for (int type = 0; type < MAX_BROADPHASE_COLLISION_TYPES; ++type) {
    dispatcher->registerCollisionCreateFunc(CUSTOM_CONVEX_SHAPE_TYPE, type, create.get());
    dispatcher->registerCollisionCreateFunc(type, CUSTOM_CONVEX_SHAPE_TYPE, create.get());
  }
  // A body against a compact field: Bullet's own algorithm with the body's
  // box tested first (field_body_algorithm.hpp); Bullet's for any other
  // heightfield in the world.
  btCollisionConfiguration* config = dispatcher->getCollisionConfiguration();
  for (int type = 0; type < CONCAVE_SHAPES_START_HERE; ++type) {
    if (!detail::FieldBodyAlgorithm::serves(type)) continue;
    field_body_creates.push_back(std::make_unique<detail::FieldBodyAlgorithm::CreateFunc>(
        config->getCollisionAlgorithmCreateFunc(type, TERRAIN_SHAPE_PROXYTYPE), false));
    dispatcher->registerCollisionCreateFunc(type, TERRAIN_SHAPE_PROXYTYPE, field_body_creates.back().get());
    field_body_creates.push_back(std::make_unique<detail::FieldBodyAlgorithm::CreateFunc>(
        config->getCollisionAlgorithmCreateFunc(TERRAIN_SHAPE_PROXYTYPE, type), true));
    dispatcher->registerCollisionCreateFunc(TERRAIN_SHAPE_PROXYTYPE, type, field_body_creates.back().get());
  }
  // Constraint mode gives each WTC contact one friction direction, along
  // the traction, capped at mu R_z: a Coulomb cone along the slip law's
  // force. Bullet keeps that direction only with the caching flag, and a
  // second direction (SOLVER_USE_2_FRICTION_DIRECTIONS) would make a
  // pyramid: both capped at mu R_z, a diagonal force gets sqrt(2) mu R_z
  // (measured: half the slip law's lateral drift). A multibody world keeps
  // its second direction: btMultiBodyConstraintSolver::convertMultiBodyContact
  // overwrites every contact's friction directions with btPlaneSpace1 before
  // it looks at the cache, so a multibody wheel's friction is its own
  // constraint's (wheel_friction_constraint.hpp). Both flags are world-wide
  // (docs/bullet-plugin.md).
  if (engineSolvesContacts(mode)) {
    // A split threshold at or above zero splits every penetrating contact:
    // no contact could keep the tyre's spring (wheel_terrain_algorithm.cpp).
    const btContactSolverInfo& info = world.getSolverInfo();
    if (info.m_splitImpulse && !(info.m_splitImpulsePenetrationThreshold < 0.0)) {
      fail("wtc::bullet::Plugin",
           "constraint mode needs the world's split impulse off or its penetration threshold "
           "below zero (m_splitImpulsePenetrationThreshold = " +
               std::to_string(info.m_splitImpulsePenetrationThreshold) +
               " m): a split contact loses the tyre's spring");
    }
    world.getSolverInfo().m_solverMode |= SOLVER_ENABLE_FRICTION_DIRECTION_CACHING;
    // Implicit mode's rigid wheels need both directions (addWheel sets it).
    if (mode == ContactMode::kConstraint && dynamic_cast<btMultiBodyDynamicsWorld*>(&world) == nullptr) {
      world.getSolverInfo().m_solverMode &= ~SOLVER_USE_2_FRICTION_DIRECTIONS;
    }
  }
  world.setInternalTickCallback(&preTickCallback, this, true);
  world.setInternalTickCallback(&postTickCallback, this, false);
}

detail::PluginState::~PluginState() {
  world.setInternalTickCallback(nullptr, nullptr, true);
  world.setInternalTickCallback(nullptr, nullptr, false);
  // Free every algorithm that points at this plugin before unregistering.
  btOverlappingPairCache* pairs = world.getBroadphase()->getOverlappingPairCache();
  for (const auto& w : wheels) {
    if (w->collider->getBroadphaseHandle() != nullptr) {
      pairs->cleanProxyFromPairs(w->collider->getBroadphaseHandle(), dispatcher);
    }
  }
  world.removeCollisionObject(&terrain.object());
  btCollisionConfiguration* config = dispatcher->getCollisionConfiguration();
  for (int type = 0; type < MAX_BROADPHASE_COLLISION_TYPES; ++type) {
    dispatcher->registerCollisionCreateFunc(CUSTOM_CONVEX_SHAPE_TYPE, type,
                                            config->getCollisionAlgorithmCreateFunc(CUSTOM_CONVEX_SHAPE_TYPE, type));
    dispatcher->registerCollisionCreateFunc(type, CUSTOM_CONVEX_SHAPE_TYPE,
                                            config->getCollisionAlgorithmCreateFunc(type, CUSTOM_CONVEX_SHAPE_TYPE));
  }
  for (int type = 0; type < CONCAVE_SHAPES_START_HERE; ++type) {
    if (!detail::FieldBodyAlgorithm::serves(type)) continue;
    dispatcher->registerCollisionCreateFunc(type, TERRAIN_SHAPE_PROXYTYPE,
                                            config->getCollisionAlgorithmCreateFunc(type, TERRAIN_SHAPE_PROXYTYPE));
    dispatcher->registerCollisionCreateFunc(TERRAIN_SHAPE_PROXYTYPE, type,
                                            config->getCollisionAlgorithmCreateFunc(TERRAIN_SHAPE_PROXYTYPE, type));
  }
  for (const auto& w : wheels) {
    w->collider->setCollisionShape(w->shape->original());
    if (w->friction != nullptr)
      static_cast<btMultiBodyDynamicsWorld&>(world).removeMultiBodyConstraint(w->friction.get());
  }
}

int detail::PluginState::wheelOf(const btCollisionObject* object) const {
  const auto found = wheel_of.find(object);
  return found == wheel_of.end() ? -1 : found->second;
}

WheelId detail::PluginState::add(std::unique_ptr<Wheel> w, const char* where) {
  if (wheel_of.count(w->collider) != 0) fail(where, "this body is already a registered wheel");
  btCollisionShape* original = w->collider->getCollisionShape();
  if (original == nullptr) fail(where, "the wheel body has no collision shape");
  // A wheel whose broadphase filters exclude the (static) terrain never
  // reaches WTC's algorithm: constraint mode would let it fall through.
  const btBroadphaseProxy* proxy = w->collider->getBroadphaseHandle();
  const btBroadphaseProxy* ground = terrain.object().getBroadphaseHandle();
  if (proxy != nullptr && ((proxy->m_collisionFilterGroup & ground->m_collisionFilterMask) == 0 ||
                           (ground->m_collisionFilterGroup & proxy->m_collisionFilterMask) == 0)) {
    fail(where, "the wheel's collision filter (group " + std::to_string(proxy->m_collisionFilterGroup) + ", mask " +
                    std::to_string(proxy->m_collisionFilterMask) +
                    ") excludes the static terrain; add the wheel's collider with btBroadphaseProxy::DefaultFilter "
                    "and AllFilter (btDiscreteDynamicsWorld::addCollisionObject defaults to the static group)");
  }
  w->manifold_point.reserve(kReservedContacts);  // no allocation in the step loop
  w->solved_forces.reserve(kReservedContacts);
  // The caps' cylinder (btCylinderShape's axis is y) at centre_local along
  // axle_local; a small margin, so that its rims stay sharp.
  const WheelGeometry& g = w->mounted.description().geometry;
  const CapCylinder caps = capCylinder(g);
  w->cap_cylinder = std::make_unique<btCylinderShape>(btVector3(caps.radius, caps.half_height, caps.radius));
  w->cap_cylinder->setMargin(kCapShapeMarginRatio * g.free_radius);
  w->cap_shape = std::make_unique<btCompoundShape>(true, 1);
  w->cap_shape->addChildShape(
      btTransform(shortestArcQuat(btVector3(0, 1, 0), w->axle_local.normalized()), w->centre_local),
      w->cap_cylinder.get());
  w->shape = std::make_unique<WheelShape>(w->mounted.description().geometry.free_radius, original);
  w->collider->setCollisionShape(w->shape.get());
  w->collider->setActivationState(DISABLE_DEACTIVATION);
  if (w->collider->getBroadphaseHandle() != nullptr) world.updateSingleAabb(w->collider);
  if (ground_memory.regionCount() > 0) w->mounted.state().setGroundMemory(&ground_memory);
  const auto id = static_cast<WheelId>(wheels.size());
  wheel_of.emplace(w->collider, id);
  wheels.push_back(std::move(w));
  return id;
}

const LinkVelocities& detail::PluginState::linkVelocities(const btMultiBody& multibody) {
  auto it = std::find_if(link_velocities.begin(), link_velocities.end(),
                         [&](const LinkVelocities& v) { return v.multibody == &multibody; });
  LinkVelocities& v = it != link_velocities.end() ? *it : link_velocities.emplace_back();
  if (v.valid) return v;
  v.multibody = &multibody;
  v.angular.resize(multibody.getNumLinks() + 1);
  v.linear.resize(multibody.getNumLinks() + 1);
  multibody.compTreeLinkVelocities(&v.angular[0], &v.linear[0]);
  v.valid = true;
  return v;
}

void detail::PluginState::preTick(double h) {
  // This step's rigid tread rows go to the solver the world has now; the
  // collision writes them (wheel_terrain_algorithm.cpp).
  tread_rows = mode == ContactMode::kImplicit ? rigidTreadRowsOf(world.getConstraintSolver()) : nullptr;
  if (tread_rows != nullptr) tread_rows->clear();
  if (pre_tick) pre_tick(h);
  stepWheels(h);
  {
    const StepClock::Section timed(clock);
    soil_bodies.step(h);
  }
  if (post_wheels) post_wheels(h);
}

void detail::PluginState::stepWheels(double h) {
  const StepClock::Section timed(clock);
  const Terrain& ground = terrain.terrain();
  const Eigen::Vector3d gravity = toEigen(world.getGravity());
  for (std::size_t id = 0; id < wheels.size(); ++id) {
    Wheel& w = *wheels[id];
    w.mounted.setRestLoad(gravity);
    w.manifold = nullptr;
    w.manifold_point.clear();
    const Kinematics k = w.body != nullptr ? rigidKinematics(w) : multiBodyKinematics(w, linkVelocities(*w.multibody));
    const MountedWheelStep& r = w.mounted.step(ground, {toEigen(k.centre), toEigen(k.axle)}, k.motion, h);
    if (r.skipped) {
      // Its body's state is not finite: no force and no contact this step
      // (an exception here would leave Bullet's world half-stepped).
      if (w.friction != nullptr) w.friction->set({}, h);
      w.mounted.tell(listener, static_cast<WheelId>(id), h);
      continue;
    }
    // Constraint mode: the contacts reach Bullet through the collision
    // algorithm (wheel_terrain_algorithm.cpp); the wrench is then the
    // rolling moment alone.
    applyWrench(w, k, toBt(r.force), toBt(r.torque), h);
    if (w.friction != nullptr) w.friction->set(r.contacts, h);
    w.mounted.tell(listener, static_cast<WheelId>(id), h);
  }
}

void detail::PluginState::postTick(double h) {
  const StepClock::Section timed(clock);
  // The step moved every body: the next reader computes the velocities anew.
  for (LinkVelocities& v : link_velocities) v.valid = false;
  // The manifold points the table names live only until the next collision.
  if (tread_rows != nullptr) tread_rows->clear();
  tread_rows = nullptr;
  if (engineSolvesContacts(mode)) {
    for (const auto& w : wheels) readSolvedForces(*w, h);
  }
#ifdef BT_USE_VIRTUAL_CLEARFORCES_AND_GRAVITY
  // This Bullet clears multibody forces once per stepSimulation, not per
  // substep (btMultiBodyDynamicsWorld.h defines the macro, as Debian's does):
  // take this substep's wrench back so that the next one starts clean.
  for (const auto& w : wheels) {
    if (w->multibody == nullptr) continue;
    w->multibody->addLinkForce(w->link, -w->link_force);
    w->multibody->addLinkTorque(w->link, -w->link_torque);
    w->multibody->addJointTorque(w->link, -w->joint_torque);
  }
#endif
  soil_bodies.stepped();
  for (const auto& w : wheels) {
    w->link_force.setZero();
    w->link_torque.setZero();
    w->joint_torque = 0.0;
  }
}

// What Bullet's solver applied at each WTC contact this substep, on the
// wheel: (n m_appliedImpulse + d1 m_appliedImpulseLateral1
// [+ d2 m_appliedImpulseLateral2]) / h, with n the manifold's normal on B
// (toward A) and d1, d2 its friction directions (both solvers write the
// impulses and directions they used back to the point).
void detail::PluginState::readSolvedForces(Wheel& w, double h) {
  if (w.mounted.last().skipped) return;
  const std::size_t n = w.mounted.last().contacts.size();
  w.solved_forces.assign(n, Eigen::Vector3d::Zero());
  const bool second = (world.getSolverInfo().m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) != 0;
  for (std::size_t i = 0; i < n && i < w.manifold_point.size() && w.manifold != nullptr; ++i) {
    if (w.manifold_point[i] < 0 || w.manifold_point[i] >= w.manifold->getNumContacts()) continue;
    const btManifoldPoint& p = w.manifold->getContactPoint(w.manifold_point[i]);
    btVector3 impulse_on_a =
        p.m_normalWorldOnB * p.m_appliedImpulse + p.m_lateralFrictionDir1 * p.m_appliedImpulseLateral1;
    if (second) impulse_on_a += p.m_lateralFrictionDir2 * p.m_appliedImpulseLateral2;
    w.solved_forces[i] = toEigen(w.wheel_is_body0 ? impulse_on_a : -impulse_on_a) / h;
  }
  if (w.friction != nullptr) {
    for (std::size_t i = 0; i < n; ++i) w.solved_forces[i] += toEigen(w.friction->appliedForce(i, h));
  }
  w.mounted.setSolvedForces(w.solved_forces);
}

// The wheel `id` as a link on a revolute joint (axleTorque, addAxleTorque).
Wheel& detail::PluginState::revoluteLink(WheelId id, const char* where) const {
  if (id < 0 || static_cast<std::size_t>(id) >= wheels.size()) {
    fail(where, "wheel " + std::to_string(id) + " is not registered (" + std::to_string(wheels.size()) + " wheels)");
  }
  Wheel& w = *wheels[static_cast<std::size_t>(id)];
  if (w.multibody == nullptr) {
    fail(where, "wheel " + std::to_string(id) + " is a rigid body: its axle torque is a multibody link's joint's");
  }
  if (w.multibody->getLink(w.link).m_jointType != btMultibodyLink::eRevolute) {
    fail(where, "wheel " + std::to_string(id) + " (link " + std::to_string(w.link) +
                    ") is not on a revolute joint: its joint has no one axis to turn about");
  }
  return w;
}

Plugin::Plugin(btDiscreteDynamicsWorld& world, const Terrain& terrain, ContactMode mode)
    : state_(std::make_unique<detail::PluginState>(world, terrain, mode)) {}

Plugin::~Plugin() = default;

// A static body (inverse mass 0) has no mass to give: bodyInertia refuses it.
constexpr double kStaticMass = std::numeric_limits<double>::infinity();

WheelId Plugin::addWheel(const RigidWheel& spec) {
  static constexpr const char* kWhere = "wtc::bullet::Plugin::addWheel (rigid body)";
  if (spec.body == nullptr) fail(kWhere, "body is null");
  // Bullet's own solvers take a friction row's CFM unscaled
  // (lambda += rhs - cfm lambda - D dV): the tread's compliance needs WTC's
  // solver, which makes the wheel's friction rows soft (rigid_tread_rows.hpp).
  if (state_->mode == ContactMode::kImplicit) {
    if (rigidTreadRowsOf(state_->world.getConstraintSolver()) == nullptr) {
      fail(kWhere,
           "implicit mode needs the world's solver to be a wtc::bullet::RigidContactSolver "
           "(wtc/bullet/rigid_contact_solver.hpp; in a btMultiBodyDynamicsWorld, a wtc::bullet::ContactSolver), "
           "which makes the tread's friction rows soft: Bullet's own solver takes their compliance unscaled and "
           "diverges");
    }
    // Row 1, across the traction: Bullet's second friction direction
    // (world-wide; docs/bullet-plugin.md).
    state_->world.getSolverInfo().m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
  }
  validateMounting(toEigen(spec.axle_local), toEigen(spec.centre_local), kWhere);
  const double mass = spec.body->getInvMass() > 0.0 ? 1.0 / spec.body->getInvMass() : kStaticMass;
  const WheelDescription description =
      mountedDescription(spec.description, spec.inertia_source, mass,
                         toEigen(spec.body->getLocalInertia()).asDiagonal(), toEigen(spec.axle_local), kWhere);
  auto w = std::make_unique<Wheel>(description, spec.effects, state_->mode);
  w->body = spec.body;
  w->collider = spec.body;
  w->axle_local = spec.axle_local;
  w->centre_local = spec.centre_local;
  return state_->add(std::move(w), kWhere);
}

WheelId Plugin::addWheel(const MultiBodyWheel& spec) {
  static constexpr const char* kWhere = "wtc::bullet::Plugin::addWheel (multibody link)";
  if (spec.multibody == nullptr) fail(kWhere, "multibody is null");
  if (spec.link < 0 || spec.link >= spec.multibody->getNumLinks()) {
    fail(kWhere, "link = " + std::to_string(spec.link) + " is not a link of the multibody (it has " +
                     std::to_string(spec.multibody->getNumLinks()) + ")");
  }
  btMultiBodyLinkCollider* collider = spec.multibody->getLinkCollider(spec.link);
  if (collider == nullptr) fail(kWhere, "link " + std::to_string(spec.link) + " has no collider");
  validateMounting(toEigen(spec.axle_local), toEigen(spec.centre_local), kWhere);
  const WheelDescription description = mountedDescription(
      spec.description, spec.inertia_source, spec.multibody->getLinkMass(spec.link),
      toEigen(spec.multibody->getLinkInertia(spec.link)).asDiagonal(), toEigen(spec.axle_local), kWhere);
  auto w = std::make_unique<Wheel>(description, spec.effects, state_->mode);
  w->multibody = spec.multibody;
  w->link = spec.link;
  w->collider = collider;
  w->axle_local = spec.axle_local;
  w->centre_local = spec.centre_local;
  auto* multibody_world = dynamic_cast<btMultiBodyDynamicsWorld*>(&state_->world);
  if (engineSolvesContacts(state_->mode)) {
    if (multibody_world == nullptr) fail(kWhere, "a multibody link's world must be a btMultiBodyDynamicsWorld");
    if (state_->mode == ContactMode::kImplicit &&
        dynamic_cast<ContactSolver*>(multibody_world->getConstraintSolver()) == nullptr) {
      fail(kWhere,
           "implicit mode needs the world's solver to be a wtc::bullet::ContactSolver (wtc/bullet/contact_solver.hpp), "
           "which bounds the tread's rows by the normal impulse it solves");
    }
    w->friction =
        std::make_unique<WheelFrictionConstraint>(spec.multibody, spec.link, static_cast<int>(2 * kReservedContacts));
    w->friction->setContactPoints(&w->manifold, &w->manifold_point);
  }
  const WheelId id = state_->add(std::move(w), kWhere);
  if (WheelFrictionConstraint* friction = state_->wheels.back()->friction.get()) {
    multibody_world->addMultiBodyConstraint(friction);
  }
  return id;
}

const WheelForces& Plugin::forces(WheelId wheel) const {
  return state_->wheels.at(static_cast<std::size_t>(wheel))->mounted.forces();
}

const WheelForces& Plugin::applied(WheelId wheel) const {
  return state_->wheels.at(static_cast<std::size_t>(wheel))->mounted.applied();
}

const WheelState& Plugin::state(WheelId wheel) const {
  return state_->wheels.at(static_cast<std::size_t>(wheel))->mounted.state();
}
SoilBodyId Plugin::addSoilBody(const SoilBody& body) { return state_->soil_bodies.add(body); }
const BodySoilForces& Plugin::soilForces(SoilBodyId body) const { return state_->soil_bodies.forces(body); }
int Plugin::soilBodyCount() const { return state_->soil_bodies.count(); }
const GroundMemory& Plugin::groundMemory() const { return state_->ground_memory; }
GroundMemory& Plugin::groundMemory() { return state_->ground_memory; }
int Plugin::wheelCount() const { return static_cast<int>(state_->wheels.size()); }
double Plugin::contactSeconds() const { return state_->clock.seconds(); }
ContactMode Plugin::mode() const { return state_->mode; }
btCollisionObject& Plugin::terrainObject() { return state_->terrain.object(); }
const TerrainObject& Plugin::terrainShapes() const { return state_->terrain; }
void Plugin::setListener(WheelListener* listener) { state_->listener = listener; }
void Plugin::setPreTickCallback(std::function<void(double)> callback) { state_->pre_tick = std::move(callback); }
void Plugin::setPostWheelsCallback(std::function<void(double)> callback) { state_->post_wheels = std::move(callback); }

double Plugin::axleTorque(WheelId wheel) const {
  const Wheel& w = state_->revoluteLink(wheel, "wtc::bullet::Plugin::axleTorque");
  // The link's frame is its collider's; its joint axis is fixed in it.
  const btVector3 axis_W = w.collider->getWorldTransform().getBasis() * w.multibody->getLink(w.link).getAxisTop(0);
  return w.multibody->getLinkTorque(w.link).dot(axis_W) + w.multibody->getJointTorque(w.link);
}

void Plugin::addAxleTorque(WheelId wheel, double torque) {
  Wheel& w = state_->revoluteLink(wheel, "wtc::bullet::Plugin::addAxleTorque");
  w.multibody->addJointTorque(w.link, torque);
  w.joint_torque += torque;
}

}  // namespace wtc::bullet
