#pragma once
// The controller of the simple scenes (wtc::vehicle): each drive follows a
// schedule given in the scene, a rate or a position linear between points
// in time and held after the last. Standing, driving straight, turning in
// place and reconfiguring are schedules; the climbing and path-following
// controllers are their own classes.
#include <optional>
#include <string>
#include <vector>

#include "wtc/vehicle/controller.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::vehicle {

struct SchedulePoint {
  double time = 0.0;   ///< (s), increasing along a schedule.
  double value = 0.0;  ///< Rate (rad/s, m/s) or position (rad, m).
};

/// One schedule for a set of drives.
struct DriveSchedule {
  std::vector<std::string> drives;  ///< Body names whose joint has a drive.
  DriveMode mode = DriveMode::kVelocity;
  std::vector<SchedulePoint> points;  ///< At least one.
  /// From this time on (s, >= 0) the drives are off (free joints): a drive
  /// that drives, then lets its wheel coast (a coast-down rig). None: never.
  std::optional<double> off_after = std::nullopt;
};

class ScheduleController final : public Controller {
 public:
  /// Throws InvalidInputError naming `where` and the schedule for a name
  /// that is not a driven body of `vehicle`, a drive scheduled twice, no
  /// points, times not increasing, non-finite values, or an off_after that
  /// is negative, not finite, or on a schedule whose mode is already off.
  /// Drives not named stay off.
  ScheduleController(const VehicleDescription& vehicle, std::vector<DriveSchedule> schedules, const std::string& where);

  void update(const VehicleState& state, std::span<DriveCommand> commands) override;

  /// The scheduled value at time t (linear between points, held outside).
  static double valueAt(const std::vector<SchedulePoint>& points, double t);

 private:
  struct Entry {
    std::vector<int> bodies;
    DriveMode mode;
    std::vector<SchedulePoint> points;
    std::optional<double> off_after;
  };
  std::vector<Entry> entries_;
};

}  // namespace wtc::vehicle
