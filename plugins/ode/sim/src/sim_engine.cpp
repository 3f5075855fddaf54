// The ODE sim engine (sim_engine.hpp): bodies, joints and drives, the near
// callback, and the wheel strategy chosen once, here.
#include "sim_engine.hpp"

#include <array>
#include <mutex>
#include <optional>
#include <span>
#include <vector>

#include <ode/ode.h>
#include <ode/threading_impl.h>

#include "body_geoms.hpp"
#include "direct_step.hpp"
#include "native_wheels.hpp"
#include "sim/body_soil_shapes.hpp"
#include "sim/engine_base.hpp"
#include "sim/terrain_normal_cone.hpp"
#include "src/conversions.hpp"
#include "wtc/base/constants.hpp"
#include "wtc/base/error.hpp"
#include "wtc/ode/message_log.hpp"
#include "wtc/ode/plugin.hpp"
#include "wtc/sim/sim_constants.hpp"
#include "wtc/vehicle/drive.hpp"
#include "wtc_wheels.hpp"

namespace wtc::ode {
namespace {

using vehicle::Body;
using vehicle::JointType;
using vehicle::Shape;

// Debian's ODE is built without its thread-local storage (dGetConfiguration
// lacks ODE_EXT_ou), so two of its states are process-wide: the init counter
// of dInitODE2/dCloseODE and the seed of dRandInt, which dWorldQuickStep
// uses to reorder the constraints every 8 iterations. Engines in several
// threads (a study's parallel runs) take this lock around both, and each
// quickstep world keeps its own seed: its run is then the same whatever
// else runs beside it, in this thread or another.
std::mutex& odeGlobalsLock() {
  static std::mutex lock;
  return lock;
}

// Turns ODE's z-aligned cylinder of `geom` onto body axis `axis` (unit).
void alignCylinder(dGeomID geom, const Eigen::Vector3d& axis) {
  dMatrix3 m;
  toOde(Eigen::Matrix3d(Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis)), m);
  dGeomSetOffsetRotation(geom, m);
}

// The body's collision geom in `space`, attached to `b`, or null. A wheel's
// is its tread (a cylinder, or a sphere: sim::treadIsSphere); with WTC's
// wheels, WTC replaces it against the terrain.
dGeomID makeGeom(const Body& body, const sim::EngineSettings& settings, dSpaceID space, dBodyID b,
                 std::deque<ConvexGeomData>& convex) {
  dGeomID geom = nullptr;
  if (body.wheel) {
    const WheelGeometry& g = body.wheel->geometry;
    geom = sim::treadIsSphere(settings, g) ? dCreateSphere(space, g.free_radius)
                                           : dCreateCylinder(space, g.free_radius, g.tread_width);
    dGeomSetBody(geom, b);
    if (dGeomGetClass(geom) == dCylinderClass) alignCylinder(geom, body.wheel->axle);
    return geom;
  }
  return addBodyGeoms(body, space, b, convex);
}

// Refuses, before any ODE object exists, the mimic joints ODE cannot hold
// (SimEngine::Mimic says why): a prismatic one, one whose master hangs from
// another body, one about an axis parallel to its master's unless it turns
// with it (multiplier = the axes' cos: +1, a steering linkage).
void checkMimics(const vehicle::VehicleDescription& v) {
  for (const Body& b : v.bodies) {
    if (b.parent < 0 || !b.joint.mimic) continue;
    const vehicle::Mimic& mimic = *b.joint.mimic;
    const Body& master = v.bodies[mimic.master];
    const std::string name = "wtc::ode sim engine: mimic joint '" + b.joint.name + "' (body '" + b.name + "')";
    if (b.joint.type != JointType::kRevolute || master.joint.type != JointType::kRevolute) {
      throw InvalidInputError(name + ": ODE holds a mimic between two revolute joints only");
    }
    if (b.parent != master.parent) {
      throw InvalidInputError(name + " and its master '" + master.joint.name +
                              "' hang from different bodies: ODE holds a mimic between two joints of one parent only");
    }
    const double c = b.joint.axis.dot(master.joint.axis);
    if (std::abs(c) > 1.0 - sim::kMimicParallelCos && std::abs(mimic.multiplier - c) > sim::kMimicParallelMultiplier) {
      throw InvalidInputError(name + " and its master '" + master.joint.name +
                              "' turn about parallel axes with multiplier " + formatNumber(mimic.multiplier) +
                              ": that ties three bodies, which ODE's two-body joints cannot hold (Bullet can: a "
                              "gear constraint on one multibody); ODE holds parallel axes with multiplier " +
                              formatNumber(c > 0.0 ? 1.0 : -1.0) + " (the two turn together, a steering linkage)");
    }
  }
}

class SimEngine final : public sim::EngineBase {
 public:
  SimEngine(Stepper stepper, const sim::EngineSettings& settings, const Terrain& terrain,
            const vehicle::VehicleDescription& v, const Eigen::Isometry3d& placement)
      : sim::EngineBase("wtc::ode sim engine", settings, v),
        terrain_(terrain),
        stepper_(stepper),
        refs_(v.bodies.size()) {
    checkMimics(v);
    {
      const std::lock_guard<std::mutex> lock(odeGlobalsLock());
      dInitODE2(0);  // counted: matched by dCloseODE in the destructor
    }
    world_ = dWorldCreate();
    // A world steps through a threading implementation; without one of its
    // own it uses ODE's process-wide default, whose wake-up flags two worlds
    // stepping in two threads trip over (an assertion in WaitWakeup).
    threading_ = dThreadingAllocateSelfThreadedImplementation();
    dWorldSetStepThreadingImplementation(world_, dThreadingImplementationGetFunctions(threading_), threading_);
    dWorldSetGravity(world_, 0, 0, -kGravityMps2);
    dWorldSetQuickStepNumIterations(world_, settings.solver_iterations);
    // A simple space: a vehicle's dozen geoms and the terrain's space are
    // tested pair by pair (under a hundred box tests), where a hash space
    // allocates a vector of boxes at every dSpaceCollide.
    space_ = dSimpleSpaceCreate(nullptr);
    contacts_ = dJointGroupCreate(0);
    plugin_ = std::make_unique<Plugin>(world_, space_, terrain, settings.mode);
    for (std::size_t i = 0; i < v.bodies.size(); ++i) buildBody(static_cast<int>(i), placement);
    for (std::size_t i = 0; i < v.bodies.size(); ++i) {
      if (v.bodies[i].parent >= 0 && v.bodies[i].joint.mimic) buildMimic(static_cast<int>(i));
    }
    // The wheels' strategy, chosen once: ODE's own, or WTC's.
    std::vector<WheelBody> wheels;
    for (const int body : v.wheels()) wheels.push_back({refs_[body].body, refs_[body].geom});
    if (settings.native_wheels) {
      wheels_ =
          std::make_unique<NativeWheels>(*this, *plugin_, world_, contacts_, terrain, wheels, *settings.native_wheels);
    } else {
      wheels_ = std::make_unique<WtcWheels>(*plugin_, v, wheels, settings.tyre_effects, contacts_);
    }
    useWheels(*wheels_);
    for (sim::SoilBodyShape& soil : sim::soilBodyShapes(settings, terrain, v)) {
      plugin_->addSoilBody({.body = refs_[soil.body].body, .hulls = std::move(soil.hulls)});
    }
    if (stepper_ == Stepper::kDirect) makeDirectStepper();
    // Room for every body touching a few pieces at once: a step's body
    // contacts are then noted without allocating (step_allocation_test).
    constexpr std::size_t kPiecesPerBody = 4;
    body_contacts_.reserve(refs_.size() * kPiecesPerBody * kMaxContactsPerPair);
    duplicate_contacts_.reserve(body_contacts_.capacity());
  }

