#pragma once
// The vehicle-level effects a scene switches on or off (wtc::vehicle), kept
// apart from the tyre's wtc::Effect: what the drives and the hitch do, not
// what a wheel's contact computes.
namespace wtc::vehicle {

struct VehicleEffects {
  /// Drives hold their commands within their rated effort and speed, and
  /// saturation is counted (off: ideal drives, travel still limited).
  bool actuator_limits = true;
  /// The hitch's damping term mu dDelta/dt (off: the spring alone).
  bool hitch_damping = true;
};

}  // namespace wtc::vehicle
