#pragma once
// wtc::ode_sim: the wtc::sim::Engine of ODE (internal; reached through the
// engine table as "ode" and "ode_quick": register.cpp). Each body is an ODE
// body, each joint the ODE joint of its type (hinge, slider, ball, fixed)
// attached (child, parent), with its travel as the joint's stops; a drive
// is a separate angular (AMotor) or linear (LMotor) motor on the same two
// bodies, so that its feedback is the drive's effort alone (a hinge's own
// motor would share its feedback with the stops and the hinge's other
// rows). Wheels are WTC wheels through wtc::ode (wtc_wheels.hpp) or ODE's
// own (native_wheels.hpp); every other body collides with the ground
// through its shape (friction kBodyGroundFriction); bodies of one vehicle do
// not collide with each other.
#include <memory>

#include "wtc/sim/engine.hpp"

namespace wtc::ode {

/// How the engine steps its world.
enum class Stepper {
  kDirect,  ///< dWorldStep: ODE's direct (Dantzig LCP) solver; "ode".
  kQuick,   ///< dWorldQuickStep: its iterative solver (solver_iterations); "ode_quick".
};

/// Builds `vehicle` (validated) on `terrain` (which must outlive the
/// engine), its frame V placed at `placement` in the world.
std::unique_ptr<sim::Engine> makeSimEngine(Stepper stepper, const sim::EngineSettings& settings, const Terrain& terrain,
                                           const vehicle::VehicleDescription& vehicle,
                                           const Eigen::Isometry3d& placement);

}  // namespace wtc::ode
