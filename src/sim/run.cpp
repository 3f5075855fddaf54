#include "wtc/sim/run.hpp"

#include <algorithm>
#include <cmath>

#include "base/scratch_capacity.hpp"
#include "wtc/base/constants.hpp"
#include "wtc/sim/sim_constants.hpp"

namespace wtc::sim {
namespace {

bool finite(const vehicle::BodyKinematics& k) {
  return k.pose.matrix().allFinite() && k.linear_velocity.allFinite() && k.angular_velocity.allFinite();
}

bool beyondBounds(const vehicle::BodyKinematics& k) {
  return k.linear_velocity.norm() > kDivergedSpeedMps || k.angular_velocity.norm() > kDivergedAngularSpeedRadps ||
         k.pose.translation().norm() > kDivergedDistanceM;
}

}  // namespace

Run::Run(Engine& engine, vehicle::Controller* controller, const vehicle::VehicleEffects& effects,
         const std::optional<Drawbar>& drawbar)
    : engine_(engine),
      controller_(controller),
      effects_(effects),
      actuated_(engine.vehicle().actuated()),
      energy_(engine.vehicle(), engine.settings().step_seconds) {
  const std::size_t n = engine.vehicle().bodies.size();
  state_.bodies.resize(n);
  state_.joint_position.resize(n);
  state_.joint_rate.resize(n);
  state_.wheels.resize(n);
  wheel_forces_.resize(n, nullptr);
  for (const int w : engine.vehicle().wheels()) state_.wheels[w].points.reserve(kReservedContacts);
  commands_.resize(n);
  targets_.resize(n);
  drives_.resize(n);
  sense();
  energy_.start(state_);  // the balance counts the first step (a kick in it)
  if (drawbar) {
    drawbar_.emplace(*drawbar, engine.vehicle(), state_.bodies.at(drawbar->body), "drawbar");
    drawbar_force_ = drawbar_->force(state_.bodies[drawbar->body], state_.time);
  }
}

void Run::step() {
  const vehicle::VehicleDescription& v = engine_.vehicle();
  if (controller_ != nullptr) controller_->update(state_, commands_);
  for (const int b : actuated_) {
    const vehicle::Joint& joint = v.bodies[b].joint;
    targets_[b] = vehicle::motorTarget(*joint.actuator, joint.limits, commands_[b], state_.joint_position[b],
                                       effects_.actuator_limits);
    engine_.setMotorTarget(b, targets_[b]);
  }
  if (v.hitch) {
    const vehicle::Hitch& h = *v.hitch;
    hitch_ = vehicle::hitchForce(h, state_.bodies[h.body_a], state_.bodies[h.body_b], effects_.hitch_damping);
    engine_.addForce(h.body_b, hitch_->force_on_b, hitch_->point_b);
    engine_.addForce(h.body_a, -hitch_->force_on_b, hitch_->point_a);
  }
  if (drawbar_) {
    drawbar_force_ = drawbar_->force(state_.bodies[drawbar_->body()], state_.time);
    engine_.addForce(drawbar_->body(), drawbar_force_->force_W, drawbar_force_->point_W);
  }
  engine_.step();
  ++steps_;
  state_.time = static_cast<double>(steps_) * engine_.settings().step_seconds;
  for (const int b : actuated_) vehicle::record(drives_[b], targets_[b], engine_.motorEffort(b));
  sense();
  // The rig's work of the step, with the point's velocity after it (as the
  // drives': EnergyBalance).
  double rig_work = 0.0;
  if (drawbar_) {
    const vehicle::BodyKinematics& k = state_.bodies[drawbar_->body()];
    const Eigen::Vector3d v_P =
        k.linear_velocity + k.angular_velocity.cross(drawbar_force_->point_W - k.pose.translation());
    rig_work = drawbar_force_->force_W.dot(v_P) * engine_.settings().step_seconds;
  }
  energy_.step(state_, wheel_forces_, drives_, rig_work);
}

void Run::setGravity(const Eigen::Vector3d& g_W) {
  engine_.setGravity(g_W);
  energy_.setGravity(g_W, state_);
}

void Run::sense() {
  const vehicle::VehicleDescription& v = engine_.vehicle();
  for (std::size_t i = 0; i < v.bodies.size(); ++i) {
    const int b = static_cast<int>(i);
    state_.bodies[i] = engine_.body(b);
    non_finite_ = non_finite_ || !finite(state_.bodies[i]);
    diverged_ = diverged_ || beyondBounds(state_.bodies[i]);
    state_.joint_position[i] = engine_.jointPosition(b);
    state_.joint_rate[i] = engine_.jointRate(b);
    if (!v.bodies[i].wheel) continue;
    // Read once a step: the controller, the recorder, the replay and the
    // summary all take the wheel's forces from here (Run::wheelForces).
    wheel_forces_[i] = &engine_.wheelForces(b);
    const WheelForces& f = *wheel_forces_[i];
    vehicle::WheelSensor& s = state_.wheels[i];
    s.contacts = static_cast<int>(f.contacts.size());
    s.force = f.force;
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    s.points.clear();  // keeps its capacity: no allocation once warm
    for (const ContactForce& c : f.contacts) {
      normal -= c.normal_force * c.contact.e;  // e points into the ground
      s.points.push_back({.point = c.contact.ground_point, .normal = -c.contact.e, .load = c.normal_force});
      max_deflection_ = std::max(max_deflection_, c.contact.deflection);
    }
    s.contact_normal = normal.norm() > 0.0 ? Eigen::Vector3d(normal.normalized()) : Eigen::Vector3d::UnitZ();
  }
  for (std::size_t i = 0; i < v.bodies.size(); ++i) {
    if (v.bodies[i].parent < 0) continue;
    const vehicle::JointError e =
        vehicle::jointError(v, static_cast<int>(i), state_.bodies[i], state_.bodies[v.bodies[i].parent]);
    max_joint_error_.distance = std::max(max_joint_error_.distance, e.distance);
    max_joint_error_.angle = std::max(max_joint_error_.angle, e.angle);
  }
}

}  // namespace wtc::sim