  ~SimEngine() override {
    wheels_.reset();
    plugin_.reset();  // its terrain space lives in space_
    dJointGroupDestroy(contacts_);
    dSpaceDestroy(space_);  // destroys the bodies' geoms (cleanup mode on)
    dWorldDestroy(world_);  // and the bodies and joints
    dThreadingFreeImplementation(threading_);
    const std::lock_guard<std::mutex> lock(odeGlobalsLock());
    dCloseODE();
  }

  void setMotorTarget(int body, const vehicle::MotorTarget& target) override {
    Ref& r = refs_.at(body);
    if (r.wheel_drive) {
      r.target = target;
      return;
    }
    if (r.motor == nullptr) return;
    const bool angular = dJointGetType(r.motor) == dJointTypeAMotor;
    const auto set = angular ? dJointSetAMotorParam : dJointSetLMotorParam;
    set(r.motor, dParamVel, target.rate);
    set(r.motor, dParamFMax, target.active ? target.max_effort : 0.0);
  }

  void addForce(int body, const Eigen::Vector3d& force, const Eigen::Vector3d& point) override {
    dBodyAddForceAtPos(refs_.at(body).body, force.x(), force.y(), force.z(), point.x(), point.y(), point.z());
  }

  // Each body's velocity as given: ODE's joints hold the bodies together
  // from the next step on, and take their rates from them.
  void setVelocities(std::span<const sim::BodyVelocity> velocities) override {
    requireOnePerBody(velocities.size());
    for (std::size_t i = 0; i < velocities.size(); ++i) {
      const sim::BodyVelocity& v = velocities[i];
      dBodySetLinearVel(refs_[i].body, v.linear.x(), v.linear.y(), v.linear.z());
      dBodySetAngularVel(refs_[i].body, v.angular.x(), v.angular.y(), v.angular.z());
    }
  }

