// The per-wheel step both engine adapters run (design note in
// include/wtc/mounted_wheel.hpp).
#include "wtc/mounted_wheel.hpp"

#include "wtc/scratch_capacity.hpp"

namespace wtc {

MountedWheel::MountedWheel(const WheelDescription& description, EffectSet effects, ContactMode mode)
    : description_(description), model_(effects, mode) {
  validate(description_, "wtc::MountedWheel");
  contacts_.reserve(kReservedContacts);
}

const MountedWheelStep& MountedWheel::step(const Terrain& terrain, const WheelPose& pose, const WheelMotion& motion,
                                           double h) {
  const WheelForces& f = model_.stepInEngine(terrain, description_, pose, motion, h, state_);
  contacts_.clear();  // keeps its capacity: no allocation once warm
  step_ = MountedWheelStep{};
  step_.skipped = state_.lastStepSkipped();
  if (step_.skipped) return step_;
  if (model_.mode() == ContactMode::kForce) {
    step_.force = f.force;
    step_.torque = f.torque;
  } else {
    for (const ContactForce& c : f.contacts) contacts_.push_back(toEngineContact(c, description_.tyre, model_));
    step_.torque = f.rolling_moment;
    step_.contacts = contacts_;
  }
  return step_;
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
