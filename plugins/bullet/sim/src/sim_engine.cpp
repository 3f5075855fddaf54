// The Bullet sim engine (sim_engine.hpp): vehicle trees as multibodies,
// their drives and limits, and the wheel strategy chosen once, here.
#include "sim_engine.hpp"

#include <algorithm>
#include <limits>
#include <span>
#include <vector>

#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyGearConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <btBulletDynamicsCommon.h>

#include "body_hull.hpp"
#include "joint_row.hpp"
#include "native_wheels.hpp"
#include "sim/body_soil_shapes.hpp"
#include "sim/engine_base.hpp"
#include "src/conversions.hpp"
#include "src/plugin_state.hpp"
#include "warm_started_joint_limit.hpp"
#include "warm_started_motor.hpp"
#include "wheel_drive_responses.hpp"
#include "wtc/base/constants.hpp"
#include "wtc/base/error.hpp"
#include "wtc/bullet/contact_solver.hpp"
#include "wtc/bullet/frictionless_contact_solver.hpp"
#include "wtc/bullet/plugin.hpp"
#include "wtc/bullet/terrain_object.hpp"
#include "wtc/sim/sim_constants.hpp"
#include "wtc/vehicle/drive.hpp"
#include "wtc_wheels.hpp"

namespace wtc::bullet {
namespace {

using vehicle::Body;
using vehicle::JointType;
using vehicle::Shape;

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

// One shape (box, cylinder, sphere, convex hull) centred and aligned in its
// own frame, or null for kNone; `keep` owns it.
template <class Keep>
btCollisionShape* partShape(const Shape& s, Keep& keep) {
  switch (s.kind) {
    case Shape::Kind::kBox:
      return keep(std::make_unique<btBoxShape>(toBt(Eigen::Vector3d(0.5 * s.box_size))));
    case Shape::Kind::kCylinder:
      return keep(cylinder(s.cylinder_axis, s.radius, s.length));
    case Shape::Kind::kSphere:
      return keep(std::make_unique<btSphereShape>(s.radius));
    case Shape::Kind::kHull:
      return keep(makeBodyHull(s.hull_vertices));
    case Shape::Kind::kNone:
      break;
  }
  return nullptr;
}

// The body's collision shape, or null; `owned` keeps every shape made. A
// wheel's is its tread (a cylinder, or a sphere: sim::treadIsSphere); with
// WTC's wheels, WTC's algorithm replaces it against the terrain.
btCollisionShape* makeShape(const Body& body, const sim::EngineSettings& settings,
                            std::vector<std::unique_ptr<btCollisionShape>>& owned) {
  const auto keep = [&](std::unique_ptr<btCollisionShape> shape) { return owned.emplace_back(std::move(shape)).get(); };
  if (body.wheel) {
    const WheelGeometry& g = body.wheel->geometry;
    if (sim::treadIsSphere(settings, g)) {
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
  if (!body.compound.empty()) {
    // Several parts, each at its pose in the body (centre-of-mass) frame.
    auto compound = std::make_unique<btCompoundShape>();
    for (const vehicle::ShapePart& part : body.compound) {
      btTransform pose(toBtRotation(Eigen::Matrix3d(part.pose_BS.linear())), toBt(part.pose_BS.translation()));
      compound->addChildShape(pose, partShape(part.shape, keep));
    }
    return keep(std::move(compound));
  }
  return partShape(body.shape, keep);
}

// Implicit mode's tread rows follow their contacts' normal impulses
// (ContactSolver, which the plugin requires for it). Constraint mode's WTC
// contacts carry no friction of their own (WheelFrictionConstraint's rows
// do): FrictionlessContactSolver makes them no friction rows, the same
// solution without two dead rows per contact, and starts their normal rows
// from the last step's impulses (fewer sweeps to the same residual). Force
// mode keeps Bullet's own solver.
std::unique_ptr<btMultiBodyConstraintSolver> makeSolver(ContactMode mode) {
  if (mode == ContactMode::kImplicit) return std::make_unique<ContactSolver>(true);
  if (mode == ContactMode::kConstraint) return std::make_unique<FrictionlessContactSolver>(true);
  return std::make_unique<btMultiBodyConstraintSolver>();
}

class SimEngine final : public sim::EngineBase {
 public:
  SimEngine(const sim::EngineSettings& settings, const Terrain& terrain, const vehicle::VehicleDescription& v,
            const Eigen::Isometry3d& placement)
      : sim::EngineBase("wtc::bullet sim engine", settings, v),
        solver_(makeSolver(settings.mode)),
        world_(&dispatcher_, &broadphase_, solver_.get(), &config_),
        refs_(v.bodies.size()) {
    world_.setGravity(btVector3(0, 0, -kGravityMps2));
    world_.getSolverInfo().m_numIterations = settings.solver_iterations;
    world_.getSolverInfo().m_leastSquaresResidualThreshold = settings.solver_residual;
    buildTrees(placement);
    shareWheelDriveSolves();
    plugin_ = std::make_unique<Plugin>(world_, terrain, settings.mode);
    plugin_->terrainObject().setFriction(1.0);  // combined friction = product: the bodies' own decides
    // The wheels' strategy, chosen once: Bullet's own, or WTC's.
    std::vector<WheelLink> links;
    for (const int body : v.wheels()) links.push_back({refs_[body].multibody, refs_[body].link, refs_[body].collider});
    if (settings.native_wheels) {
      wheels_ = std::make_unique<NativeWheels>(*this, *plugin_, world_, terrain, links, *settings.native_wheels);
    } else {
      wheels_ = std::make_unique<WtcWheels>(*plugin_, v, links, settings.tyre_effects);
    }
    useWheels(*wheels_);
    const std::vector<int> wheels = v.wheels();
    for (std::size_t k = 0; k < wheels.size(); ++k) {
      if (refs_[wheels[k]].wheel_drive) driven_wheels_.push_back({.body = wheels[k], .wheel = static_cast<WheelId>(k)});
    }
    if (!driven_wheels_.empty()) plugin_->setPostWheelsCallback([this](double h) { driveWheels(h); });
    for (sim::SoilBodyShape& soil : sim::soilBodyShapes(settings, terrain, v)) {
      const Ref& r = refs_[soil.body];
      plugin_->addSoilBody({.multibody = r.multibody, .link = r.link, .hulls = std::move(soil.hulls)});
    }
  }

  ~SimEngine() override {
    wheels_.reset();
    plugin_.reset();
    for (auto& c : constraints_) world_.removeMultiBodyConstraint(c.get());
    for (auto& c : colliders_) world_.removeCollisionObject(c.get());
    for (auto& mb : trees_) world_.removeMultiBody(mb.get());
  }

  void setMotorTarget(int body, const vehicle::MotorTarget& target) override {
    Ref& r = refs_.at(body);
    if (r.wheel_drive) {
      r.target = target;
      return;
    }
    WarmStartedMotor* motor = r.motor;
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

  GroundMemory* groundMemory() const override {
    return plugin_->groundMemory().regionCount() > 0 ? &plugin_->groundMemory() : nullptr;
  }

  void setGravity(const Eigen::Vector3d& g_W) override { world_.setGravity(toBt(g_W)); }

  // One internal step of exactly h (maxSubSteps = 0: Bullet's variable step).
  void step() override {
    for (WarmStartedJointLimit* limit : limits_) limit->prepare(settings().step_seconds);
    drive_responses_.forget();
    world_.stepSimulation(settings().step_seconds, 0, settings().step_seconds);
    for (Ref& r : refs_) {
      if (r.motor != nullptr) r.motor->stepped();
    }
    for (WarmStartedJointLimit* limit : limits_) limit->stepped();
    for (LinkFrames& f : link_frames_) f.valid = false;
    wheels_->stepped();
  }

  // The roots' velocities as given; each link's joint rate from its
  // velocity against its parent's (btMultiBody's joint velocities: a
  // revolute or prismatic joint's rate along its axis, a spherical joint's
  // relative angular velocity in the link's frame).
  void setVelocities(std::span<const sim::BodyVelocity> velocities) override {
    requireOnePerBody(velocities.size());
    const std::vector<Body>& bodies = vehicle().bodies;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const Ref& r = refs_[i];
      const sim::BodyVelocity& v = velocities[i];
      if (r.link < 0) {
        r.multibody->setBaseVel(toBt(v.linear));
        r.multibody->setBaseOmega(toBt(v.angular));
        continue;
      }
      const int parent = bodies[i].parent;
      const sim::BodyVelocity& p = velocities[parent];
      const Eigen::Matrix3d R_WC = body(static_cast<int>(i)).pose.linear();
      const Eigen::Vector3d r_PC = body(static_cast<int>(i)).pose.translation() - body(parent).pose.translation();
      const Eigen::Vector3d w_rel = v.angular - p.angular;
      const Eigen::Vector3d v_rel = v.linear - p.linear - p.angular.cross(r_PC);
      const btMultibodyLink& link = r.multibody->getLink(r.link);
      switch (bodies[i].joint.type) {
        case JointType::kRevolute:
          r.multibody->setJointVel(r.link, w_rel.dot(R_WC * toEigen(link.getAxisTop(0))));
          break;
        case JointType::kPrismatic:
          r.multibody->setJointVel(r.link, v_rel.dot(R_WC * toEigen(link.getAxisBottom(0))));
          break;
        case JointType::kBall: {
          const Eigen::Vector3d w_C = R_WC.transpose() * w_rel;
          btScalar rates[3] = {w_C.x(), w_C.y(), w_C.z()};
          r.multibody->setJointVelMultiDof(r.link, rates);
          break;
        }
        case JointType::kFixed:
          break;
      }
    }
    // The plugin's cache of link velocities was read at the start pose.
    for (LinkVelocities& lv : detail::PluginState::of(*plugin_).link_velocities) lv.valid = false;
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
    const LinkFrames& frames = linkFrames(r.tree);
    const LinkVelocities& velocities = detail::PluginState::of(*plugin_).linkVelocities(mb);
    const btMatrix3x3& to_world = frames.to_world[r.link + 1];
    k.pose.translation() = toEigen(frames.origin[r.link + 1]);
    k.pose.linear() = toEigen(to_world);
    k.linear_velocity = toEigen(to_world * velocities.linear[r.link + 1]);
    k.angular_velocity = toEigen(to_world * velocities.angular[r.link + 1]);
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
    const Ref& r = refs_.at(body);
    if (r.wheel_drive) return r.effort;
    return r.motor == nullptr ? 0.0 : r.motor->effort();
  }

 private:
  // A tree's link frames (world rotation and origin), index 0 the base and
  // i + 1 link i, computed once per step for all its links: btMultiBody's
  // localPosToWorld and localDirToWorld walk to the base for every call.
  // Their velocities are the plugin's (LinkVelocities, one cache for both).
  struct LinkFrames {
    btAlignedObjectArray<btMatrix3x3> to_world;
    btAlignedObjectArray<btVector3> origin;
    btAlignedObjectArray<btQuaternion> world_to_local;
    bool valid = false;
  };
  const LinkFrames& linkFrames(int tree) const {
    LinkFrames& s = link_frames_[tree];
    if (s.valid) return s;
    const btMultiBody& mb = *trees_[tree];
    const int n = mb.getNumLinks() + 1;
    btAlignedObjectArray<btQuaternion>& world_to_local = s.world_to_local;
    world_to_local.resize(n);
    s.to_world.resize(n);
    s.origin.resize(n);
    // btMultiBody::updateCollisionObjectWorldTransforms' recursion.
    world_to_local[0] = mb.getWorldToBaseRot();
    s.origin[0] = mb.getBasePos();
    for (int k = 0; k + 1 < n; ++k) {
      const int parent = mb.getParent(k) + 1;
      world_to_local[k + 1] = mb.getParentToLocalRot(k) * world_to_local[parent];
      s.origin[k + 1] = s.origin[parent] + quatRotate(world_to_local[k + 1].inverse(), mb.getRVector(k));
    }
    for (int k = 0; k < n; ++k) s.to_world[k].setRotation(world_to_local[k].inverse());
    s.valid = true;
    return s;
  }

  struct Ref {
    btMultiBody* multibody = nullptr;
    int tree = -1;  // index in trees_
    int link = -1;  // -1: the tree's base
    WarmStartedMotor* motor = nullptr;
    btMultiBodyLinkCollider* collider = nullptr;
    bool wheel_drive = false;     // solved in closed form (driveWheels), not a motor row in Bullet's solver
    double spin_inertia = 0.0;    // the wheel's moment about its axle (kg m^2)
    vehicle::MotorTarget target;  // the wheel drive's, this step
    double effort = 0.0;          // the wheel drive's torque, this step (N m)
  };
  struct DrivenWheel {
    int body = -1;
    WheelId wheel = -1;  // the plugin's
  };

  // The wheels' drives in force mode (vehicle::wheelDriveTorque), in the
  // plugin's post-wheels callback: the tyre's wrench of the step is on each
  // wheel by then, so the torque that holds the wheel's rate is known
  // before the step, and the drive needs no row of Bullet's solver (ODE's
  // sim engine solves its wheels' drives by the same law).
  void driveWheels(double h) {
    for (const DrivenWheel& d : driven_wheels_) {
      Ref& r = refs_[d.body];
      const double tau_axle = plugin_->axleTorque(d.wheel);
      r.effort = vehicle::wheelDriveTorque(r.target, r.multibody->getJointVel(r.link), tau_axle, r.spin_inertia, h);
      plugin_->addAxleTorque(d.wheel, r.effort);
    }
  }

  bool hasCoordinate(int body) const {
    const Body& b = vehicle().bodies.at(body);
    return b.parent >= 0 && (b.joint.type == JointType::kRevolute || b.joint.type == JointType::kPrismatic);
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
    link_frames_.resize(trees_.size());
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
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      if (bodies[i].parent >= 0 && bodies[i].joint.mimic) addMimic(static_cast<int>(i));
    }
  }

  // A mimic joint (URDF's <mimic>: q = k q_master + offset) as a gear
  // constraint between two joint coordinates of one multibody. Its row is
  // qdot_A + ratio qdot_B = 0 with the position error q_A + ratio q_B -
  // target fed back (btMultiBodyGearConstraint.cpp): A the mimic joint's
  // link, B the master's, ratio = -k, target = offset. It reads B's
  // coordinate through A's multibody, so both must be one tree.
  // Bullet's gear filed on the multibody's island (islandOf), as the
  // drives and limits are: its own rule takes the links' colliders, and a
  // mimic joint's link without one (a knuckle) would be solved never.
  class MimicGear final : public btMultiBodyGearConstraint {
   public:
    using btMultiBodyGearConstraint::btMultiBodyGearConstraint;
    int getIslandIdA() const override { return islandOf(*m_bodyA); }
    int getIslandIdB() const override { return islandOf(*m_bodyB); }
  };

  void addMimic(int i) {
    const Body& b = vehicle().bodies[i];
    const vehicle::Mimic& mimic = *b.joint.mimic;
    const Ref& a = refs_[i];
    const Ref& m = refs_[mimic.master];
    if (a.multibody != m.multibody) {
      throw InvalidInputError("wtc::bullet sim engine: mimic joint '" + b.joint.name + "' (body '" + b.name +
                              "') and its master are in two trees: a gear constraint ties one multibody's joints");
    }
    auto gear = std::make_unique<MimicGear>(a.multibody, a.link, m.multibody, m.link,
                                                            btVector3(0, 0, 0), btVector3(0, 0, 0),
                                                            btMatrix3x3::getIdentity(), btMatrix3x3::getIdentity());
    gear->setGearRatio(-mimic.multiplier);
    gear->setRelativePositionTarget(mimic.offset);
    gear->setErp(sim::kMimicErp);
    gear->setMaxAppliedImpulse(sim::kMimicMaxImpulse);
    world_.addMultiBodyConstraint(gear.get());
    constraints_.push_back(std::move(gear));
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
    if (solvesWheelDrive(i)) {
      r.wheel_drive = true;
      r.spin_inertia = sim::wheelDescription(b).inertia.axial_inertia;
    } else if (b.joint.actuator) {
      auto motor = std::make_unique<WarmStartedMotor>(&mb, r.link);
      r.motor = motor.get();
      world_.addMultiBodyConstraint(motor.get());
      constraints_.push_back(std::move(motor));
    }
  }

  // The wheels' drives that are rows (constraint and implicit modes): two
  // on one parent share one articulated-body solve a step
  // (wheel_drive_responses.hpp).
  void shareWheelDriveSolves() {
    const std::vector<Body>& bodies = vehicle().bodies;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const Ref& r = refs_[i];
      if (bodies[i].wheel && r.motor != nullptr && WheelDriveResponses::applies(*r.multibody, r.link)) {
        r.motor->shareResponses(&drive_responses_);
      }
    }
  }

  void addCollider(int i, const Eigen::Isometry3d& placement) {
    btCollisionShape* shape = makeShape(vehicle().bodies[i], settings(), shapes_);
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
  std::unique_ptr<btMultiBodyConstraintSolver> solver_;
  btMultiBodyDynamicsWorld world_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btMultiBody>> trees_;
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders_;
  WheelDriveResponses drive_responses_;  // the wheel drives' shared solves; outlives the motors
  std::vector<std::unique_ptr<btMultiBodyConstraint>> constraints_;
  std::vector<WarmStartedJointLimit*> limits_;  // in constraints_
  std::vector<Ref> refs_;
  std::vector<DrivenWheel> driven_wheels_;  // the bodies whose drive driveWheels solves
  std::unique_ptr<Plugin> plugin_;
  std::unique_ptr<sim::WheelContacts> wheels_;   // WtcWheels or NativeWheels
  mutable std::vector<LinkFrames> link_frames_;  // per tree
};

}  // namespace

std::unique_ptr<sim::Engine> makeSimEngine(const sim::EngineSettings& settings, const Terrain& terrain,
                                           const vehicle::VehicleDescription& vehicle,
                                           const Eigen::Isometry3d& placement) {
  sim::validate(settings, "wtc::bullet::makeSimEngine");
  return std::make_unique<SimEngine>(settings, terrain, vehicle, placement);
}

}  // namespace wtc::bullet
