#include "wtc/bullet/sim_engine.hpp"

#include <algorithm>
#include <limits>
#include <mutex>
#include <vector>

#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <btBulletDynamicsCommon.h>

#include "warm_started_joint_limit.hpp"
#include "warm_started_motor.hpp"
#include "wtc/bullet/plugin.hpp"
#include "wtc/bullet/terrain_object.hpp"
#include "wtc/base/constants.hpp"
#include "wtc/sim/sim_constants.hpp"
#include "wtc/base/error.hpp"
#include "sim/native_wheel_contacts.hpp"

namespace wtc::bullet {
namespace {

using vehicle::Body;
using vehicle::JointType;
using vehicle::Shape;

btVector3 toBt(const Eigen::Ref<const Eigen::Vector3d>& v) { return {v.x(), v.y(), v.z()}; }
Eigen::Vector3d toEigen(const btVector3& v) { return {v.x(), v.y(), v.z()}; }
btQuaternion toBtRotation(const Eigen::Matrix3d& r) {
  const Eigen::Quaterniond q(r);
  return {q.x(), q.y(), q.z(), q.w()};
}
Eigen::Matrix3d toEigen(const btMatrix3x3& m) {
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i) r.row(i) = toEigen(m.getRow(i)).transpose();
  return r;
}
btTransform toBtTransform(const Eigen::Isometry3d& t) {
  return btTransform(toBtRotation(Eigen::Matrix3d(t.linear())), toBt(t.translation()));
}

// A cylinder along body axis `axis` (0 x, 1 y, 2 z) of radius r and length l.
std::unique_ptr<btCollisionShape> cylinder(int axis, double r, double l) {
  switch (axis) {
    case 0:
      return std::make_unique<btCylinderShapeX>(btVector3(0.5 * l, r, r));
    case 1:
      return std::make_unique<btCylinderShape>(btVector3(r, 0.5 * l, r));
    default:
      return std::make_unique<btCylinderShapeZ>(btVector3(r, r, 0.5 * l));
  }
}

// The body's collision shape, or null; `owned` keeps every shape made. A
// wheel's is its tread (a sphere when w >= 2 r_f or when `sphere_wheels`);
// with WTC's wheels, WTC's algorithm replaces it against the terrain.
btCollisionShape* makeShape(const Body& body, bool sphere_wheels,
                            std::vector<std::unique_ptr<btCollisionShape>>& owned) {
  const auto keep = [&](std::unique_ptr<btCollisionShape> shape) { return owned.emplace_back(std::move(shape)).get(); };
  if (body.wheel) {
    const WheelGeometry& g = body.wheel->geometry;
    if (sphere_wheels || g.tread_width >= 2.0 * g.free_radius) {
      return keep(std::make_unique<btSphereShape>(g.free_radius));
    }
    int axis = 0;
    body.wheel->axle.cwiseAbs().maxCoeff(&axis);
    if (std::abs(body.wheel->axle[axis]) > 1.0 - 1e-12) return keep(cylinder(axis, g.free_radius, g.tread_width));
    // An oblique axle: a y cylinder turned onto it.
    auto compound = std::make_unique<btCompoundShape>();
    const Eigen::Matrix3d turn(Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitY(), body.wheel->axle));
    compound->addChildShape(btTransform(toBtRotation(turn)), keep(cylinder(1, g.free_radius, g.tread_width)));
    return keep(std::move(compound));
  }
  const Shape& s = body.shape;
  switch (s.kind) {
    case Shape::Kind::kBox:
      return keep(std::make_unique<btBoxShape>(toBt(Eigen::Vector3d(0.5 * s.box_size))));
    case Shape::Kind::kCylinder:
      return keep(cylinder(s.cylinder_axis, s.radius, s.length));
    case Shape::Kind::kSphere:
      return keep(std::make_unique<btSphereShape>(s.radius));
    case Shape::Kind::kNone:
      break;
  }
  return nullptr;
}

