// A vehicle's own body on soft soil in every engine (issue 55: a belly
// dragging in sand; wtc/tyre/body_soil.hpp through the plugins'
// addSoilBody): with the soft_soil effect a plate dropped on sand settles at
// Bekker's plate sinkage instead of on the fresh surface, a plate sliding
// on loam stops where the soil's shear strength (c A + W tan phi) stops it,
// and where the ground remembers it leaves its hollow and rests in it on
// the elastic part of its load. Without the effect
// the soil is hard ground for the bodies, as for the wheels.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "sim_test_support.hpp"
#include "soil_plate.hpp"
#include "wtc/sim/engine.hpp"
#include "wtc/sim/run.hpp"
#include "wtc/sim/start_velocity.hpp"
#include "wtc/tyre/body_soil.hpp"
#include "wtc/tyre/ground_memory.hpp"

namespace wtc::testing {
namespace body_soil_engines_test {

constexpr double kGravity = 9.81;
// A 0.5 m x 0.3 m belly plate whose edges lie on the soil's 2 cm cells'
// edges when centred on the origin (25 x 15 nodes: its area exact).
const Eigen::Vector3d kPlateM(0.5, 0.3, 0.1);
constexpr double kPlateMassKg = 150.0;
constexpr double kSettleSeconds = 1.5;

vehicle::VehicleDescription belly() {
  vehicle::Body b;
  b.name = "belly";
  b.mass = kPlateMassKg;
  b.shape.kind = vehicle::Shape::Kind::kBox;
  b.shape.box_size = kPlateM;
  b.inertia = vehicle::solidInertia(b.shape, kPlateMassKg);
  vehicle::VehicleDescription v;
  v.name = "belly";
  v.bodies.push_back(std::move(b));
  vehicle::validate(v, "body_soil_engines_test");
  return v;
}

// A 6 m x 4 m slab of `soil`, top z = 0, remembering over [-2, 2] x [-1, 1]
// when asked.
Terrain soilGround(const char* soil, bool remember) {
  std::optional<SoilRegion> region;
  if (remember) {
    region.emplace();
    region->origin = {-2.0, -1.0};
    region->size = {4.0, 2.0};
  }
  return soilSlab(soil, 6.0, 4.0, region);
}

sim::EngineSettings withSoil(sim::EngineSettings s, bool soft) {
  s.tyre_effects = soft ? s.tyre_effects.with(Effect::kSoftSoil) : s.tyre_effects.without(Effect::kSoftSoil);
  return s;
}

double bekkerSinkage(const Soil& soil, double load) { return bekkerPlateSinkage(soil, load, kPlateM.x(), kPlateM.y()); }

// The engines one per kind: a body's soil force is the same in every WTC
// contact mode (the modes are the wheels').
class BodySoilEnginesTest : public ::testing::TestWithParam<std::string> {
 protected:
  sim::EngineSettings settings() const {
    sim::EngineSettings s;
    s.engine = GetParam();
    return s;
  }
};

TEST_P(BodySoilEnginesTest, ABellyDroppedOnSandSettlesAtBekkersPlateSinkage) {
  const Terrain sand = soilGround("toyoura_sand", false);
  const Soil soil = *namedSoil("toyoura_sand");
  const vehicle::VehicleDescription v = belly();
  const Eigen::Isometry3d start(Eigen::Translation3d(0.0, 0.0, 0.5 * kPlateM.z() + 0.01));
  for (const bool soft : {true, false}) {
    const auto engine = sim::makeEngine(withSoil(settings(), soft), sand, v, start);
    sim::Run run(*engine, nullptr);
    while (run.time() < kSettleSeconds) run.step();
    const double bottom = engine->body(0).pose.translation().z() - 0.5 * kPlateM.z();
    if (!soft) {
      EXPECT_NEAR(bottom, 0.0, 2e-3) << "without soft_soil the sand is hard ground";
      continue;
    }
    const double bekker = bekkerSinkage(soil, kPlateMassKg * kGravity);
    RecordProperty("bekker_mm", std::to_string(1e3 * bekker));
    RecordProperty(GetParam() + "_sinkage_mm", std::to_string(-1e3 * bottom));
    EXPECT_NEAR(-bottom, bekker, 0.01 * bekker);
    EXPECT_LT(engine->body(0).linear_velocity.norm(), 1e-3);
  }
}

TEST_P(BodySoilEnginesTest, ABellySlidingOnLoamStopsWhereTheSoilsShearStrengthStopsIt) {
  const Terrain loam = soilGround("sandy_loam", false);
  const Soil soil = *namedSoil("sandy_loam");
  const vehicle::VehicleDescription v = belly();
  const double load = kPlateMassKg * kGravity, area = kPlateM.x() * kPlateM.y();
  // Set down at its resting sinkage, moving at v0 along x.
  const double z = bekkerSinkage(soil, load), v0 = 2.0;
  const Eigen::Isometry3d start(Eigen::Translation3d(0.0, 0.0, 0.5 * kPlateM.z() - z));
  const auto engine = sim::makeEngine(withSoil(settings(), true), loam, v, start);
  const sim::BodyVelocity moving{.linear = {v0, 0.0, 0.0}, .angular = Eigen::Vector3d::Zero()};
  engine->setVelocities(std::span(&moving, 1));
  sim::Run run(*engine, nullptr);
  while (run.time() < 1.0) run.step();
  // Coulomb's stop: the drag c A + W tan phi decelerates it uniformly.
  const double drag = soil.cohesion * area + load * std::tan(soil.friction_angle_deg * std::numbers::pi / 180.0);
  const double stop = v0 * v0 * kPlateMassKg / (2.0 * drag);
  const double travelled = engine->body(0).pose.translation().x();
  RecordProperty("coulomb_stop_mm", std::to_string(1e3 * stop));
  RecordProperty(GetParam() + "_stop_mm", std::to_string(1e3 * travelled));
  EXPECT_NEAR(travelled, stop, 0.05 * stop);
  EXPECT_LT(engine->body(0).linear_velocity.norm(), 1e-3);
}

TEST_P(BodySoilEnginesTest, WhereTheGroundRemembersABellyRestsInTheHollowItsDropPressed) {
  const Terrain sand = soilGround("toyoura_sand", true);
  const Soil soil = *namedSoil("toyoura_sand");
  const vehicle::VehicleDescription v = belly();
  const Eigen::Isometry3d start(Eigen::Translation3d(0.0, 0.0, 0.5 * kPlateM.z() + 0.01));
  const auto engine = sim::makeEngine(withSoil(settings(), true), sand, v, start);
  sim::Run run(*engine, nullptr);
  while (run.time() < kSettleSeconds) run.step();
  const GroundMemory& memory = *sim::groundMemory(*engine);
  EXPECT_EQ(memory.touchedNodes(), 25u * 15u);
  // Dropped, it pressed the sand past Bekker's static sinkage (the impact),
  // and the sand keeps the deepest; it rests in that hollow on the elastic
  // part sigma / k_u of its weight's pressure, W / A.
  const double bekker = bekkerSinkage(soil, kPlateMassKg * kGravity);
  const double elastic = kPlateMassKg * kGravity / (kPlateM.x() * kPlateM.y()) / soil.unloading_stiffness;
  const double hollow = memory.at(0.0, 0.0).plastic_sinkage;
  const double rest = 0.5 * kPlateM.z() - engine->body(0).pose.translation().z();
  RecordProperty(GetParam() + "_hollow_mm", std::to_string(1e3 * hollow));
  RecordProperty(GetParam() + "_rests_below_it_um", std::to_string(1e6 * (rest - hollow)));
  RecordProperty("elastic_um", std::to_string(1e6 * elastic));
  EXPECT_GT(hollow, bekker - elastic);
  EXPECT_NEAR(rest - hollow, elastic, 0.1 * elastic);
}

INSTANTIATE_TEST_SUITE_P(Engines, BodySoilEnginesTest, ::testing::Values("bullet", "ode", "ode_quick", "mujoco"),
                         [](const auto& info) { return info.param; });

}  // namespace body_soil_engines_test
}  // namespace wtc::testing
