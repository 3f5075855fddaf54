#pragma once
// A vehicle's energy balance over a run (wtc::sim). Design note:
//
// The vehicle's energy, summed over its bodies b, its tyres' contacts k and
// its hitch,
//
//   E = sum_b ( 1/2 m_b |v_b|^2 + 1/2 w_b^T R_b I_b R_b^T w_b + m_b g z_b )
//     + sum_k 1/2 c_k Z_k^2 + 1/2 Delta^T diag(C) Delta,
//
// (v_b, w_b the centre of mass's velocity and the angular velocity, world;
// I_b the principal moments in the body frame R_b; z_b the centre's height;
// c_k, Z_k a tyre's radial stiffness and deflection; Delta, C the hitch's
// deflection in the tug's axes and stiffness) changes by the work of what
// acts on it. Of that, only the drives (and a rig outside the vehicle, a
// drawbar: its W_rig = sum F . v_P h, drawbar.hpp) are sources: the drives' work is
//
//   W = sum over steps and drives of effort x joint rate x h,
//
// the effort on the child about (along) the joint axis against the parent,
// and the joint's rate after the step (a semi-implicit step moves a body by
// its new velocity, so an effort that is constant over the step does
// exactly this work). Everything else only dissipates: the tyres' damping
// and slip law (a driven wheel's traction does work on the chassis, but it
// comes from the drive's work on the wheel; the tread's tangential spring,
// under 0.1 J a wheel, is left out), the engine's contacts, friction and
// joint stops, the hitch's damping (its power is <= 0: hitch_law.hpp; the
// hitch is internal to the vehicle, P on the towed body and -P on the
// tug). Gravity is in E. Constraint mode's contact is the same spring and
// damper, implicit (engine_contact.hpp), so its c Z^2 / 2 is stored alike.
// A contact on soft soil (ContactForce::soft_soil) stores nothing: the soil
// takes work as the wheel sinks and gives back at most a part of it.
//
// So the unexplained growth G = E - E_0 - W - W_rig stays at or below zero but for
// the integrators' error. The balance starts before the first step (start):
// E_0 is the start state's bodies and hitch, plus the tyres' springs as the
// first step found them (the engines report the tyres' contacts only after a
// step, and a tyre placed pressed into the ground holds energy that is not
// made from nothing), and W counts from the first step. A kick in the first
// step (a body placed inside the ground, thrown out by the engine's contact)
// is growth (issue 57 row 4: the balance started after step 1, and such a
// kick, 1 m/s, went unnoticed). A run whose G passes
// tolerance::kEnergyGrowthHeightM (the energy of lifting the whole
// vehicle that high) made energy from nothing (a tyre spring too stiff for
// its step, a solver's position correction throwing a body) and is not a
// success (runScene; docs/vehicles-and-scenes.md has the measured margins).
#include <optional>
#include <span>
#include <vector>

#include "wtc/sim/engine.hpp"
#include "wtc/vehicle/controller.hpp"
#include "wtc/vehicle/drive.hpp"

namespace wtc::sim {

class EnergyBalance {
 public:
  /// For `vehicle` stepped by `step_seconds` (s).
  EnergyBalance(const vehicle::VehicleDescription& vehicle, double step_seconds);

  /// Before the first step: the start state's energy of the bodies and the
  /// hitch (E_0 without the tyres', which the first step adds).
  void start(const vehicle::VehicleState& state);
  /// Gravity turned (a tilt table) to `g_W` (m/s^2) with the bodies at
  /// `state`: E's potential is then sum m |g| (u . x), u = -g / |g|, and
  /// the turn itself is a source, sum m |g| (u_new - u_old) . x (the
  /// potential's change at fixed positions, dV/dt dt), counted as a rig's
  /// work.
  void setGravity(const Eigen::Vector3d& g_W, const vehicle::VehicleState& state);
  /// After each step: the drives' work of the step
  /// (their last efforts by body, N m or N) and E of `state`, the state
  /// after it, with each wheel's contacts in `wheel_forces` (by body; null
  /// for a body that is not a wheel). `rig_work` is what a rig outside the
  /// vehicle did on it in the step (J: a drawbar's F . v_P h), a source like
  /// the drives'. Allocates nothing.
  void step(const vehicle::VehicleState& state, std::span<const WheelForces* const> wheel_forces,
            std::span<const vehicle::DriveReport> drives, double rig_work = 0.0);

  /// E after the last step (J; 0 before the first).
  double energy() const { return energy_; }
  /// W since the first step (J; negative when the drives brake more than
  /// they push).
  double driveWork() const { return drive_work_; }
  /// G = E - E_1 - W now, and its largest value so far with the time it
  /// had it (J, s; 0 until it grows).
  double growth() const { return energy_ - initial_ - drive_work_ - rig_work_; }
  /// The rigs' work since the first step (J).
  double rigWork() const { return rig_work_; }
  double maxGrowth() const { return max_growth_; }
  double maxGrowthTime() const { return max_growth_time_; }

 private:
  double bodiesEnergy(const vehicle::VehicleState& state) const;  // kinetic, gravity, the hitch's spring
  double tyresEnergy(std::span<const WheelForces* const> wheel_forces) const;

  const vehicle::VehicleDescription& vehicle_;
  std::vector<int> wheels_;
  double h_;  // (s)
  bool started_ = false;  // the first step is in
  std::optional<double> start_;  // E_0 without the tyres (start)
  double gravity_;               // |g| (m/s^2)
  Eigen::Vector3d up_{Eigen::Vector3d::UnitZ()};  // -g / |g|
  double initial_ = 0.0, energy_ = 0.0, drive_work_ = 0.0, rig_work_ = 0.0;
  double max_growth_ = 0.0, max_growth_time_ = 0.0;
};

}  // namespace wtc::sim