// What an engine wheel's contact needs to know of the ground (the wheel
// collider's user pointer): the Coulomb coefficient of each material.
struct EngineWheelGround {
  const TerrainObject* terrain = nullptr;
  std::vector<double> mu;  // per material id
};

// Bullet lets a collision object flagged CF_CUSTOM_MATERIAL_CALLBACK set
// the friction of each new contact point through one process-wide
// callback; only the engine wheels' colliders carry the flag. The ground's
// wrapper is the child the wheel met: a hull, or a compact field's triangle
// (TerrainObject::pieceOf).
bool engineWheelContactAdded(btManifoldPoint& point, const btCollisionObjectWrapper* a, int, int,
                             const btCollisionObjectWrapper* b, int, int) {
  const bool a_is_wheel =
      (a->getCollisionObject()->getCollisionFlags() & btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK) != 0;
  const btCollisionObjectWrapper* wheel = a_is_wheel ? a : b;
  const btCollisionObjectWrapper* ground = a_is_wheel ? b : a;
  const auto* g = static_cast<const EngineWheelGround*>(wheel->getCollisionObject()->getUserPointer());
  if (g == nullptr || ground->getCollisionObject() != &g->terrain->object()) return false;
  const Terrain& pieces = g->terrain->terrain();
  const PieceId piece = g->terrain->pieceOf(*ground);
  if (piece < 0 || piece >= static_cast<PieceId>(pieces.pieceCount())) return false;
  point.m_combinedFriction = g->mu[pieces.materialId(piece)];
  return true;
}

class SimEngine final : public sim::Engine {
 public:
  SimEngine(const sim::EngineSettings& settings, const Terrain& terrain, const vehicle::VehicleDescription& v,
            const Eigen::Isometry3d& placement)
      : sim::Engine(settings, v), refs_(v.bodies.size()) {
    world_.setGravity(btVector3(0, 0, -kGravityMps2));
    world_.getSolverInfo().m_numIterations = settings.solver_iterations;
    world_.getSolverInfo().m_leastSquaresResidualThreshold = settings.solver_residual;
    buildTrees(placement);
    plugin_ = std::make_unique<Plugin>(world_, terrain, settings.mode);
    plugin_->terrainObject().setFriction(1.0);  // combined friction = product: the bodies' own decides
    if (settings.engine_wheels != sim::EngineWheels::kNone) {
      addEngineWheels(terrain);
      return;
    }
    for (std::size_t i = 0; i < v.bodies.size(); ++i) {
      const Body& body = v.bodies[i];
      if (!body.wheel) continue;
      MultiBodyWheel wheel;
      wheel.multibody = refs_[i].multibody;
      wheel.link = refs_[i].link;
      wheel.axle_local = toBt(body.wheel->axle);
      wheel.description = sim::wheelDescription(body);
      wheel.effects = settings.tyre_effects;
      refs_[i].wheel = plugin_->addWheel(wheel);
    }
  }

  ~SimEngine() override {
    plugin_.reset();
    for (auto& c : constraints_) world_.removeMultiBodyConstraint(c.get());
    for (auto& c : colliders_) world_.removeCollisionObject(c.get());
    for (auto& mb : trees_) world_.removeMultiBody(mb.get());
  }

  void setMotorTarget(int body, const vehicle::MotorTarget& target) override {
    WarmStartedMotor* motor = refs_.at(body).motor;
    if (motor == nullptr) return;
    motor->setTarget(target.rate, target.max_effort, target.active, settings().step_seconds);
  }

  void addForce(int body, const Eigen::Vector3d& force, const Eigen::Vector3d& point) override {
    const Ref& r = refs_.at(body);
    const Eigen::Vector3d torque = (point - this->body(body).pose.translation()).cross(force);
    if (r.link < 0) {
      r.multibody->addBaseForce(toBt(force));
      r.multibody->addBaseTorque(toBt(torque));
    } else {
      r.multibody->addLinkForce(r.link, toBt(force));
      r.multibody->addLinkTorque(r.link, toBt(torque));
    }
  }

