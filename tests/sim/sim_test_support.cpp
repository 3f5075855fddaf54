#include "sim_test_support.hpp"

#include "wtc/sim/engine_table.hpp"
#include "wtc/terrain/terrain_primitives.hpp"
#include "wtc/vehicle/vehicle_file.hpp"

namespace wtc::sim {

void PrintTo(const EngineSettings& settings, std::ostream* out) {
  *out << settings.engine << ' ' << modeName(settings);
}

}  // namespace wtc::sim

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

std::vector<std::string> everyEngineName(Variants variants) {
  std::vector<std::string> names;
  for (const std::string_view engine : sim::engineNames()) {
    // A variant is named <engine>_<variant> (src/sim/engine_entry.hpp; EngineTableTest).
    if (variants == Variants::kLeftOut && engine.find('_') != std::string_view::npos) continue;
    names.emplace_back(engine);
  }
  return names;
}

std::vector<sim::EngineSettings> everyEngine(Variants variants) {
  std::vector<sim::EngineSettings> all;
  for (const std::string& engine : everyEngineName(variants)) {
    for (const ContactMode mode : {ContactMode::kForce, ContactMode::kConstraint, ContactMode::kImplicit}) {
      const sim::EngineSettings settings{.engine = engine, .mode = mode};
      if (sim::servesWheels(settings)) all.push_back(settings);
    }
  }
  return all;
}

std::vector<std::pair<std::string, std::string>> everyEngineByName(Variants variants) {
  std::vector<std::pair<std::string, std::string>> all;
  for (const sim::EngineSettings& s : everyEngine(variants)) all.emplace_back(s.engine, sim::modeName(s));
  return all;
}

std::vector<sim::EngineSettings> everyNativeWheelBaseline() {
  std::vector<sim::EngineSettings> all;
  for (const std::string_view engine : sim::engineNames()) {
    for (const sim::NativeWheelShape shape : {sim::NativeWheelShape::kCylinder, sim::NativeWheelShape::kSphere}) {
      all.push_back({.engine = std::string(engine), .native_wheels = shape});
    }
  }
  return all;
}

std::string label(const sim::EngineSettings& s) { return s.engine + "_" + std::string(sim::modeName(s)); }

std::vector<sim::Override> atImplicitModeStep(std::vector<sim::Override> overrides) {
  bool implicit = false;
  for (const sim::Override& o : overrides) implicit = implicit || (o.path == "mode" && o.value == "implicit");
  if (implicit) overrides.push_back({"dt", kImplicitModeStep});
  return overrides;
}

}  // namespace wtc::testing
