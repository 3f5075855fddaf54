#include "wtc/vehicle/controllers/schedule_controller.hpp"

#include <cmath>

#include "wtc/base/error.hpp"

namespace wtc::vehicle {

ScheduleController::ScheduleController(const VehicleDescription& vehicle, std::vector<DriveSchedule> schedules,
                                       const std::string& where) {
  std::vector<bool> taken(vehicle.bodies.size(), false);
  for (std::size_t s = 0; s < schedules.size(); ++s) {
    const DriveSchedule& schedule = schedules[s];
    const std::string at = where + ": schedule " + std::to_string(s);
    if (schedule.points.empty()) throw InvalidInputError(at + " has no points");
    for (std::size_t k = 0; k < schedule.points.size(); ++k) {
      const SchedulePoint& p = schedule.points[k];
      if (!std::isfinite(p.time) || !std::isfinite(p.value)) {
        throw InvalidInputError(at + ", point " + std::to_string(k) + ": time and value must be finite");
      }
      if (k > 0 && p.time <= schedule.points[k - 1].time) {
        throw InvalidInputError(at + ", point " + std::to_string(k) + ": time " + formatNumber(p.time) +
                                " s does not increase");
      }
    }
    if (schedule.off_after) {
      if (!std::isfinite(*schedule.off_after) || *schedule.off_after < 0.0) {
        throw InvalidInputError(at + ": off_after = " + formatNumber(*schedule.off_after) +
                                " must be finite and >= 0 (s)");
      }
      if (schedule.mode == DriveMode::kOff) {
        throw InvalidInputError(at + ": off_after on a schedule whose mode is off (its drives are off throughout)");
      }
    }
    Entry entry{.bodies = {}, .mode = schedule.mode, .points = schedule.points, .off_after = schedule.off_after};
    for (const std::string& name : schedule.drives) {
      const int b = vehicle.find(name);
      if (b < 0 || !vehicle.bodies[b].joint.actuator || vehicle.bodies[b].parent < 0) {
        throw InvalidInputError(at + ": '" + name + "' is not a driven body of vehicle '" + vehicle.name + "'");
      }
      if (taken[b]) throw InvalidInputError(at + ": drive '" + name + "' is scheduled twice");
      taken[b] = true;
      entry.bodies.push_back(b);
    }
    entries_.push_back(std::move(entry));
  }
}

double ScheduleController::valueAt(const std::vector<SchedulePoint>& points, double t) {
  if (t <= points.front().time) return points.front().value;
  for (std::size_t k = 1; k < points.size(); ++k) {
    if (t <= points[k].time) {
      const SchedulePoint& a = points[k - 1];
      const SchedulePoint& b = points[k];
      return a.value + (b.value - a.value) * (t - a.time) / (b.time - a.time);
    }
  }
  return points.back().value;
}

void ScheduleController::update(const VehicleState& state, std::span<DriveCommand> commands) {
  for (const Entry& e : entries_) {
    if (e.off_after && state.time >= *e.off_after) {
      for (const int b : e.bodies) commands[b] = {.mode = DriveMode::kOff, .value = 0.0};
      continue;
    }
    const double value = valueAt(e.points, state.time);
    for (const int b : e.bodies) commands[b] = {.mode = e.mode, .value = value};
  }
}

}  // namespace wtc::vehicle