  // One internal step of exactly h (maxSubSteps = 0: Bullet's variable step).
  void step() override {
    for (WarmStartedJointLimit* limit : limits_) limit->prepare(settings().step_seconds);
    world_.stepSimulation(settings().step_seconds, 0, settings().step_seconds);
    for (Ref& r : refs_) {
      if (r.motor != nullptr) r.motor->stepped();
    }
    for (WarmStartedJointLimit* limit : limits_) limit->stepped();
    for (LinkStates& s : link_states_) s.valid = false;
    if (!engine_wheels_.empty()) readEngineWheels();
  }

  vehicle::BodyKinematics body(int body) const override {
    const Ref& r = refs_.at(body);
    const btMultiBody& mb = *r.multibody;
    vehicle::BodyKinematics k;
    if (r.link < 0) {
      k.pose.translation() = toEigen(mb.getBasePos());
      k.pose.linear() = toEigen(btMatrix3x3(mb.getWorldToBaseRot().inverse()));
      k.linear_velocity = toEigen(mb.getBaseVel());
      k.angular_velocity = toEigen(mb.getBaseOmega());
      return k;
    }
    const LinkStates& links = linkStates(r.tree);
    const btMatrix3x3& to_world = links.to_world[r.link + 1];
    k.pose.translation() = toEigen(links.origin[r.link + 1]);
    k.pose.linear() = toEigen(to_world);
    k.linear_velocity = toEigen(to_world * links.linear[r.link + 1]);
    k.angular_velocity = toEigen(to_world * links.angular[r.link + 1]);
    return k;
  }

  double jointPosition(int body) const override {
    const Ref& r = refs_.at(body);
    return hasCoordinate(body) ? r.multibody->getJointPos(r.link) : 0.0;
  }
  double jointRate(int body) const override {
    const Ref& r = refs_.at(body);
    return hasCoordinate(body) ? r.multibody->getJointVel(r.link) : 0.0;
  }
  double motorEffort(int body) const override {
    WarmStartedMotor* motor = refs_.at(body).motor;
    return motor == nullptr ? 0.0 : motor->effort();
  }
  const WheelForces& wheelForces(int body) const override {
    return engine_wheels_.empty() ? plugin_->applied(wheelId(body)) : engine_wheels_[wheelId(body)].forces();
  }
  const WheelState& wheelState(int body) const override {
    return engine_wheels_.empty() ? plugin_->state(wheelId(body)) : engine_wheels_[wheelId(body)].state();
  }
  // The engine's own wheels run no tyre model: nothing to tell.
  void setWheelListener(WheelListener* listener) override { plugin_->setListener(listener); }
  double contactSeconds() const override { return plugin_->contactSeconds(); }

 private:
  // A tree's link frames (world rotation and origin) and velocities (in
  // link frames), index 0 the base and i + 1 link i, computed once per step
  // for all its links: btMultiBody's localPosToWorld and localDirToWorld
  // walk to the base for every call.
  struct LinkStates {
    btAlignedObjectArray<btMatrix3x3> to_world;
    btAlignedObjectArray<btVector3> origin, angular, linear;
    btAlignedObjectArray<btQuaternion> world_to_local;
    bool valid = false;
  };
  const LinkStates& linkStates(int tree) const {
    LinkStates& s = link_states_[tree];
    if (s.valid) return s;
    const btMultiBody& mb = *trees_[tree];
    const int n = mb.getNumLinks() + 1;
    btAlignedObjectArray<btQuaternion>& world_to_local = s.world_to_local;
    world_to_local.resize(n);
    s.to_world.resize(n);
    s.origin.resize(n);
    s.angular.resize(n);
    s.linear.resize(n);
    // btMultiBody::updateCollisionObjectWorldTransforms' recursion.
    world_to_local[0] = mb.getWorldToBaseRot();
    s.origin[0] = mb.getBasePos();
    for (int k = 0; k + 1 < n; ++k) {
      const int parent = mb.getParent(k) + 1;
      world_to_local[k + 1] = mb.getParentToLocalRot(k) * world_to_local[parent];
      s.origin[k + 1] = s.origin[parent] + quatRotate(world_to_local[k + 1].inverse(), mb.getRVector(k));
    }
    for (int k = 0; k < n; ++k) s.to_world[k].setRotation(world_to_local[k].inverse());
    mb.compTreeLinkVelocities(&s.angular[0], &s.linear[0]);
    s.valid = true;
    return s;
  }

