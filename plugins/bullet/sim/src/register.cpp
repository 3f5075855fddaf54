// Bullet's entry in the engine table (src/sim/engine_entry.hpp): the one
// place that names it for scenes.
#include <span>

#include "sim/engine_entry.hpp"
#include "sim_engine.hpp"

namespace wtc::bullet {

std::span<const sim::EngineEntry> engineEntries() {
  static constexpr sim::EngineEntry kEntries[] = {{.name = "bullet", .make = &makeSimEngine}};
  return kEntries;
}

}  // namespace wtc::bullet
