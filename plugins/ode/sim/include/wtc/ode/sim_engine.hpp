#pragma once
// wtc::ode_sim: the wtc::sim::Engine of ODE. Each body is an ODE body,
// each joint the ODE joint of its type (hinge, slider, ball, fixed) attached
// (child, parent), with its travel as the joint's stops; a drive is a
// separate angular (AMotor) or linear (LMotor) motor on the same two bodies,
// so that its feedback is the drive's effort alone (a hinge's own motor
// would share its feedback with the stops and the hinge's other rows).
// Wheels are WTC wheels through wtc::ode; every other body collides with the
// ground through its shape (friction kBodyGroundFriction); bodies of one
// vehicle do not collide with each other. EngineKind::kOde steps with
// dWorldStep, kOdeQuick with dWorldQuickStep.
#include <memory>

#include "wtc/sim/engine.hpp"

namespace wtc::ode {

/// Builds `vehicle` (validated) on `terrain` (which must outlive the
/// engine), its frame V placed at `placement` in the world.
std::unique_ptr<sim::Engine> makeSimEngine(const sim::EngineSettings& settings, const Terrain& terrain,
                                           const vehicle::VehicleDescription& vehicle,
                                           const Eigen::Isometry3d& placement);

}  // namespace wtc::ode
