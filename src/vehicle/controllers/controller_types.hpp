#pragma once
// The controller types a scene may name (`controller: {type: ...}`), each
// reading its own settings beside its class (src/vehicle/controllers/<type>/,
// as Jolt's VehicleControllerSettings::ConstructController): the scene
// reader looks the type up here and hands it its mapping. A new controller
// is a folder and one line of the table in controller_types.cpp; a layer
// above (the Python bindings) adds its own with addControllerType.
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "io/yaml_reader.hpp"
#include "wtc/vehicle/controller.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::vehicle {

/// A fresh controller for one run (controllers keep state); may return
/// null (no controller: every drive off).
using ControllerFactory = std::function<std::unique_ptr<Controller>()>;

/// Reads a type's settings from the scene's `controller` mapping `node`
/// (its keys checked, `type` among them), checks them against `vehicle`,
/// and returns the factory; refusals through `in.fail` (file, line, key).
using ControllerReader = ControllerFactory (*)(const io::detail::YamlReader& in, const YAML::Node& node,
                                               const VehicleDescription& vehicle);

struct ControllerType {
  std::string name;  ///< As scenes name it.
  ControllerReader read = nullptr;
};

/// The type named `name`, or null.
const ControllerType* findControllerType(std::string_view name);
/// "none, schedule, path or climb": the known names, for messages.
std::string controllerTypeNames();
/// Adds a type at run time (before any scene names it; not thread-safe).
/// Throws InvalidInputError if the name is taken.
void addControllerType(ControllerType type);

/// The factory of a controller `C(vehicle, settings, "controller")`, after
/// making one to check the settings: its refusal is `in.fail` at `node`.
template <class C, class Settings>
ControllerFactory checkedFactory(const io::detail::YamlReader& in, const YAML::Node& node,
                                 const VehicleDescription& vehicle, const Settings& settings) {
  try {
    C check(vehicle, settings, "controller");
  } catch (const InvalidInputError& e) {
    in.fail(node, e.what());
  }
  return
      [settings, vehicle] { return std::unique_ptr<Controller>(std::make_unique<C>(vehicle, settings, "controller")); };
}

// Each type's reader, beside its controller.
ControllerFactory readScheduleController(const io::detail::YamlReader& in, const YAML::Node& node,
                                         const VehicleDescription& vehicle);
ControllerFactory readPathController(const io::detail::YamlReader& in, const YAML::Node& node,
                                     const VehicleDescription& vehicle);
ControllerFactory readClimbController(const io::detail::YamlReader& in, const YAML::Node& node,
                                      const VehicleDescription& vehicle);

}  // namespace wtc::vehicle