  struct Ref {
    btMultiBody* multibody = nullptr;
    int tree = -1;  // index in trees_
    int link = -1;  // -1: the tree's base
    WarmStartedMotor* motor = nullptr;
    btMultiBodyLinkCollider* collider = nullptr;
    WheelId wheel = -1;  // the plugin's, or with engine wheels the index in engine_wheels_
  };

  // The engine's own wheel contact (sim::EngineWheels): the wheels keep
  // their collision shapes against the terrain's hulls, with Bullet's
  // contact and Coulomb friction of the piece's mu (engineWheelContactAdded).
  void addEngineWheels(const Terrain& terrain) {
    static std::once_flag installed;
    std::call_once(installed, [] { gContactAddedCallback = engineWheelContactAdded; });
    ground_ = {.terrain = &plugin_->terrainShapes(), .mu = sim::engineWheelFrictions(terrain)};
    engine_wheels_ = sim::EngineWheelSet(vehicle());
    for (std::size_t k = 0; k < engine_wheels_.size(); ++k) {
      Ref& r = refs_[engine_wheels_.body(k)];
      r.collider->setCollisionFlags(r.collider->getCollisionFlags() | btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK);
      r.collider->setUserPointer(&ground_);
      r.wheel = static_cast<WheelId>(k);
    }
  }

