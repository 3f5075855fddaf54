// The engine table: the entries every engine registered (engine_list.hpp,
// whose source CMake generates from the engines declared with
// wtc_add_engine), looked up by name.
#include "wtc/sim/engine_table.hpp"

#include <string>

#include "engine_list.hpp"
#include "wtc/base/error.hpp"

namespace wtc::sim {
namespace {

// The entry named `name`, or null.
const EngineEntry* find(std::string_view name) {
  for (const EngineEntry& entry : detail::engineList()) {
    if (entry.name == name) return &entry;
  }
  return nullptr;
}

}  // namespace

std::vector<std::string_view> engineNames() {
  std::vector<std::string_view> names;
  for (const EngineEntry& entry : detail::engineList()) names.push_back(entry.name);
  return names;
}

void requireEngine(const EngineSettings& settings) {
  if (find(settings.engine) != nullptr) return;
  // "bullet", "bullet or ode", "bullet, ode or ode_quick".
  const std::vector<std::string_view> names = engineNames();
  std::string known;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) known += i + 1 == names.size() ? " or " : ", ";
    known += names[i];
  }
  throw InvalidInputError(settings.engine_where + ": unknown engine '" + settings.engine + "' (expected " + known +
                          ")");
}

std::unique_ptr<Engine> makeEngine(const EngineSettings& settings, const Terrain& terrain,
                                   const vehicle::VehicleDescription& vehicle, const Eigen::Isometry3d& placement) {
  requireEngine(settings);
  return find(settings.engine)->make(settings, terrain, vehicle, placement);
}

}  // namespace wtc::sim
