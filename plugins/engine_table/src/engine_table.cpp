// The engine table: the entries every engine registered (engine_list.hpp,
// whose source CMake generates from the engines declared with
// wtc_add_engine), looked up by name.
#include "wtc/sim/engine_table.hpp"

#include <algorithm>
#include <string>
#include <vector>

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

// "a", "a or b", "a, b or c".
template <class Names>
std::string listed(const Names& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += i + 1 == names.size() ? " or " : ", ";
    out += names[i];
  }
  return out;
}

bool serves(const EngineEntry& entry, const EngineSettings& settings) {
  return settings.native_wheels || entry.modes.empty() ||
         std::find(entry.modes.begin(), entry.modes.end(), settings.mode) != entry.modes.end();
}

}  // namespace

std::vector<std::string_view> engineNames() {
  std::vector<std::string_view> names;
  for (const EngineEntry& entry : detail::engineList()) names.push_back(entry.name);
  return names;
}

std::string engineNameList() { return listed(engineNames()); }

bool servesWheels(const EngineSettings& settings) {
  const EngineEntry* entry = find(settings.engine);
  return entry != nullptr && serves(*entry, settings);
}

void requireEngine(const EngineSettings& settings) {
  const EngineEntry* entry = find(settings.engine);
  if (entry == nullptr) {
    throw InvalidInputError(settings.engine_where + ": unknown engine '" + settings.engine + "' (expected " +
                            engineNameList() + ")");
  }
  if (serves(*entry, settings)) return;
  std::vector<std::string_view> modes;
  for (const ContactMode mode : entry->modes) modes.push_back(contactModeName(mode));
  throw InvalidInputError(settings.engine_where + ": engine '" + settings.engine + "' does not serve contact mode " +
                          std::string(contactModeName(settings.mode)) + " (" + std::string(entry->other_modes) +
                          "); it serves " + listed(modes));
}

std::unique_ptr<Engine> makeEngine(const EngineSettings& settings, const Terrain& terrain,
                                   const vehicle::VehicleDescription& vehicle, const Eigen::Isometry3d& placement) {
  requireEngine(settings);
  return find(settings.engine)->make(settings, terrain, vehicle, placement);
}

}  // namespace wtc::sim