  GroundMemory* groundMemory() const override {
    return plugin_->groundMemory().regionCount() > 0 ? &plugin_->groundMemory() : nullptr;
  }

  void setGravity(const Eigen::Vector3d& g_W) override { dWorldSetGravity(world_, g_W.x(), g_W.y(), g_W.z()); }

  void step() override {
    const double h = settings().step_seconds;
    // ODE's messages of this step (its LCP giving up) are counted, not printed.
    const std::uint64_t messages_before = messages_.total();
    const MessageLog::Capture capture(messages_);
    plugin_->beginStep(h);
    body_contacts_.clear();
    duplicate_contacts_.clear();
    dSpaceCollide(space_, this, &SimEngine::nearCallback);
    for (Ref& r : refs_) {
      if (r.wheel_drive) driveWheel(r, h);
    }
    for (const Mimic& m : mimics_) holdMimic(m, h);
    if (stepper_ == Stepper::kQuick) {
      quickStep(h);
    } else {
      direct_->step(h, messages_, duplicate_contacts_);  // a solve ODE gave up on is done again (direct_step.hpp)
    }
    dJointGroupEmpty(contacts_);
    wheels_->stepped();
    ++steps_;
    if (messages_.total() != messages_before) noteMessageStep();
  }

  vehicle::BodyKinematics body(int body) const override {
    const dBodyID b = refs_.at(body).body;
    vehicle::BodyKinematics k;
    k.pose.translation() = toEigen(dBodyGetPosition(b));
    k.pose.linear() = rotationFromOde(dBodyGetRotation(b));
    k.linear_velocity = toEigen(dBodyGetLinearVel(b));
    k.angular_velocity = toEigen(dBodyGetAngularVel(b));
    return k;
  }

  double jointPosition(int body) const override {
    const dJointID j = refs_.at(body).joint;
    if (j == nullptr) return 0.0;
    switch (dJointGetType(j)) {
      case dJointTypeHinge:
        return dJointGetHingeAngle(j);
      case dJointTypeSlider:
        return dJointGetSliderPosition(j);
      default:
        return 0.0;
    }
  }
  double jointRate(int body) const override {
    const dJointID j = refs_.at(body).joint;
    if (j == nullptr) return 0.0;
    switch (dJointGetType(j)) {
      case dJointTypeHinge:
        return dJointGetHingeAngleRate(j);
      case dJointTypeSlider:
        return dJointGetSliderPositionRate(j);
      default:
        return 0.0;
    }
  }
  // The motor's force or torque on the child along the joint's axis.
  double motorEffort(int body) const override {
    const Ref& r = refs_.at(body);
    if (r.wheel_drive) return r.effort;
    return r.motor == nullptr ? 0.0 : motorForce(r.motor, r.feedback);
  }
  std::vector<sim::SolverMessage> solverMessages() const override {
    std::vector<sim::SolverMessage> said;
    for (std::size_t k = 0; k < messages_.counts().size(); ++k) {
      const MessageCount& m = messages_.counts()[k];
      said.push_back({.engine = "ODE",
                      .text = m.text,
                      .steps = message_steps_[k].steps,
                      .count = m.count,
                      .first_time_s = static_cast<double>(message_steps_[k].first) * settings().step_seconds});
    }
    return said;
  }

