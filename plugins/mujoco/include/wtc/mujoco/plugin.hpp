#pragma once
// wtc::mujoco: WTC wheels in a user's own MuJoCo model (mjModel / mjData,
// MuJoCo 2.2.2 as Debian ships it). The adapter does nothing physical
// itself: it reads each wheel body's pose and velocity from mjData, asks the
// core (wtc::TyreModel, one step per wheel per MuJoCo step), and hands the
// wrench back to MuJoCo. docs/mujoco-plugin.md has the details.
//
// How a program steps (force mode), instead of mj_step(m, d):
//
//      plugin.step(m, d);
//
// which is MuJoCo's own two halves with the wheels between them:
//
//      mj_step1(m, d);            // positions, velocities: xpos, xmat, xipos, cvel of this step
//      plugin.applyForces(m, d);  // every wheel's tyre model; its wrench added to xfrc_applied
//      mj_step2(m, d);            // actuation, acceleration (xfrc_applied at the COM), constraints, integration
//      plugin.clearForces(d);     // the wrench taken back out of xfrc_applied
//
// so a user's own xfrc_applied on a wheel body is kept, and the wrench acts
// on exactly this step. mj_step1 + mj_step2 is mj_step, stage for stage,
// for the Euler and implicit integrators: with no wheels, plugin.step(m, d)
// equals mj_step(m, d) bit for bit (tests/mujoco). RK4 is refused: its
// mj_step2 integrates by Euler, and its four stages would each need the
// tyre model.
//
// MuJoCo's own collisions: the wheels' contact is WTC's. A wheel body's
// geoms must not also meet the ground in MuJoCo (addWheel refuses a geom
// whose contype / conaffinity bits, or a <pair>, would collide it with a
// geom of the world body): give them contype="0" conaffinity="0", or bits
// the ground lacks. The terrain for the wheels is the WTC terrain given
// here, which the model's own ground (for the other bodies) should match.
//
// No global callback (mjcb_passive, mjcb_control) is taken.
//
// Constraint mode (ContactMode::kConstraint): WTC's contacts go into
// mjData's contact list between mj_collision and mj_makeConstraint, and
// MuJoCo's solver solves them. plugin.step(m, d) then runs mj_step's
// stages for the Euler integrator one by one (mj_step's order; with no
// wheels it is mj_step to the bit):
//
//      mj_checkPos ... mj_collision(m, d);
//      plugin.addContacts(m, d);           // every wheel's tyre model; its contacts as mjContacts
//      mj_makeConstraint ... mj_fwdConstraint(m, d), mj_sensorAcc(m, d);
//      plugin.collectSolvedForces(m, d);   // the forces MuJoCo applied at them (applied())
//      mj_checkAcc, mj_Euler(m, d);
//      plugin.clearForces(d);
//
// Each contact's solref and solimp make MuJoCo's soft constraint the
// implicit Euler step of the tyre's spring-damper (c, b), ODE's ERP and
// CFM: a wheel settles at W / c at any step. Its friction is MuJoCo's cone
// (pyramidal or elliptic, the model's) at the slip law's coefficient;
// MuJoCo ties the friction's compliance to the normal's, so friction
// creeps at h R / impratio metres a second per newton. docs/mujoco-plugin.md
// has the mapping, what maps and what does not. Implicit mode is refused:
// MuJoCo 2.2.2's friction rows take no target velocity.
#include <memory>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>
#include <Eigen/Core>

#include "wtc/adapter/wheel_listener.hpp"
#include "wtc/adapter/wheel_spec.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"
#include "wtc/terrain/terrain.hpp"
#include "wtc/tyre/body_soil.hpp"
#include "wtc/tyre/contact_mode.hpp"
#include "wtc/tyre/ground_memory.hpp"
#include "wtc/tyre/tyre_model.hpp"

