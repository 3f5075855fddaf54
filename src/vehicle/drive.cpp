#include "wtc/vehicle/drive.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "wtc/base/error.hpp"

namespace wtc::vehicle {

MotorTarget motorTarget(const ActuatorLimits& drive, const std::optional<JointLimits>& travel,
                        const DriveCommand& command, double position, bool limits_on) {
  if (command.mode == DriveMode::kOff) return {};
  if (!std::isfinite(command.value) || !std::isfinite(position)) {
    throw InvalidInputError("wtc::vehicle::motorTarget: command " + formatNumber(command.value) + " at position " +
                            formatNumber(position) + " is not finite");
  }
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  MotorTarget target{.active = true, .rate = command.value, .max_effort = limits_on ? drive.max_effort : kInfinity};
  if (command.mode == DriveMode::kPosition) {
    double goal = command.value;
    if (travel) {
      goal = std::clamp(goal, travel->lower, travel->upper);
      target.clamped = goal != command.value;
      if (travel->upper - travel->lower > 2.0 * kDriveStopMargin) {
        goal = std::clamp(goal, travel->lower + kDriveStopMargin, travel->upper - kDriveStopMargin);
      }
    }
    target.rate = drive.position_gain * (goal - position);
    // Moving to a position at full speed is the drive's job, not saturation.
    if (limits_on) target.rate = std::clamp(target.rate, -drive.max_speed, drive.max_speed);
    return target;
  }
  if (limits_on && std::abs(target.rate) > drive.max_speed) {
    target.rate = std::copysign(drive.max_speed, target.rate);
    target.clamped = true;
  }
  return target;
}

double wheelDriveTorque(const MotorTarget& target, double rate, double tau_axle, double spin_inertia, double h) {
  if (!target.active) return 0.0;
  return std::clamp(spin_inertia * (target.rate - rate) / h - tau_axle, -target.max_effort, target.max_effort);
}

void record(DriveReport& report, const MotorTarget& target, double applied_effort) {
  report.last_effort = applied_effort;
  report.last_saturated = false;
  if (!target.active) return;
  ++report.steps;
  report.peak_effort = std::max(report.peak_effort, std::abs(applied_effort));
  report.last_saturated = target.clamped || std::abs(applied_effort) >= (1.0 - kFullEffortFraction) * target.max_effort;
  if (report.last_saturated) ++report.saturated_steps;
}

}  // namespace wtc::vehicle
