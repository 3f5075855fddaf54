#pragma once
// wtc::mujoco_sim: the wtc::sim::Engine of MuJoCo (internal; reached through
// the engine table as "mujoco": register.cpp). The vehicle and the terrain
// become one MuJoCo model (mjcf_model.hpp); a step is MuJoCo's Euler step
// run stage by stage (src/euler_stages.hpp) with WTC's part at its hooks:
//  - after mj_collision, constraint mode's contacts (Plugin::addContacts);
//  - after mj_fwdVelocity, force mode's tyre wrench (Plugin::applyForces),
//    a force-mode wheel drive in closed form (vehicle::wheelDriveTorque, as
//    qfrc_applied on its hinge), and each other drive's velocity target:
//    a drive is its joint's friction row (dof_frictionloss = the drive's
//    effort cap, a direct solref with B = 1 / h and impedance
//    kDriveImpedance), whose reference acceleration -v / h becomes
//    -(v - target) / h: MuJoCo's solver then holds the target rate within
//    the cap, implicitly, as ODE's and Bullet's motors do (an actuator's
//    explicit velocity servo would need gains the 0.4 ms step cannot keep
//    stable for a 1500 N m fold drive);
//  - after mj_fwdConstraint, the forces MuJoCo applied at WTC's contacts
//    and the drives' efforts (their rows' efc_force).
// Implicit mode is not served (engine table: MuJoCo 2.2.2's friction rows
// take no target velocity). With the soft_soil effect, every body with a
// shape is the plugin's soil body (sim::soilBodyShapes), as in Bullet and
// ODE: its contacts on soil pieces are dropped after mj_collision.
#include <memory>

#include <Eigen/Geometry>

#include "wtc/sim/engine.hpp"
#include "wtc/terrain/terrain.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::mujoco {

/// Builds `vehicle` (validated) on `terrain` (which must outlive the
/// engine), its frame V placed at `placement` in the world.
std::unique_ptr<sim::Engine> makeSimEngine(const sim::EngineSettings& settings, const Terrain& terrain,
                                           const vehicle::VehicleDescription& vehicle,
                                           const Eigen::Isometry3d& placement);

}  // namespace wtc::mujoco