 private:
  struct Ref {
    dBodyID body = nullptr;
    dGeomID geom = nullptr;
    dJointID joint = nullptr;  // to the parent
    dJointID motor = nullptr;  // the drive, if any
    dJointFeedback feedback{};
    bool wheel_drive = false;     // solved here (driveWheel), not a motor row in ODE's solver
    double spin_inertia = 0.0;    // the wheel's moment about its axle (kg m^2)
    vehicle::MotorTarget target;  // the wheel drive's, this step
    double effort = 0.0;          // the wheel drive's torque, this step (N m)
  };

  void quickStep(double h) {
    const std::lock_guard<std::mutex> lock(odeGlobalsLock());
    dRandSetSeed(quickstep_seed_);
    dWorldQuickStep(world_, h);
    quickstep_seed_ = dRandGetSeed();
  }

  // dWorldStep with what it needs to solve a step again: every body, the
  // joints with stops (a resting one can make its LCP give up) and the
  // drives (solved first without their caps: drive_rows.hpp).
  void makeDirectStepper() {
    std::vector<dBodyID> bodies;
    std::vector<StoppedJoint> stopped;
    DriveRows drives;
    for (std::size_t i = 0; i < refs_.size(); ++i) {
      bodies.push_back(refs_[i].body);
      if (refs_[i].motor != nullptr) drives.add(refs_[i].motor, &refs_[i].feedback);
      const Body& b = vehicle().bodies[i];
      if (b.parent < 0 || !b.joint.limits) continue;
      if (b.joint.type == JointType::kRevolute || b.joint.type == JointType::kPrismatic) {
        stopped.push_back({.joint = refs_[i].joint, .lower = b.joint.limits->lower, .upper = b.joint.limits->upper});
      }
    }
    direct_ = std::make_unique<DirectStepper>(world_, std::move(bodies), std::move(stopped), std::move(drives),
                                              [this](double h) { quickStep(h); });
  }

  // In how many steps each message of messages_ came, and the first (1 the
  // engine's first step); called after a step in which some came.
  void noteMessageStep() {
    message_steps_.resize(messages_.counts().size());
    for (std::size_t k = 0; k < message_steps_.size(); ++k) {
      MessageSteps& m = message_steps_[k];
      if (messages_.counts()[k].count == m.seen) continue;
      m.seen = messages_.counts()[k].count;
      ++m.steps;
      if (m.first == 0) m.first = steps_;
    }
  }

  // A wheel's drive in force mode (vehicle::wheelDriveTorque): WTC has put
  // the tyre's forces on the wheel by now (beginStep), so the torque that
  // holds the wheel's rate is known before the step, and the wheels'
  // one-row motors, each a pivot of ODE's direct solver, leave its LCP
  // (what that saves: docs/vehicles-and-scenes.md, Speed).
  void driveWheel(Ref& r, double h) {
    dVector3 a;
    dJointGetHingeAxis(r.joint, a);
    const Eigen::Vector3d axis = toEigen(a);
    const double tau_axle = toEigen(dBodyGetTorque(r.body)).dot(axis);
    r.effort = vehicle::wheelDriveTorque(r.target, dJointGetHingeAngleRate(r.joint), tau_axle, r.spin_inertia, h);
    const Eigen::Vector3d t = r.effort * axis;
    dBodyAddTorque(r.body, t.x(), t.y(), t.z());
    dBodyAddTorque(dJointGetBody(r.joint, 1), -t.x(), -t.y(), -t.z());
  }

  void buildBody(int i, const Eigen::Isometry3d& placement) {
    const Body& b = vehicle().bodies[i];
    Ref& r = refs_[i];
    r.body = dBodyCreate(world_);
    dMass m;
    dMassSetParameters(&m, b.mass, 0, 0, 0, b.inertia.x(), b.inertia.y(), b.inertia.z(), 0, 0, 0);
    dBodySetMass(r.body, &m);
    const Eigen::Isometry3d pose = sim::startPose(vehicle(), i, placement);
    dBodySetPosition(r.body, pose.translation().x(), pose.translation().y(), pose.translation().z());
    dMatrix3 rotation;
    toOde(pose.linear(), rotation);
    dBodySetRotation(r.body, rotation);
    r.geom = makeGeom(b, settings(), space_, r.body, convex_);
    if (b.parent >= 0) buildJoint(i, placement);
  }

