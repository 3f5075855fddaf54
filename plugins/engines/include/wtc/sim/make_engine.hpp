#pragma once
// The engine a setting names, behind wtc::sim::Engine: the one place that
// knows every engine, so that the runner, the tests and the benchmarks
// need not.
#include <memory>

#include "wtc/sim/engine.hpp"

namespace wtc::sim {

/// Builds `vehicle` on `terrain` (which must outlive the engine) in the
/// engine settings.kind names, its frame placed at `placement`.
std::unique_ptr<Engine> makeEngine(const EngineSettings& settings, const Terrain& terrain,
                                   const vehicle::VehicleDescription& vehicle, const Eigen::Isometry3d& placement);

}  // namespace wtc::sim
