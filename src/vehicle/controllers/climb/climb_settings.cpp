// `controller: {type: climb, approach_speed: ..., ...}` (scenes/README.md).
#include "vehicle/controllers/controller_types.hpp"
#include "wtc/vehicle/controllers/climb_controller.hpp"

namespace wtc::vehicle {

using io::detail::YamlReader;

ControllerFactory readClimbController(const YamlReader& in, const YAML::Node& node, const VehicleDescription& vehicle) {
  in.checkKeys(node, {"type", "approach_speed", "crawl_speed", "drive_on_time", "phase_timeout"});
  ClimbControllerParams p;
  p.approach_speed = in.number(node, "approach_speed", p.approach_speed);
  p.crawl_speed = in.number(node, "crawl_speed", p.crawl_speed);
  p.drive_on_time = in.number(node, "drive_on_time", p.drive_on_time);
  p.phase_timeout = in.number(node, "phase_timeout", p.phase_timeout);
  return checkedFactory<ClimbController>(in, node, vehicle, p);
}

}  // namespace wtc::vehicle