  // The joint to the parent, at the start pose (where its coordinate is 0).
  void buildJoint(int i, const Eigen::Isometry3d& placement) {
    const Body& b = vehicle().bodies[i];
    Ref& r = refs_[i];
    const dBodyID parent = refs_[b.parent].body;
    const Eigen::Vector3d anchor = placement * b.joint.anchor;
    const Eigen::Vector3d axis = placement.linear() * b.joint.axis;
    switch (b.joint.type) {
      case JointType::kRevolute:
        r.joint = dJointCreateHinge(world_, nullptr);
        dJointAttach(r.joint, r.body, parent);
        dJointSetHingeAnchor(r.joint, anchor.x(), anchor.y(), anchor.z());
        dJointSetHingeAxis(r.joint, axis.x(), axis.y(), axis.z());
        if (b.joint.limits) {
          dJointSetHingeParam(r.joint, dParamLoStop, b.joint.limits->lower);
          dJointSetHingeParam(r.joint, dParamHiStop, b.joint.limits->upper);
        }
        break;
      case JointType::kPrismatic:
        r.joint = dJointCreateSlider(world_, nullptr);
        dJointAttach(r.joint, r.body, parent);
        dJointSetSliderAxis(r.joint, axis.x(), axis.y(), axis.z());
        if (b.joint.limits) {
          dJointSetSliderParam(r.joint, dParamLoStop, b.joint.limits->lower);
          dJointSetSliderParam(r.joint, dParamHiStop, b.joint.limits->upper);
        }
        break;
      case JointType::kBall:
        r.joint = dJointCreateBall(world_, nullptr);
        dJointAttach(r.joint, r.body, parent);
        dJointSetBallAnchor(r.joint, anchor.x(), anchor.y(), anchor.z());
        break;
      case JointType::kFixed:
        r.joint = dJointCreateFixed(world_, nullptr);
        dJointAttach(r.joint, r.body, parent);
        dJointSetFixed(r.joint);
        break;
    }
    if (!b.joint.actuator) return;
    if (solvesWheelDrive(i)) {
      r.wheel_drive = true;
      r.spin_inertia = sim::wheelDescription(b).inertia.axial_inertia;
      return;
    }
    // The drive: off until the first command.
    if (b.joint.type == JointType::kRevolute) {
      r.motor = dJointCreateAMotor(world_, nullptr);
      dJointAttach(r.motor, r.body, parent);
      dJointSetAMotorMode(r.motor, dAMotorUser);
      dJointSetAMotorNumAxes(r.motor, 1);
      dJointSetAMotorAxis(r.motor, 0, 1, axis.x(), axis.y(), axis.z());  // rel 1: fixed in the child
      dJointSetAMotorParam(r.motor, dParamFMax, 0.0);
    } else {
      r.motor = dJointCreateLMotor(world_, nullptr);
      dJointAttach(r.motor, r.body, parent);
      dJointSetLMotorNumAxes(r.motor, 1);
      dJointSetLMotorAxis(r.motor, 0, 1, axis.x(), axis.y(), axis.z());
      dJointSetLMotorParam(r.motor, dParamFMax, 0.0);
    }
    dJointSetFeedback(r.motor, &r.feedback);
  }