namespace wtc::mujoco {

using WheelId = wtc::WheelId;
using WheelListener = wtc::WheelListener;

/// A wheel: a body of the model (wtc/adapter/wheel_spec.hpp: what the wheel
/// is and where its inertia comes from). Its centre and axle are given in
/// the body's frame (mjData::xpos, xmat), not its inertial frame.
struct Wheel : WheelSpec {
  int body = -1;  ///< The body's id (mj_name2id(m, mjOBJ_BODY, name)); not the world (0).
  Eigen::Vector3d axle_local{Eigen::Vector3d::UnitY()};   ///< Axle direction in the body frame.
  Eigen::Vector3d centre_local{Eigen::Vector3d::Zero()};  ///< Wheel centre O in the body frame (m).
};

/// A body of the model on soft soil (addSoilBody).
struct SoilBody {
  int body = -1;  ///< The body's id; not the world, not welded to it.
  /// Its shape in the body's frame (mjData::xpos, xmat; m), one or more
  /// convex hulls.
  std::vector<ConvexPolyhedron> hulls;
};
using SoilBodyId = int;

namespace detail {
struct PluginState;
}  // namespace detail

class Plugin {
 public:
  /// WTC's wheels for `model` (which, like `terrain`, must outlive the
  /// plugin) on `terrain`. InvalidInputError: an engine-solved mode (not
  /// yet served), an integrator WTC cannot serve (RK4), a timestep that is
  /// not positive.
  Plugin(const mjModel& model, const Terrain& terrain, ContactMode mode = ContactMode::kForce);
  ~Plugin();
  Plugin(const Plugin&) = delete;
  Plugin& operator=(const Plugin&) = delete;

  /// Registers a wheel. InvalidInputError naming the problem: a body id
  /// the model lacks or the world's, a body registered twice, a zero axle,
  /// invalid parameters, a geom of the body that MuJoCo would also collide
  /// with the world's geoms (named); in constraint mode a body without a
  /// geom.
  WheelId addWheel(const Wheel& wheel);

  /// A body of the model on the terrain's soft soil (docs/soft-soil.md, "A
  /// body on the soil"): each step its wtc::BodyOnSoil force goes into its
  /// xfrc_applied, and its MuJoCo contacts on pieces with a soil are
  /// dropped after mj_collision (dropRigidSoilContacts), so the soil, not
  /// MuJoCo's rigid contact, carries it there. With a soil body the step
  /// runs MuJoCo's stages one by one in force mode too: the model must use
  /// the Euler integrator. InvalidInputError: the world, a body the model
  /// lacks, one welded to the world, a registered wheel, a body registered
  /// twice, bad hulls, another integrator.
  SoilBodyId addSoilBody(const SoilBody& body);
  /// What the soil did to it in the last step.
  const BodySoilForces& soilForces(SoilBodyId body) const;
  int soilBodyCount() const;
  /// After mj_collision: the soil bodies' contacts on soil pieces excluded.
  void dropRigidSoilContacts(const mjModel& model, mjData& data) const;

  /// One MuJoCo step with the wheels (the call order above). `model` must
  /// be the plugin's.
  void step(const mjModel& model, mjData& data);
  /// After mj_step1: every wheel's tyre model for a step of
  /// model.opt.timestep from the state mj_step1 computed, its wrench added
  /// to data.xfrc_applied at the body's centre of mass.
  void applyForces(const mjModel& model, mjData& data);
  /// Constraint mode, after mj_collision: every wheel's tyre model from
  /// this step's positions and velocities, its contacts added to
  /// data.contact (InvalidInputError when the model's nconmax is full), and
  /// what stays explicit (the rolling-resistance moment, soft soil's shear)
  /// added to data.xfrc_applied.
  void addContacts(const mjModel& model, mjData& data);
  /// Constraint mode, after mj_fwdConstraint: reads the forces MuJoCo's
  /// solver applied at the wheels' contacts (applied()).
  void collectSolvedForces(const mjModel& model, const mjData& data);
  /// After the step: takes the wrench applyForces or addContacts added back out.
  void clearForces(mjData& data);

  /// The last step's result and state of a wheel (std::out_of_range for an
  /// id that is not registered).
  const WheelForces& forces(WheelId wheel) const;
  const WheelState& state(WheelId wheel) const;
  /// What acted on the wheel in the last step: forces() in force mode; in
  /// constraint mode the forces MuJoCo's solver applied at its contacts,
  /// their wrench and the explicit moment (wtc::MountedWheel::applied).
  /// Report these, not forces(), as a constraint-mode run's contact forces.
  const WheelForces& applied(WheelId wheel) const;
  /// What the terrain's soil regions remember (wtc/tyre/ground_memory.hpp).
  const GroundMemory& groundMemory() const;
  GroundMemory& groundMemory();
  int wheelCount() const;
  /// Wall time (s) the plugin's own per-step work took since construction
  /// (MuJoCo's stages not included): against the simulation's wall time,
  /// WTC's share of a step.
  double contactSeconds() const;
  ContactMode mode() const;
  /// Called by applyForces for each wheel after its tyre model ran; null: none.
  void setListener(WheelListener* listener);

 private:
  std::unique_ptr<detail::PluginState> state_;
};

}  // namespace wtc::mujoco
