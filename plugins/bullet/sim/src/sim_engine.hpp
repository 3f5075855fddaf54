#pragma once
// wtc::bullet_sim: the wtc::sim::Engine of Bullet (internal; reached through
// the engine table as "bullet": register.cpp). Each vehicle tree is a
// btMultiBody (reduced coordinates: joints hold exactly, as the robot's
// must), in a btMultiBodyDynamicsWorld; wheels are WTC wheels through
// wtc::bullet (wtc_wheels.hpp) or Bullet's own (native_wheels.hpp); drives
// are btMultiBodyJointMotor (an implicit velocity motor capped at the
// drive's effort; warm_started_motor.hpp), but a WTC wheel's in force mode,
// solved in closed form through the plugin's post-wheels callback
// (vehicle::wheelDriveTorque, as ODE's sim engine does), travel limits
// btMultiBodyJointLimitConstraint. Bodies of
// one tree do not collide with each other; every other body collides with
// the ground through its shape (friction kBodyGroundFriction).
#include <memory>

#include "wtc/sim/engine.hpp"

namespace wtc::bullet {

/// Builds `vehicle` (validated) on `terrain` (which must outlive the
/// engine), its frame V placed at `placement` in the world. Throws
/// InvalidInputError naming the body for what Bullet cannot build (a wheel
/// without a parent joint).
std::unique_ptr<sim::Engine> makeSimEngine(const sim::EngineSettings& settings, const Terrain& terrain,
                                           const vehicle::VehicleDescription& vehicle,
                                           const Eigen::Isometry3d& placement);

}  // namespace wtc::bullet
