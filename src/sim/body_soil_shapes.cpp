// Which bodies meet soft soil (body_soil_shapes.hpp).
#include "body_soil_shapes.hpp"

#include <algorithm>

#include "wtc/vehicle/body_hulls.hpp"

namespace wtc::sim {

std::vector<SoilBodyShape> soilBodyShapes(const EngineSettings& settings, const Terrain& terrain,
                                          const vehicle::VehicleDescription& vehicle) {
  std::vector<SoilBodyShape> out;
  if (!settings.tyre_effects.has(Effect::kSoftSoil)) return out;
  const auto materials = terrain.materials();
  if (std::none_of(materials.begin(), materials.end(), [](const Material& m) { return m.soil.has_value(); })) {
    return out;
  }
  for (std::size_t i = 0; i < vehicle.bodies.size(); ++i) {
    const vehicle::Body& body = vehicle.bodies[i];
    if (body.wheel) continue;
    std::vector<ConvexPolyhedron> hulls = vehicle::convexHulls(body);
    if (!hulls.empty()) out.push_back({.body = static_cast<int>(i), .hulls = std::move(hulls)});
  }
  return out;
}

}  // namespace wtc::sim