  static void nearCallback(void* data, dGeomID a, dGeomID b) {
    SimEngine& e = *static_cast<SimEngine*>(data);
    if (e.wheels_->collide(a, b)) return;  // the wheels' pairs: WTC's, or ODE's own wheels
    // A body against the whole terrain: WTC's index says in a few hundred
    // nanoseconds whether any piece is near it, where ODE's quadtree walk
    // costs microseconds per body even when none is.
    const dSpaceID terrain = e.plugin_->terrainGeoms().space();
    if (a == reinterpret_cast<dGeomID>(terrain) || b == reinterpret_cast<dGeomID>(terrain)) {
      if (!e.nearTerrain(a == reinterpret_cast<dGeomID>(terrain) ? b : a)) return;
    }
    if (dGeomIsSpace(a) || dGeomIsSpace(b)) {
      dSpaceCollide2(a, b, data, &SimEngine::nearCallback);
      return;
    }
    const dBodyID body_a = dGeomGetBody(a), body_b = dGeomGetBody(b);
    // Terrain against terrain, or two bodies of the vehicle: nothing.
    if ((body_a == nullptr) == (body_b == nullptr)) return;
    std::array<dContact, kMaxContactsPerPair> contact{};
    int n = dCollide(a, b, kMaxContactsPerPair, &contact[0].geom, sizeof(dContact));
    n = e.plugin_->keepRigidContacts(a, b, &contact[0].geom, n, sizeof(dContact));  // a belly on soil: the soil's
    const bool on_field = e.plugin_->terrainGeoms().isField(body_a != nullptr ? b : a);
    for (int k = 0; k < n; ++k) {
      if (on_field && !e.onFieldSurface(contact[k].geom, body_a != nullptr ? a : b, body_a != nullptr)) continue;
      contact[k].surface.mode = dContactApprox1;
      contact[k].surface.mu = sim::kBodyGroundFriction;
      const dJointID joint = dJointCreateContact(e.world_, e.contacts_, &contact[k]);
      dJointAttach(joint, body_a, body_b);
      e.noteBodyContact(joint, body_a, body_b, contact[k].geom);
    }
  }

  // Gives a body's contact with a heightfield a normal the field's surface
  // can push along (terrain_normal_cone.hpp), or false when there is none: a
  // wall between two of its prisms is no part of the surface. ODE's normal
  // points into the first geom of the pair.
  bool onFieldSurface(dContactGeom& g, dGeomID body, bool body_first) {
    const double sign = body_first ? 1.0 : -1.0;
    const Eigen::Vector3d p_W = toEigen(g.pos), n_W = sign * toEigen(g.normal);
    const std::optional<Eigen::Vector3d> surface = normal_cone_.normal(p_W, n_W, g.depth, placedShape(body));
    if (!surface) return false;
    if (*surface != n_W) {
      for (int i = 0; i < 3; ++i) g.normal[i] = sign * (*surface)[i];
    }
    return true;
  }

  // Keeps this step's body contacts, and marks `joint` as a duplicate when
  // it repeats an earlier one of the same bodies (sim::kDuplicateContactM):
  // left out of a step only if ODE's direct solver gives up (direct_step.hpp).
  void noteBodyContact(dJointID joint, dBodyID a, dBodyID b, const dContactGeom& g) {
    const Eigen::Vector3d p = toEigen(g.pos), n = toEigen(g.normal);
    for (const BodyContact& c : body_contacts_) {
      if (c.a == a && c.b == b && (c.point - p).norm() <= sim::kDuplicateContactM &&
          c.normal.dot(n) >= 1.0 - sim::kDuplicateContactCos) {
        duplicate_contacts_.push_back(joint);
        return;
      }
    }
    body_contacts_.push_back({.a = a, .b = b, .point = p, .normal = n});
  }

  // A mimic joint (URDF's <mimic>: q = k q_master + offset) as a one-axis
  // angular motor between the two joints' child bodies
  // (docs/rocker-bogie-rover.md, "The differential"). With a and b the two
  // hinges' world axes, c = a . b, and both hinges on one parent body P,
  // (w_1 - w_P) = qdot_1 a and (w_2 - w_P) = qdot_2 b, so along
  //   n = ((k c - 1) a + (c - k) b) / (c^2 - 1)
  // (w_1 - w_2) . n = qdot_1 - k qdot_2: P's rotation cancels and the
  // motor, holding that rate at 0, holds the mimic (n = a + k b for
  // perpendicular axes). n is fixed in neither body: set every step. Two
  // parallel axes (b = c a, c = +-1) give (w_1 - w_2) . a = qdot_1 - c qdot_2:
  // with k = c (a steering linkage's 1), n = a holds the mimic; with another
  // k, P stays in the rate (three bodies), which a joint between two bodies
  // cannot hold: refused, as are mimics across parents or of a prismatic
  // joint.
  struct Mimic {
    dJointID motor = nullptr;
    int body = -1;    // the mimic joint's child
    int master = -1;  // the master joint's child
    double multiplier = 1.0;
    double offset = 0.0;
  };

