// ODE's entries in the engine table (src/sim/engine_entry.hpp): the one
// place that names its two steppers for scenes.
#include <span>

#include "sim/engine_entry.hpp"
#include "sim_engine.hpp"

namespace wtc::ode {
namespace {

template <Stepper kStepper>
std::unique_ptr<sim::Engine> make(const sim::EngineSettings& settings, const Terrain& terrain,
                                  const vehicle::VehicleDescription& vehicle, const Eigen::Isometry3d& placement) {
  return makeSimEngine(kStepper, settings, terrain, vehicle, placement);
}

}  // namespace

std::span<const sim::EngineEntry> engineEntries() {
  static constexpr sim::EngineEntry kEntries[] = {{.name = "ode", .make = &make<Stepper::kDirect>},
                                                  {.name = "ode_quick", .make = &make<Stepper::kQuick>}};
  return kEntries;
}

}  // namespace wtc::ode
