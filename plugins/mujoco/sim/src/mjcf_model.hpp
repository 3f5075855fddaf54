#pragma once
// A vehicle and its terrain as a MuJoCo model, written as MJCF in memory and
// compiled by MuJoCo (internal to wtc::mujoco_sim). Design note:
//
// Each vehicle body is a MuJoCo body whose frame is the body's centre-of-
// mass frame (Body::pose, which the engine integrates), nested under its
// parent at the start pose (sim::startPose), with its mass and principal
// moments as <inertial>. A root has a free joint; a revolute, prismatic or
// ball joint is MuJoCo's hinge, slide or ball at the anchor, with its travel
// as range; a fixed joint welds the body to its parent (no joint). A mimic
// joint is an <equality><joint> with polycoef (offset, multiplier). A drive
// is its joint's friction row (frictionloss, a velocity target set each
// step: sim_engine.cpp), not an actuator.
//
// The ground is the world body's: each stored terrain piece a convex mesh
// geom, each compact heightfield one MuJoCo height field, each compact
// mesh's triangles their prisms. Collision bits keep contacts to body-ground
// pairs: ground geoms contype 1 conaffinity 0, body geoms contype 0
// conaffinity 1; a WTC wheel's geom (which its contacts name) collides with
// nothing. Friction: a body geom's kBodyGroundFriction by priority 1; a
// native wheel's geom (friction 0) takes the ground geom's, the peak of its
// material's mu(s) (sim::nativeWheelFrictions).
#include <memory>
#include <vector>

#include <mujoco/mujoco.h>
#include <Eigen/Geometry>

#include "wtc/sim/engine.hpp"
#include "wtc/terrain/terrain.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::mujoco {

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};

/// The compiled model and where each vehicle body went.
struct VehicleModel {
  std::unique_ptr<mjModel, ModelDeleter> model;
  std::vector<int> body;        ///< Per vehicle body: its MuJoCo body id.
  std::vector<int> dof;         ///< Per vehicle body: its joint's first dof (a root's free joint's), or -1.
  std::vector<int> qpos;        ///< Per vehicle body: its joint's first qpos address, or -1.
  std::vector<int> wheel_geom;  ///< Per vehicle body: a wheel's tread geom, or -1.
};

/// Throws InvalidInputError naming the problem: a heightfield with holes
/// (MuJoCo's height fields have none), what MuJoCo's compiler refuses (its
/// message, with the body or piece).
VehicleModel buildVehicleModel(const sim::EngineSettings& settings, const Terrain& terrain,
                               const vehicle::VehicleDescription& vehicle, const Eigen::Isometry3d& placement);

}  // namespace wtc::mujoco
