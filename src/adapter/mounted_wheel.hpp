#pragma once
// A wheel as an engine adapter holds it (wtc::core). Design note:
//
// Both adapters (wtc::bullet, wtc::ode) do the same per wheel and step:
// run the tyre model inside the engine's step, skip a wheel whose body state
// went non-finite, and turn the result into what the engine takes for the
// contact mode: in force mode the whole tyre wrench about the wheel centre
// O; in constraint mode the engine contacts (engine_contact.hpp) plus the
// rolling-resistance moment and the soft-soil contacts' shear, which stay
// explicit. That lives here once; an adapter reads the wheel's kinematics
// from its engine, calls step, writes the result to its bodies and solver,
// and calls tell for its listener.
#include <span>
#include <vector>

#include <Eigen/Core>

#include "wtc/tyre/effects.hpp"
#include "wtc/adapter/solver_contact.hpp"
#include "wtc/terrain/terrain.hpp"
#include "wtc/tyre/tyre_model.hpp"
#include "wtc/tyre/wheel_forces.hpp"
#include "wtc/adapter/wheel_listener.hpp"

namespace wtc {

/// What an adapter applies for one step of one wheel.
struct MountedWheelStep {
  /// The body's pose or motion was not finite: apply nothing, add no
  /// contact (WheelState::nonFiniteSteps counts it).
  bool skipped = false;
  /// Through O (N): the tyre force in force mode; in constraint mode the
  /// soft-soil contacts' force (zero without one).
  Eigen::Vector3d force{Eigen::Vector3d::Zero()};
  /// About O (N m): the tyre torque in force mode; the rolling-resistance
  /// moment and the soft-soil contacts' moment in constraint mode.
  Eigen::Vector3d torque{Eigen::Vector3d::Zero()};
  /// Constraint mode: the engine contacts for this step (empty in force
  /// mode). Valid until the wheel's next step.
  std::span<const SolverContact> contacts;
};

class MountedWheel {
 public:
  /// Throws InvalidInputError for an invalid description or effect set.
  MountedWheel(const WheelDescription& description, EffectSet effects, ContactMode mode);

  /// One step of length h inside the engine's step: never throws for a
  /// non-finite pose or motion (TyreModel::stepInEngine); throws for a
  /// non-positive step.
  const MountedWheelStep& step(const Terrain& terrain, const WheelPose& pose, const WheelMotion& motion, double h);
  /// The acceleration that loads a vehicle at rest: the world's gravity
  /// (m/s^2; default 0, -9.81 along z is not assumed). Constraint mode holds
  /// a sticking contact along its tangential part (toSolverContact).
  void setRestLoad(const Eigen::Vector3d& acceleration) { rest_load_ = acceleration; }

  const WheelDescription& description() const { return description_; }
  const TyreModel& model() const { return model_; }
  ContactMode mode() const { return model_.mode(); }
  /// The last step's tyre result (what the explicit model computed).
  const WheelForces& forces() const { return state_.result(); }
  const WheelState& state() const { return state_; }
  WheelState& state() { return state_; }
  /// The last step's result for the engine.
  const MountedWheelStep& last() const { return step_; }
  /// Constraint mode, once the engine has solved the step: the force its
  /// solver applied on the wheel at each of last().contacts (N, world;
  /// impulse / h), in their order. Throws InvalidInputError for a
  /// count that is not theirs.
  void setSolvedForces(std::span<const Eigen::Vector3d> forces);
  /// What acted on the wheel in the last step. Force mode: forces(). In
  /// constraint mode the tyre model's contacts with the engine's solved
  /// forces (force, normal_force, tangential_force, mu) and their wrench
  /// about O, plus the explicit rolling moment: what the engine applied,
  /// which the explicit model only approximates (issue 11, defect 7);
  /// forces() until setSolvedForces is called for the step.
  const WheelForces& applied() const { return solved_valid_ ? solved_ : forces(); }
  /// Tells `listener` (none if null) what the last step did, for wheel
  /// `id`: onWheelSkipped; or onWheelStep, and onFirstUnstableStep on the
  /// wheel's first step beyond its explicit stability limit.
  void tell(WheelListener* listener, WheelId id, double h) const;

 private:
  WheelDescription description_;
  TyreModel model_;
  WheelState state_;
  std::vector<SolverContact> contacts_;
  MountedWheelStep step_;
  WheelPose pose_;
  Eigen::Vector3d rest_load_{Eigen::Vector3d::Zero()};
  std::vector<ContactForce> solved_contacts_;
  WheelForces solved_;
  bool solved_valid_ = false;
};

}  // namespace wtc
