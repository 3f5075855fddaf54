// ODE's direct step that never keeps a step its LCP gave up on
// (direct_step.hpp has the design note).
#include "direct_step.hpp"

#include <cstdint>
#include <utility>

namespace wtc::ode {
namespace {

std::array<dReal, 3> copy3(const dReal* v) { return {v[0], v[1], v[2]}; }

bool isHinge(dJointID joint) { return dJointGetType(joint) == dJointTypeHinge; }

// The joint's coordinate and rate as ODE's stop sees them (its getInfo1
// tests dJointGetHingeAngle / dJointGetSliderPosition against the stops).
double position(dJointID joint) { return isHinge(joint) ? dJointGetHingeAngle(joint) : dJointGetSliderPosition(joint); }
double rate(dJointID joint) {
  return isHinge(joint) ? dJointGetHingeAngleRate(joint) : dJointGetSliderPositionRate(joint);
}
void setStop(dJointID joint, int parameter, double value) {
  if (isHinge(joint)) {
    dJointSetHingeParam(joint, parameter, value);
  } else {
    dJointSetSliderParam(joint, parameter, value);
  }
}

}  // namespace

DirectStepper::DirectStepper(dWorldID world, std::vector<dBodyID> bodies, std::vector<StoppedJoint> stopped,
                             DriveRows drives, std::function<void(double)> quick_step)
    : world_(world),
      bodies_(std::move(bodies)),
      stopped_(std::move(stopped)),
      drives_(std::move(drives)),
      quick_step_(std::move(quick_step)),
      saved_(bodies_.size()) {
  released_.reserve(stopped_.size());
}

DirectStepOutcome DirectStepper::step(double h, MessageLog& log, std::span<const dJointID> duplicate_contacts) {
  save();
  if (drives_.release()) {
    const bool gave_up = gaveUp(h, drives_said_);
    const bool within = drives_.restore();  // every cap back in place
    if (!gave_up && within) {
      drives_.noteCaps(h);
      return DirectStepOutcome::kSolved;
    }
    restore();
  }
  const DirectStepOutcome outcome = solveCapped(h, log, duplicate_contacts);
  drives_.noteCaps(h);
  return outcome;
}

// The step with every drive's cap, as dWorldStep alone would solve it, and
// again where ODE gave up (direct_step.hpp's 1. and 2.).
DirectStepOutcome DirectStepper::solveCapped(double h, MessageLog& log, std::span<const dJointID> duplicate_contacts) {
  if (!gaveUp(h, attempt_)) return DirectStepOutcome::kSolved;
  restore();
  if (!released_.empty() || !duplicate_contacts.empty()) {
    setResting(true);
    for (const dJointID j : duplicate_contacts) dJointDisable(j);
    const bool again = gaveUp(h, retry_);
    setResting(false);
    for (const dJointID j : duplicate_contacts) dJointEnable(j);
    retry_.clear();
    if (!again) {
      attempt_.clear();
      return DirectStepOutcome::kDegenerateRowsLeftOut;
    }
    restore();
  }
  // The first solve's messages are the step's: the rows ODE zeroed are now
  // solved by quickstep, but its direct solver did give up on this step.
  log.merge(attempt_);
  attempt_.clear();
  quick_step_(h);
  return DirectStepOutcome::kQuickStep;
}

bool DirectStepper::gaveUp(double h, MessageLog& said) {
  const std::uint64_t before = said.total();
  {
    const MessageLog::Capture capture(said);
    dWorldStep(world_, h);
  }
  return said.total() != before;
}

// dWorldStep clears the force and torque accumulators and moves the
// bodies: all of it is put back before a step is solved again. Contact
// joints and the drives' settings are the world's and unchanged by a step.
void DirectStepper::save() {
  findRestingStops();
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const dBodyID b = bodies_[i];
    BodyState& s = saved_[i];
    s.position = copy3(dBodyGetPosition(b));
    const dReal* q = dBodyGetQuaternion(b);
    s.quaternion = {q[0], q[1], q[2], q[3]};
    s.linear_velocity = copy3(dBodyGetLinearVel(b));
    s.angular_velocity = copy3(dBodyGetAngularVel(b));
    s.force = copy3(dBodyGetForce(b));
    s.torque = copy3(dBodyGetTorque(b));
  }
}

void DirectStepper::restore() {
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const dBodyID b = bodies_[i];
    const BodyState& s = saved_[i];
    dBodySetPosition(b, s.position[0], s.position[1], s.position[2]);
    dBodySetQuaternion(b, s.quaternion.data());
    dBodySetLinearVel(b, s.linear_velocity[0], s.linear_velocity[1], s.linear_velocity[2]);
    dBodySetAngularVel(b, s.angular_velocity[0], s.angular_velocity[1], s.angular_velocity[2]);
    dBodySetForce(b, s.force[0], s.force[1], s.force[2]);
    dBodySetTorque(b, s.torque[0], s.torque[1], s.torque[2]);
  }
}

// Exactly on the stop and exactly at rest against it: the only case in
// which ODE's stop row has rhs 0 and starts Dantzig's solve at w = 0. Read
// before the step (save): the restored bodies need not be bit for bit the
// same (dBodySetQuaternion normalises).
void DirectStepper::findRestingStops() {
  released_.clear();
  for (const StoppedJoint& j : stopped_) {
    if (rate(j.joint) != 0.0) continue;
    const double q = position(j.joint);
    if (q == j.lower) {
      released_.push_back({j.joint, dParamLoStop, j.lower});
    } else if (q == j.upper) {
      released_.push_back({j.joint, dParamHiStop, j.upper});
    }
  }
}

void DirectStepper::setResting(bool released) {
  for (const ReleasedStop& r : released_) {
    const double open = r.parameter == dParamLoStop ? -dInfinity : dInfinity;
    setStop(r.joint, r.parameter, released ? open : r.value);
  }
}

}  // namespace wtc::ode
