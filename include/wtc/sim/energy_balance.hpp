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
//
// So the unexplained growth G = E - E_1 - W - W_rig stays at or below zero but for
// the integrators' error. The balance starts after the first step (E_1,
// W from the second step on): the engines report the tyres' contacts only
// after a step, and a tyre pressed into the ground at the start holds
// energy that is not made from nothing. A run whose G passes
// tolerance::kEnergyGrowthHeightM (the energy of lifting the whole
// vehicle that high) made energy from nothing (a tyre spring too stiff for
// its step, a solver's position correction throwing a body) and is not a
// success (runScene; docs/vehicles-and-scenes.md has the measured margins).
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

  /// After each step (the first sets E_1): the drives' work of the step
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
  double energyOf(const vehicle::VehicleState& state, std::span<const WheelForces* const> wheel_forces) const;

  const vehicle::VehicleDescription& vehicle_;
  std::vector<int> wheels_;
  double h_;  // (s)
  bool started_ = false;
  double initial_ = 0.0, energy_ = 0.0, drive_work_ = 0.0, rig_work_ = 0.0;
  double max_growth_ = 0.0, max_growth_time_ = 0.0;
};

}  // namespace wtc::sim
