#pragma once
// A drive on a joint (a wheel motor, a fold drive, a linear drive), as a
// real one behaves: it holds a commanded rate with at most its rated effort,
// never faster than its rated speed. Design note:
//
// The engine holds the rate with its own implicit motor (Bullet's
// btMultiBodyJointMotor, ODE's dParamVel/dParamFMax), capped at the drive's
// effort: an explicit PD loop would need gains the 0.4 ms step cannot keep
// stable for a 1500 N m fold drive. This file is what is engine-free: the
// rate the motor is given this step, the accounting of saturation, and a
// wheel's drive in closed form (wheelDriveTorque) for an engine whose
// solver rows cost more than the one-line solve.
//
// Position mode turns the position error into a rate, rate = k (q* - q),
// clamped to max_speed; a target beyond the joint's limits is clamped to
// them, and the drive holds kDriveStopMargin inside them. A command that
// asks for more than the drive has (a rate above max_speed, a position past
// a limit, or an effort at max_effort) is a saturated step: counted per
// drive and reported, never hidden.
#include <cstdint>
#include <optional>

#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::vehicle {

enum class DriveMode : std::uint8_t {
  kOff,       ///< No motor: the joint is free (a passive wheel).
  kVelocity,  ///< value: rate (rad/s or m/s).
  kPosition,  ///< value: position (rad or m).
};

struct DriveCommand {
  DriveMode mode = DriveMode::kOff;
  double value = 0.0;
};

/// What the engine's motor is given for one step.
struct MotorTarget {
  bool active = false;    ///< False: no motor this step.
  double rate = 0.0;      ///< Rate to hold (rad/s or m/s).
  double max_effort = 0;  ///< Effort cap (N m or N); infinite when limits are off.
  bool clamped = false;   ///< The command asked for more than the drive's speed or travel.
};

/// The motor target for `command` at joint position `position`. With
/// `limits_on` false (the actuator_limits effect off) the drive is ideal:
/// no speed or effort cap, but a position target still stays within the
/// joint's travel. Throws InvalidInputError for a non-finite command.
MotorTarget motorTarget(const ActuatorLimits& drive, const std::optional<JointLimits>& travel,
                        const DriveCommand& command, double position, bool limits_on);

/// A wheel's drive solved for one step in closed form: the torque that
/// brings the wheel's rate relative to its carrier from `rate` to
/// target.rate in one step h,
///   T = I (target.rate - rate) / h - tau_axle,   |T| <= target.max_effort,
/// 0 when the target is inactive. I is the wheel's moment about its axle
/// (kg m^2), tau_axle the torque the step's other loads (the tyre's, in
/// force mode) put on the wheel about it (N m). Exact for the wheel's spin,
/// which nothing but those torques and the drive turns; the engine's own
/// motor row solves the same equation with the carrier's share added,
/// I / I_carrier (under 1 % for a robot's wheel), which this leaves out.
/// Not for contacts the solver adds during the step (constraint mode):
/// their torque is unknown here.
double wheelDriveTorque(const MotorTarget& target, double rate, double tau_axle, double spin_inertia, double h);

/// A drive's record over a run.
struct DriveReport {
  std::uint64_t steps = 0;            ///< Steps with the motor active.
  std::uint64_t saturated_steps = 0;  ///< Steps clamped or at full effort.
  double peak_effort = 0.0;           ///< Largest |effort| applied (N m or N).
  double last_effort = 0.0;           ///< Effort of the last step (N m or N).
  bool last_saturated = false;
};

/// A position target stops this far inside the joint's travel (m or rad):
/// a drive's soft limit short of its stop, as a real one has. Commanded to
/// the stop itself, the drive and the stop would hold one axis with two
/// rows of the solver, and a direct solver may split the load between them
/// any way it likes: ODE's put a slider's full effort against its stop, a
/// saturated step (docs/vehicles-and-scenes.md).
inline constexpr double kDriveStopMargin = 1e-4;

/// A motor is at full effort when |effort| >= (1 - kFullEffortFraction) cap:
/// the engine's solver stops at its cap to within its own tolerance.
inline constexpr double kFullEffortFraction = 1e-3;

/// Adds one step: the target given and the effort the engine applied.
void record(DriveReport& report, const MotorTarget& target, double applied_effort);

}  // namespace wtc::vehicle
