#pragma once
// The run loop (wtc::sim): one engine, one vehicle, one controller. Each
// step reads the sensors, asks the controller, turns its commands into the
// drives' motor targets (vehicle::motorTarget, saturation counted), applies
// the hitch force, steps the engine and reads what it did. The runner, the
// tests and the benchmarks all step vehicles through this class.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "wtc/sim/drawbar.hpp"
#include "wtc/sim/energy_balance.hpp"
#include "wtc/sim/engine.hpp"
#include "wtc/vehicle/controller.hpp"
#include "wtc/vehicle/joint_error.hpp"
#include "wtc/vehicle/vehicle_effects.hpp"

namespace wtc::sim {

class Run {
 public:
  /// `engine` and `controller` must outlive the run; a null controller
  /// leaves every drive off (a passive vehicle). A drawbar, if given, pulls
  /// from the start (DrawbarRig, placed on the vehicle as it stands now).
  Run(Engine& engine, vehicle::Controller* controller, const vehicle::VehicleEffects& effects = {},
      const std::optional<Drawbar>& drawbar = std::nullopt);

  /// One engine step. Throws InvalidInputError for a non-finite command.
  void step();
  /// Gravity for the next steps (m/s^2, world): the engine's, and the
  /// energy balance's (the turn is a source: EnergyBalance::setGravity).
  void setGravity(const Eigen::Vector3d& g_W);

  double time() const { return state_.time; }
  std::uint64_t steps() const { return steps_; }
  /// The sensors after the last step (at the start before the first).
  const vehicle::VehicleState& state() const { return state_; }
  /// Per body: the last step's commands, motor targets and drive records.
  std::span<const vehicle::DriveCommand> commands() const { return commands_; }
  std::span<const vehicle::MotorTarget> targets() const { return targets_; }
  std::span<const vehicle::DriveReport> drives() const { return drives_; }
  /// What acted on wheel body `body` in the last step (Engine::wheelForces,
  /// read once a step), valid until the next step.
  const WheelForces& wheelForces(int body) const { return *wheel_forces_[static_cast<std::size_t>(body)]; }
  /// The hitch force of the last step, if the vehicle has a hitch.
  const std::optional<vehicle::HitchForce>& hitch() const { return hitch_; }
  /// The drawbar's pull of the last step (before the first: the pull the
  /// first will apply), if the run has a drawbar.
  const std::optional<DrawbarForce>& drawbar() const { return drawbar_force_; }
  bool hasDrawbar() const { return drawbar_.has_value(); }

  /// Over the run so far: the largest joint error (vehicle::jointError),
  /// the deepest tyre deflection Z of any contact (m), and whether any body
  /// state was not finite (the run should stop).
  const vehicle::JointError& maxJointError() const { return max_joint_error_; }
  double maxDeflection() const { return max_deflection_; }
  bool nonFinite() const { return non_finite_; }
  /// Whether any body state went beyond kDivergedSpeedMps,
  /// kDivergedAngularSpeedRadps or kDivergedDistanceM (wtc/sim/sim_constants.hpp):
  /// the run should stop, as at a non-finite state.
  bool diverged() const { return diverged_; }
  /// The vehicle's energy against the drives' work since the start
  /// (EnergyBalance: what grew without a source).
  const EnergyBalance& energyBalance() const { return energy_; }

  const Engine& engine() const { return engine_; }

 private:
  void sense();

  Engine& engine_;
  vehicle::Controller* controller_;
  vehicle::VehicleEffects effects_;
  std::vector<int> actuated_;
  vehicle::VehicleState state_;
  std::vector<const WheelForces*> wheel_forces_;  // per body, null for a body that is not a wheel
  std::vector<vehicle::DriveCommand> commands_;
  std::vector<vehicle::MotorTarget> targets_;
  std::vector<vehicle::DriveReport> drives_;
  std::optional<vehicle::HitchForce> hitch_;
  std::optional<DrawbarRig> drawbar_;
  std::optional<DrawbarForce> drawbar_force_;
  vehicle::JointError max_joint_error_;
  double max_deflection_ = 0.0;
  bool non_finite_ = false;
  bool diverged_ = false;
  EnergyBalance energy_;
  std::uint64_t steps_ = 0;
};

}  // namespace wtc::sim
