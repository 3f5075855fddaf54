// `controller: {type: schedule, schedules: [...]}` (scenes/README.md).
#include "vehicle/controllers/controller_types.hpp"
#include "wtc/vehicle/controllers/schedule_controller.hpp"

namespace wtc::vehicle {
namespace {

using io::detail::YamlReader;

std::vector<DriveSchedule> readSchedules(const YamlReader& in, const YAML::Node& node) {
  if (!node.IsSequence()) in.fail(node, "schedules: expected a list");
  std::vector<DriveSchedule> schedules;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YamlReader s = in.with("controller.schedules[" + std::to_string(i) + "]: ");
    const YAML::Node n = node[i];
    s.requireMap(n, "a schedule");
    s.checkKeys(n, {"drives", "mode", "points", "off_after"});
    DriveSchedule schedule;
    const YAML::Node drives = s.require(n, "drives");
    if (!drives.IsSequence()) s.fail(drives, "drives: expected a list of body names");
    for (const auto& d : drives) schedule.drives.push_back(s.string(d, "drives"));
    const std::string mode = s.string(s.require(n, "mode"), "mode");
    if (mode == "velocity") {
      schedule.mode = DriveMode::kVelocity;
    } else if (mode == "position") {
      schedule.mode = DriveMode::kPosition;
    } else if (mode == "off") {
      schedule.mode = DriveMode::kOff;
    } else {
      s.fail(n["mode"], "mode: '" + mode + "' (expected velocity, position or off)");
    }
    const YAML::Node points = s.require(n, "points");
    if (!points.IsSequence() || points.size() == 0) s.fail(points, "points: expected a list of [time, value]");
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Eigen::Vector2d p = s.vector<2>(points[k], "points[" + std::to_string(k) + "]");
      schedule.points.push_back({.time = p.x(), .value = p.y()});
    }
    if (const auto off = YamlReader::get(n, "off_after")) {
      schedule.off_after = s.number(*off, "off_after");
      if (*schedule.off_after < 0.0)
        s.fail(*off, "off_after: " + formatNumber(*schedule.off_after) + " must be >= 0 (s)");
      if (schedule.mode == DriveMode::kOff) {
        s.fail(*off, "off_after: the schedule's mode is off already (its drives are off throughout)");
      }
    }
    schedules.push_back(std::move(schedule));
  }
  return schedules;
}

}  // namespace

ControllerFactory readScheduleController(const YamlReader& in, const YAML::Node& node,
                                         const VehicleDescription& vehicle) {
  in.checkKeys(node, {"type", "schedules"});
  return checkedFactory<ScheduleController>(in, node, vehicle, readSchedules(in, in.require(node, "schedules")));
}

}  // namespace wtc::vehicle
