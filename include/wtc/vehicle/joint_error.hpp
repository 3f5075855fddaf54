#pragma once
// How far an engine lets a joint come apart (engine-free): what the
// vehicles issue bounds (1 mm, 0.1 deg through a scene at 0.4 ms).
//
// From the two bodies' poses alone: the joint's anchor, carried by each
// body from the reference configuration, must meet (revolute, ball,
// fixed; a prismatic joint's anchors may part along its axis only); the
// axis carried by each must agree (revolute); the relative rotation must
// stay what it was (prismatic, fixed).
#include "wtc/vehicle/hitch_law.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::vehicle {

struct JointError {
  double distance = 0.0;  ///< Anchor separation, across the axis for a prismatic joint (m).
  double angle = 0.0;     ///< Axis or orientation misalignment (rad).
};

/// The error of the joint of `vehicle.bodies[body]` (not a root) with the
/// body at `child` and its parent at `parent`.
JointError jointError(const VehicleDescription& vehicle, int body, const BodyKinematics& child,
                      const BodyKinematics& parent);

}  // namespace wtc::vehicle
