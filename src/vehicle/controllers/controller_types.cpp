#include "controller_types.hpp"

#include "wtc/base/error.hpp"

namespace wtc::vehicle {
namespace {

// `type: none`: no controller, every drive off.
ControllerFactory readNoController(const io::detail::YamlReader& in, const YAML::Node& node,
                                   const VehicleDescription& /*vehicle*/) {
  in.checkKeys(node, {"type"});
  return [] { return std::unique_ptr<Controller>(); };
}

// The table: one line per controller type.
std::vector<ControllerType>& table() {
  static std::vector<ControllerType> types = {
      {"none", &readNoController},
      {"schedule", &readScheduleController},
      {"path", &readPathController},
      {"climb", &readClimbController},
  };
  return types;
}

}  // namespace

const ControllerType* findControllerType(std::string_view name) {
  for (const ControllerType& t : table()) {
    if (t.name == name) return &t;
  }
  return nullptr;
}

std::string controllerTypeNames() {
  std::string names;
  const std::vector<ControllerType>& types = table();
  for (std::size_t i = 0; i < types.size(); ++i) {
    names += (i == 0 ? "" : (i + 1 == types.size() ? " or " : ", ")) + types[i].name;
  }
  return names;
}

void addControllerType(ControllerType type) {
  if (type.read == nullptr)
    throw InvalidInputError("wtc::vehicle::addControllerType: '" + type.name + "' has no reader");
  if (findControllerType(type.name) != nullptr) {
    throw InvalidInputError("wtc::vehicle::addControllerType: a controller type '" + type.name + "' exists already");
  }
  table().push_back(std::move(type));
}

}  // namespace wtc::vehicle
