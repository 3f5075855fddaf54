#include "wtc/sim/make_engine.hpp"

#include "wtc/bullet/sim_engine.hpp"
#include "wtc/ode/sim_engine.hpp"

namespace wtc::sim {

std::unique_ptr<Engine> makeEngine(const EngineSettings& settings, const Terrain& terrain,
                                   const vehicle::VehicleDescription& vehicle, const Eigen::Isometry3d& placement) {
  if (settings.kind == EngineKind::kBullet) return bullet::makeSimEngine(settings, terrain, vehicle, placement);
  return ode::makeSimEngine(settings, terrain, vehicle, placement);
}

}  // namespace wtc::sim
