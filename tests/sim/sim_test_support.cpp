#include "sim_test_support.hpp"

#include "wtc/vehicle/vehicle_file.hpp"
#include "wtc/terrain/terrain_primitives.hpp"

namespace wtc::testing {

vehicle::VehicleDescription shippedVehicle(const std::string& file) {
  return vehicle::loadVehicle(std::string(WTC_SOURCE_DIR) + "/vehicles/" + file);
}

Terrain flatGround() {
  TerrainBuilder builder;
  const MaterialId m = builder.addMaterial(Material{});
  addSlab(builder, SlabParams{.size_x = 20.0, .size_y = 20.0}, m);
  return std::move(builder).build();
}

std::vector<sim::EngineSettings> everyEngine() {
  std::vector<sim::EngineSettings> all;
  for (const sim::EngineKind kind : {sim::EngineKind::kBullet, sim::EngineKind::kOde, sim::EngineKind::kOdeQuick}) {
    for (const ContactMode mode : {ContactMode::kForce, ContactMode::kConstraint}) {
      all.push_back({.kind = kind, .mode = mode});
    }
  }
  return all;
}

std::vector<sim::EngineSettings> everyEngineWheelBaseline() {
  std::vector<sim::EngineSettings> all;
  for (const sim::EngineKind kind : {sim::EngineKind::kBullet, sim::EngineKind::kOde, sim::EngineKind::kOdeQuick}) {
    for (const sim::EngineWheels wheels : {sim::EngineWheels::kCylinder, sim::EngineWheels::kSphere}) {
      all.push_back({.kind = kind, .engine_wheels = wheels});
    }
  }
  return all;
}

std::string label(const sim::EngineSettings& s) {
  return std::string(sim::engineName(s.kind)) + "_" + std::string(sim::modeName(s));
}

}  // namespace wtc::testing