  void buildMimic(int i) {
    const vehicle::Mimic& mimic = *vehicle().bodies[i].joint.mimic;
    Mimic m{.motor = dJointCreateAMotor(world_, nullptr),
            .body = i,
            .master = mimic.master,
            .multiplier = mimic.multiplier,
            .offset = mimic.offset};
    dJointAttach(m.motor, refs_[i].body, refs_[mimic.master].body);
    dJointSetAMotorMode(m.motor, dAMotorUser);
    dJointSetAMotorNumAxes(m.motor, 1);
    dJointSetAMotorParam(m.motor, dParamFMax, dInfinity);
    mimics_.push_back(m);
    holdMimic(m, settings().step_seconds);
  }

  // The motor's axis for this step, and its rate: 0 plus the position
  // error fed back, -erp (q - k q_master - offset) / h (a motor corrects
  // no drift of its own).
  void holdMimic(const Mimic& m, double h) {
    dVector3 a_ode, b_ode;
    const dJointID joint = refs_[m.body].joint, master = refs_[m.master].joint;
    dJointGetHingeAxis(joint, a_ode);
    dJointGetHingeAxis(master, b_ode);
    const Eigen::Vector3d a = toEigen(a_ode), b = toEigen(b_ode);
    const double c = a.dot(b), k = m.multiplier;
    const Eigen::Vector3d n =
        std::abs(c) > 1.0 - sim::kMimicParallelCos ? a : Eigen::Vector3d(((k * c - 1.0) * a + (c - k) * b) / (c * c - 1.0));
    dJointSetAMotorAxis(m.motor, 0, 0, n.x(), n.y(), n.z());
    const double error = dJointGetHingeAngle(joint) - k * dJointGetHingeAngle(master) - m.offset;
    dJointSetAMotorParam(m.motor, dParamVel, -sim::kMimicErp * error / h);
  }

  // Whether any terrain piece's box overlaps the geom's (or the space's) box.
  bool nearTerrain(dGeomID geom) {
    dReal box[6];
    dGeomGetAABB(geom, box);
    const Aabb aabb{.min = {box[0], box[2], box[4]}, .max = {box[1], box[3], box[5]}};
    near_pieces_.clear();
    terrain_.overlapping(aabb, near_pieces_);
    return !near_pieces_.empty();
  }

  const Terrain& terrain_;
  sim::TerrainNormalCone normal_cone_{terrain_};  // the body contacts' normals against a heightfield's surface
  Stepper stepper_;
  std::vector<PieceId> near_pieces_;  // scratch
  dWorldID world_ = nullptr;
  dThreadingImplementationID threading_ = nullptr;  // this world's own (see the constructor)
  unsigned long quickstep_seed_ = 0;                // this world's dRandInt stream (see odeGlobalsLock)
  dSpaceID space_ = nullptr;
  dJointGroupID contacts_ = nullptr;
  std::unique_ptr<Plugin> plugin_;
  std::vector<Ref> refs_;
  std::vector<Mimic> mimics_;
  std::deque<ConvexGeomData> convex_;      // what the bodies' convex geoms point into
  std::unique_ptr<OdeWheels> wheels_;      // WtcWheels or NativeWheels
  std::unique_ptr<DirectStepper> direct_;  // Stepper::kDirect's
  struct BodyContact {
    dBodyID a, b;
    Eigen::Vector3d point, normal;
  };
  std::vector<BodyContact> body_contacts_;    // this step's body-ground contacts (scratch)
  std::vector<dJointID> duplicate_contacts_;  // those of this step's that repeat one of them
  MessageLog messages_;                       // ODE's messages in this engine's steps
  struct MessageSteps {
    std::uint64_t seen = 0;   // messages_.counts()[k].count after the last step that had it
    std::uint64_t steps = 0;  // steps that had it
    std::uint64_t first = 0;  // the first of them (1: the engine's first step)
  };
  std::vector<MessageSteps> message_steps_;  // parallel to messages_.counts()
  std::uint64_t steps_ = 0;                  // steps so far
};

}  // namespace

std::unique_ptr<sim::Engine> makeSimEngine(Stepper stepper, const sim::EngineSettings& settings, const Terrain& terrain,
                                           const vehicle::VehicleDescription& vehicle,
                                           const Eigen::Isometry3d& placement) {
  sim::validate(settings, "wtc::ode::makeSimEngine");
  return std::make_unique<SimEngine>(stepper, settings, terrain, vehicle, placement);
}

}  // namespace wtc::ode
