// The per-wheel step both engine adapters run (design note in
// src/adapter/mounted_wheel.hpp).
#include "mounted_wheel.hpp"

#include <string>

#include "base/scratch_capacity.hpp"
#include "wtc/base/error.hpp"

namespace wtc {
namespace {

// In the engine-solved modes every contact is a row but one on soft soil
// with no sinkage to make a spring of; what a soft-soil contact's row does
// not carry is applied explicitly: its shear, or all of it without a row.
bool hasRow(const ContactForce& c) { return !c.soft_soil || c.soil_stiffness > 0.0; }

Eigen::Vector3d explicitForce(const ContactForce& c) { return hasRow(c) ? c.tangential_force : c.force; }

}  // namespace

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
    // A contact becomes a row; on soft soil the row carries the normal and
    // the rest of its force (the shear; all of it with no sinkage to make a
    // spring of) joins the explicit rolling moment as a wrench about O.
    step_.torque = f.rolling_moment;
    const double r = description_.geometry.free_radius;
    for (const ContactForce& c : f.contacts) {
      if (c.soft_soil) {
        const Eigen::Vector3d explicit_part = explicitForce(c);
        step_.force += explicit_part;
        step_.torque += (r * c.contact.e).cross(explicit_part);
      }
      if (hasRow(c)) contacts_.push_back(toSolverContact(c, description_.tyre, model_, rest_load_));
    }
    step_.contacts = contacts_;
  }
  return step_;
}

// Each row's force R = -R_z e + R_xy as the solver applied it, at the
// model's P, plus the part of a soft-soil contact's force applied
// explicitly (about O at r e). The wrench about O splits as in wheel_forces.hpp.
void MountedWheel::setSolvedForces(std::span<const Eigen::Vector3d> forces) {
  const WheelForces& model = this->forces();
  if (forces.size() != contacts_.size()) {
    throw InvalidInputError("wtc::MountedWheel::setSolvedForces: " + std::to_string(forces.size()) + " forces for " +
                            std::to_string(contacts_.size()) + " contacts");
  }
  solved_contacts_.assign(model.contacts.begin(), model.contacts.end());
  const Eigen::Vector3d a = pose_.axle.normalized();
  const double r = description_.geometry.free_radius;
  Eigen::Vector3d total = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  std::size_t row = 0;
  for (ContactForce& c : solved_contacts_) {
    const Eigen::Vector3d& e = c.contact.e;
    if (hasRow(c)) {
      c.force = forces[row++];
      moment += (c.contact.point - pose_.center).cross(c.force);
    } else {
      c.force.setZero();
    }
    if (c.soft_soil) {
      const Eigen::Vector3d explicit_part = explicitForce(c);
      c.force += explicit_part;
      moment += (r * e).cross(explicit_part);
    }
    c.normal_force = -c.force.dot(e);
    c.tangential_force = c.force + c.normal_force * e;
    c.mu = c.normal_force > 0.0 ? c.tangential_force.norm() / c.normal_force : 0.0;
    total += c.force;
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
