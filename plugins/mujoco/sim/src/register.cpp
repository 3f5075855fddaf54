// MuJoCo's entry in the engine table (src/sim/engine_entry.hpp).
#include <span>

#include "sim/engine_entry.hpp"
#include "sim_engine.hpp"

namespace wtc::mujoco {

std::span<const sim::EngineEntry> engineEntries() {
  static constexpr ContactMode kModes[] = {ContactMode::kForce, ContactMode::kConstraint};
  static constexpr sim::EngineEntry kEntries[] = {
      {.name = "mujoco",
       .make = &makeSimEngine,
       .modes = kModes,
       .other_modes = "MuJoCo 2.2.2's friction rows take no target velocity, which implicit mode's tread rows need; "
                      "docs/mujoco-plugin.md"}};
  return kEntries;
}

}  // namespace wtc::mujoco
