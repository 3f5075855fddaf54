// The per-wheel step both engine adapters run (design note in
// src/adapter/mounted_wheel.hpp).
#include "mounted_wheel.hpp"

#include <string>

#include "wtc/base/error.hpp"
#include "base/scratch_capacity.hpp"

namespace wtc {

MountedWheel::MountedWheel(const WheelDescription& description, EffectSet effects, ContactMode mode)
    : description_(description), model_(effects, mode) {
  validate(description_, "wtc::MountedWheel");
  contacts_.reserve(kReservedContacts);
  solved_contacts_.reserve(kReservedContacts);
}

const MountedWheelStep& MountedWheel::step(const Terrain& terrain, const WheelPose& pose, const WheelMotion& motion,
                                           double h) {
  const WheelForces& f = model_.stepInEngine(terrain, description_, pose, motion, h, state_);
  contacts_.clear();  // keeps its capacity: no allocation once warm
  step_ = MountedWheelStep{};
  pose_ = pose;
  solved_valid_ = false;
  step_.skipped = state_.lastStepSkipped();
  if (step_.skipped) return step_;
  if (model_.mode() == ContactMode::kForce) {
    step_.force = f.force;
    step_.torque = f.torque;
  } else {
    for (const ContactForce& c : f.contacts) {
      contacts_.push_back(toSolverContact(c, description_.tyre, model_, rest_load_));
    }
    step_.torque = f.rolling_moment;
    step_.contacts = contacts_;
  }
  return step_;
}

// Each contact's force R = -R_z e + R_xy as the solver applied it, at the
// model's P; the wrench about O splits as in wheel_forces.hpp.
void MountedWheel::setSolvedForces(std::span<const Eigen::Vector3d> forces) {
  const WheelForces& model = this->forces();
  if (forces.size() != model.contacts.size()) {
    throw InvalidInputError("wtc::MountedWheel::setSolvedForces: " + std::to_string(forces.size()) + " forces for " +
                            std::to_string(model.contacts.size()) + " contacts");
  }
  solved_contacts_.assign(model.contacts.begin(), model.contacts.end());
  const Eigen::Vector3d a = pose_.axle.normalized();
  Eigen::Vector3d total = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < forces.size(); ++i) {
    ContactForce& c = solved_contacts_[i];
    const Eigen::Vector3d& e = c.contact.e;
    c.force = forces[i];
    c.normal_force = -forces[i].dot(e);
    c.tangential_force = forces[i] + c.normal_force * e;
    c.mu = c.normal_force > 0.0 ? c.tangential_force.norm() / c.normal_force : 0.0;
    total += c.force;
    moment += (c.contact.point - pose_.center).cross(c.force);
  }
  solved_ = model;
  solved_.contacts = solved_contacts_;
  solved_.force = total;
  solved_.torque = moment + model.rolling_moment;
  solved_.axial_moment = a * a.dot(moment) + model.rolling_moment;
  solved_.bearing_moment = moment - a * a.dot(moment);
  solved_valid_ = true;
}

void MountedWheel::tell(WheelListener* listener, WheelId id, double h) const {
  if (listener == nullptr) return;
  if (step_.skipped) {
    listener->onWheelSkipped(id, h);
    return;
  }
  listener->onWheelStep(id, forces(), h);
  if (state_.firstUnstableStep()) listener->onFirstUnstableStep(id, forces().normal_stability);
}

}  // namespace wtc
