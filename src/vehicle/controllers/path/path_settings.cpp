// `controller: {type: path, body: ..., x: [...], y: [...], ...}` (scenes/README.md).
#include "vehicle/controllers/controller_types.hpp"
#include "wtc/vehicle/controllers/path_controller.hpp"

namespace wtc::vehicle {

using io::detail::YamlReader;

ControllerFactory readPathController(const YamlReader& in, const YAML::Node& node, const VehicleDescription& vehicle) {
  in.checkKeys(
      node, {"type", "body", "left_drive", "right_drive", "lead", "x", "y", "gains", "max_tracking_error", "end_time"});
  PathControllerParams p;
  p.body = in.string(in.require(node, "body"), "controller.body");
  p.left_drive = in.string(in.require(node, "left_drive"), "controller.left_drive");
  p.right_drive = in.string(in.require(node, "right_drive"), "controller.right_drive");
  p.lead = in.number(node, "lead", p.lead);
  for (const auto& [key, coefficients] : {std::pair{"x", &p.x_coefficients}, std::pair{"y", &p.y_coefficients}}) {
    const YAML::Node list = in.require(node, key);
    if (!list.IsSequence() || list.size() == 0 || list.size() > 6) {
      in.fail(list, std::string("controller.") + key + ": expected 1 to 6 polynomial coefficients (degree <= 5)");
    }
    for (std::size_t i = 0; i < list.size(); ++i) {
      (*coefficients)[i] = in.number(list[i], std::string("controller.") + key + "[" + std::to_string(i) + "]");
    }
  }
  if (const auto gains = YamlReader::get(node, "gains")) {
    const Eigen::Vector2d k = in.vector<2>(*gains, "controller.gains");
    p.gain_x = k.x();
    p.gain_y = k.y();
  }
  p.max_tracking_error = in.number(node, "max_tracking_error", p.max_tracking_error);
  if (YamlReader::get(node, "end_time")) p.end_time = in.number(node, "end_time", p.end_time);
  return checkedFactory<PathController>(in, node, vehicle, p);
}

}  // namespace wtc::vehicle