  // What Bullet's solver did at each wheel-terrain point of this step: the
  // impulses it wrote back to the point (normal, and each friction
  // direction it used) over h, on the wheel.
  void readEngineWheels() {
    engine_wheels_.clear();
    const double h = settings().step_seconds;
    const bool second = (world_.getSolverInfo().m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) != 0;
    const btCollisionObject* ground = &plugin_->terrainObject();
    btDispatcher& dispatcher = *world_.getDispatcher();
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
      const btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(m);
      const bool wheel_is_a = manifold.getBody1() == ground;
      if (!wheel_is_a && manifold.getBody0() != ground) continue;
      const btCollisionObject* other = wheel_is_a ? manifold.getBody0() : manifold.getBody1();
      const auto* collider = btMultiBodyLinkCollider::upcast(other);
      if (collider == nullptr || collider->m_link < 0) continue;
      const int wheel = engineWheelOf(collider);
      if (wheel < 0) continue;
      for (int k = 0; k < manifold.getNumContacts(); ++k) {
        const btManifoldPoint& p = manifold.getContactPoint(k);
        if (p.getDistance() > 0.0 && p.m_appliedImpulse == 0.0) continue;  // kept, not touching
        btVector3 impulse_on_a =
            p.m_normalWorldOnB * p.m_appliedImpulse + p.m_lateralFrictionDir1 * p.m_appliedImpulseLateral1;
        if (second) impulse_on_a += p.m_lateralFrictionDir2 * p.m_appliedImpulseLateral2;
        const btVector3 normal = wheel_is_a ? p.m_normalWorldOnB : -p.m_normalWorldOnB;  // out of the ground
        const btVector3 point = wheel_is_a ? p.getPositionWorldOnB() : p.getPositionWorldOnA();
        engine_wheels_[wheel].add(toEigen(point), toEigen(normal), -p.getDistance(),
                                  toEigen(wheel_is_a ? impulse_on_a : -impulse_on_a) / h);
      }
    }
    engine_wheels_.finish(*this);
  }

  // The engine wheel whose collider is `collider`, or -1.
  int engineWheelOf(const btMultiBodyLinkCollider* collider) const {
    for (std::size_t k = 0; k < engine_wheels_.size(); ++k) {
      if (refs_[engine_wheels_.body(k)].collider == collider) return static_cast<int>(k);
    }
    return -1;
  }

  bool hasCoordinate(int body) const {
    const Body& b = vehicle().bodies.at(body);
    return b.parent >= 0 && (b.joint.type == JointType::kRevolute || b.joint.type == JointType::kPrismatic);
  }

  WheelId wheelId(int body) const {
    const WheelId id = refs_.at(body).wheel;
    if (id < 0) throw InvalidInputError("wtc::bullet sim engine: body " + std::to_string(body) + " is not a wheel");
    return id;
  }

  // One btMultiBody per root: its descendants are links, in body order.
  void buildTrees(const Eigen::Isometry3d& placement) {
    const std::vector<Body>& bodies = vehicle().bodies;
    std::vector<int> links_of_root(bodies.size(), 0);
    std::vector<int> root_of(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const int parent = bodies[i].parent;
      root_of[i] = parent < 0 ? static_cast<int>(i) : root_of[parent];
      if (parent >= 0) refs_[i].link = links_of_root[root_of[i]]++;
    }
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const Body& b = bodies[i];
      if (b.parent >= 0) {
        refs_[i].multibody = refs_[root_of[i]].multibody;
        refs_[i].tree = refs_[root_of[i]].tree;
        setupLink(static_cast<int>(i));
        continue;
      }
      if (b.wheel) {
        throw InvalidInputError("wtc::bullet sim engine: wheel body '" + b.name +
                                "' must hang from a parent by a joint (Bullet's WTC wheels are multibody links)");
      }
      auto mb = std::make_unique<btMultiBody>(links_of_root[i], b.mass, toBt(b.inertia), false, false);
      const Eigen::Isometry3d pose = sim::startPose(vehicle(), static_cast<int>(i), placement);
      mb->setBasePos(toBt(pose.translation()));
      mb->setWorldToBaseRot(toBtRotation(Eigen::Matrix3d(pose.linear().transpose())));
      refs_[i].multibody = mb.get();
      refs_[i].tree = static_cast<int>(trees_.size());
      trees_.push_back(std::move(mb));
    }
    link_states_.resize(trees_.size());
    for (auto& mb : trees_) {
      mb->finalizeMultiDof();
      mb->setHasSelfCollision(false);
      // No artificial damping, no clamp a robot's joints could meet.
      mb->setLinearDamping(0.0);
      mb->setAngularDamping(0.0);
      world_.addMultiBody(mb.get());
      btAlignedObjectArray<btQuaternion> rotations;
      btAlignedObjectArray<btVector3> offsets;
      mb->forwardKinematics(rotations, offsets);
    }
    for (std::size_t i = 0; i < bodies.size(); ++i) addCollider(static_cast<int>(i), placement);
  }

  void setupLink(int i) {
    const Body& b = vehicle().bodies[i];
    const Body& p = vehicle().bodies[b.parent];
    Ref& r = refs_[i];
    const int parent_link = refs_[b.parent].link;
    const Eigen::Matrix3d r_p = p.pose.linear(), r_c = b.pose.linear();
    const btQuaternion parent_to_this = toBtRotation(Eigen::Matrix3d(r_c.transpose() * r_p));
    const btVector3 parent_com_to_pivot = toBt(r_p.transpose() * (b.joint.anchor - p.pose.translation()));
    const btVector3 pivot_to_com = toBt(r_c.transpose() * (b.pose.translation() - b.joint.anchor));
    const btVector3 axis = toBt(r_c.transpose() * b.joint.axis);
    btMultiBody& mb = *r.multibody;
    switch (b.joint.type) {
      case JointType::kRevolute:
        mb.setupRevolute(r.link, b.mass, toBt(b.inertia), parent_link, parent_to_this, axis, parent_com_to_pivot,
                         pivot_to_com, true);
        break;
      case JointType::kPrismatic:
        mb.setupPrismatic(r.link, b.mass, toBt(b.inertia), parent_link, parent_to_this, axis, parent_com_to_pivot,
                          pivot_to_com, true);
        break;
      case JointType::kBall:
        mb.setupSpherical(r.link, b.mass, toBt(b.inertia), parent_link, parent_to_this, parent_com_to_pivot,
                          pivot_to_com, true);
        break;
      case JointType::kFixed:
        mb.setupFixed(r.link, b.mass, toBt(b.inertia), parent_link, parent_to_this, parent_com_to_pivot, pivot_to_com,
                      true);
        break;
    }
    if (b.joint.limits) {
      auto limit = std::make_unique<WarmStartedJointLimit>(&mb, r.link, b.joint.limits->lower, b.joint.limits->upper);
      limits_.push_back(limit.get());
      world_.addMultiBodyConstraint(limit.get());
      constraints_.push_back(std::move(limit));
    }
    if (b.joint.actuator) {
      auto motor = std::make_unique<WarmStartedMotor>(&mb, r.link);
      r.motor = motor.get();
      world_.addMultiBodyConstraint(motor.get());
      constraints_.push_back(std::move(motor));
    }
  }

  void addCollider(int i, const Eigen::Isometry3d& placement) {
    btCollisionShape* shape =
        makeShape(vehicle().bodies[i], settings().engine_wheels == sim::EngineWheels::kSphere, shapes_);
    if (shape == nullptr) return;
    Ref& r = refs_[i];
    auto collider = std::make_unique<btMultiBodyLinkCollider>(r.multibody, r.link);
    collider->setCollisionShape(shape);
    collider->setWorldTransform(toBtTransform(sim::startPose(vehicle(), i, placement)));
    collider->setFriction(sim::kBodyGroundFriction);
    // A dynamic body's filters (a plain collision object defaults to the
    // static group, which never meets the terrain).
    world_.addCollisionObject(collider.get(), btBroadphaseProxy::DefaultFilter, btBroadphaseProxy::AllFilter);
    if (r.link < 0) {
      r.multibody->setBaseCollider(collider.get());
    } else {
      r.multibody->getLink(r.link).m_collider = collider.get();
    }
    r.collider = collider.get();
    colliders_.push_back(std::move(collider));
  }

  btDefaultCollisionConfiguration config_;
  btCollisionDispatcher dispatcher_{&config_};
  btDbvtBroadphase broadphase_;
  btMultiBodyConstraintSolver solver_;
  btMultiBodyDynamicsWorld world_{&dispatcher_, &broadphase_, &solver_, &config_};
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btMultiBody>> trees_;
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders_;
  std::vector<std::unique_ptr<btMultiBodyConstraint>> constraints_;
  std::vector<WarmStartedJointLimit*> limits_;  // in constraints_
  std::vector<Ref> refs_;
  std::unique_ptr<Plugin> plugin_;
  sim::EngineWheelSet engine_wheels_;            // with sim::EngineWheels only
  EngineWheelGround ground_;                     // the engine wheels' colliders point here
  mutable std::vector<LinkStates> link_states_;  // per tree
};

}  // namespace

std::unique_ptr<sim::Engine> makeSimEngine(const sim::EngineSettings& settings, const Terrain& terrain,
                                           const vehicle::VehicleDescription& vehicle,
                                           const Eigen::Isometry3d& placement) {
  sim::validate(settings, "wtc::bullet::makeSimEngine");
  return std::make_unique<SimEngine>(settings, terrain, vehicle, placement);
}

}  // namespace wtc::bullet
