#pragma once
// Each mobility event's bound from mechanics (wtc::mobility), computed from
// the vehicle description and the ground's slip law and rolling resistance
// (docs/mobility-bounds.md derives each one; docs/mobility.md compares them
// with the runs). Quasi-static rigid bodies on WTC's contact law: rolling
// resistance is a moment at the axle (a driven wheel pushes mu(s) N
// whatever f_r is), held wheels stick up to the peak of mu(s), locked ones
// slide at mu(1).
#include <optional>
#include <string>
#include <vector>

#include "wtc/mobility/mobility_settings.hpp"
#include "wtc/mobility/vehicle_statics.hpp"

namespace wtc::mobility {

/// One event's bound: the value mechanics allows, the limit that sets it,
/// and how it was found.
struct Bound {
  double value = 0.0;           ///< In the event's unit (MobilityEvent's).
  std::optional<double> lower;  ///< Where mechanics gives a range (a rigid vehicle lifting an axle).
  std::string governs;          ///< "traction", "drive torque", "tip-over", ...
  std::string detail;           ///< The numbers behind it, one line.
};

/// The driving slip i's bound: DP/W and the torque coefficient sum T / (r_f W).
struct DrawbarPoint {
  double slip = 0.0;  ///< i (dimensionless).
  double dp_per_weight = 0.0;
  double torque_coefficient = 0.0;
};

struct VehicleBounds {
  Bound grade_deg;       ///< Steepest incline climbed from rest.
  Bound parked_deg;      ///< Steepest held, wheels held.
  Bound side_slope_deg;  ///< Parked across a slope: the first of sliding and tipping.
  double side_slide_deg = 0.0, side_tip_deg = 0.0;
  Bound step_m;                       ///< Tallest step, plain drive forward.
  Bound gap_m;                        ///< Widest gap, plain drive forward.
  Bound coast_mps2;                   ///< Coast-down deceleration.
  Bound braking_m;                    ///< Locked-wheel stopping distance from BrakingSettings::speed_mps.
  std::optional<Bound> turn_radps;    ///< Skid-steer yaw rate at TurnSettings::wheel_rate (all-wheel drive, one track).
  double turn_moment_Nm = 0.0;        ///< Sum mu N_i d_i of fully sliding wheels (0 if not skid-steered).
  std::vector<DrawbarPoint> drawbar;  ///< At DrawbarSettings::slips.
};

/// The bounds for `vehicle` on `settings.ground`.
VehicleBounds computeBounds(const VehicleStatics& vehicle, const MobilitySettings& settings);

/// mu(s) and its peak for the ground (the slip law, docs/tyre-model.md).
double slipLawPeak(const Material& ground);

}  // namespace wtc::mobility
