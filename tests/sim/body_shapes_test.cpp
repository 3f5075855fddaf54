// A body's collision shape is where its description puts it, in every
// engine: a plate given as a convex hull (what a URDF <mesh> becomes) rests
// on the ground where the same plate as a box does, at half its thickness.
// Issue 57 row 1: Bullet put its default 0.04 m margin outside every hull,
// and a mesh plate rested 4 cm high (a mesh nose stopped 41 mm short of a
// ledge).
#include <gtest/gtest.h>

#include <filesystem>

#include "sim_test_support.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/run.hpp"
#include "wtc/sim/scene_file.hpp"
#include "wtc/sim/scene_run.hpp"

namespace wtc::testing {
namespace {

constexpr double kPlateMassKg = 10.0;
const Eigen::Vector3d kPlateSizeM(0.3, 0.2, 0.1);
constexpr double kDropM = 0.01;  // the plate's lowest face above the ground at the start
constexpr double kSettleSeconds = 1.0;
// The engines' own contact: Bullet's terrain hulls keep a 1 mm margin
// (kTerrainMarginM) and both engines let a resting body sink by their
// contact slop; 2 mm bounds both.
constexpr double kRestToleranceM = 2e-3;

vehicle::Shape box() {
  vehicle::Shape s;
  s.kind = vehicle::Shape::Kind::kBox;
  s.box_size = kPlateSizeM;
  return s;
}

vehicle::VehicleDescription plate(vehicle::Shape shape) {
  vehicle::Body b;
  b.name = "plate";
  b.mass = kPlateMassKg;
  b.inertia = vehicle::solidInertia(box(), kPlateMassKg);
  b.shape = std::move(shape);
  vehicle::VehicleDescription v;
  v.name = "plate";
  v.bodies.push_back(std::move(b));
  vehicle::validate(v, "test");
  return v;
}

// The plate's 8 corners, as a mesh's hull gives them.
vehicle::Shape hull() {
  vehicle::Shape s;
  s.kind = vehicle::Shape::Kind::kHull;
  for (const double x : {-0.5, 0.5})
    for (const double y : {-0.5, 0.5})
      for (const double z : {-0.5, 0.5}) s.hull_vertices.push_back(kPlateSizeM.cwiseProduct(Eigen::Vector3d(x, y, z)));
  return s;
}

double restHeight(const sim::EngineSettings& settings, const vehicle::VehicleDescription& v, const Terrain& ground) {
  const Eigen::Isometry3d start(Eigen::Translation3d(0.0, 0.0, 0.5 * kPlateSizeM.z() + kDropM));
  const auto engine = sim::makeEngine(settings, ground, v, start);
  sim::Run run(*engine, nullptr);
  while (run.time() < kSettleSeconds) run.step();
  return engine->body(0).pose.translation().z();
}

class BodyShapesTest : public ::testing::TestWithParam<sim::EngineSettings> {};

TEST_P(BodyShapesTest, AHullRestsWhereTheSameBoxDoes) {
  const Terrain ground = flatGround();
  const double as_box = restHeight(GetParam(), plate(box()), ground);
  const double as_hull = restHeight(GetParam(), plate(hull()), ground);
  EXPECT_NEAR(as_box, 0.5 * kPlateSizeM.z(), kRestToleranceM);
  EXPECT_NEAR(as_hull, 0.5 * kPlateSizeM.z(), kRestToleranceM);
  EXPECT_NEAR(as_hull, as_box, kRestToleranceM);
}

// Issue 57 row 2: a robot standing on a skid plate 2 cm thick given as a
// mesh (tests/urdf/skid_plate.urdf), dropped 7 cm at 1 ms steps. ODE
// collided the plate's hull through libccd, one contact point a step: the
// robot rocked 7 degrees at 0.4 ms steps and at 1 ms was thrown 33 m, its
// energy up 16 kJ. It lands on the plate and stays level, its energy held.
TEST_P(BodyShapesTest, ARobotDroppedOnAThinMeshPlateLandsOnItAndStays) {
  const sim::Scene scene =
      sim::loadScene(std::filesystem::path(WTC_SOURCE_DIR) / "tests/urdf/skid_plate_drop.yaml",
                     std::vector<sim::Override>{{"engine", GetParam().engine}}, sim::requireEngine);
  const auto engine = sim::makeEngine(scene.engine, *scene.terrain, scene.vehicle, scene.placement);
  const sim::RunSummary summary = sim::runScene(scene, *engine);
  EXPECT_TRUE(summary.success) << summary.failed_criteria.size();
  EXPECT_LT(summary.fields.at("max_tilt_deg"), 0.1);
  EXPECT_LT(summary.fields.at("distance_m"), 1e-3);
  // On the plate, not on the wheels: its underside 0.15 m below the base's
  // frame, the wheels' lowest points 0.13 m.
  EXPECT_GT(summary.fields.at("lowest_wheel_height_m"), 0.115);
}

// One mode per engine: the body's own contact is the engine's, whatever
// WTC's wheels do.
std::vector<sim::EngineSettings> everyEngineOnce() {
  std::vector<sim::EngineSettings> all;
  for (const std::string_view engine : sim::engineNames()) all.push_back({.engine = std::string(engine)});
  return all;
}

INSTANTIATE_TEST_SUITE_P(EveryEngine, BodyShapesTest, ::testing::ValuesIn(everyEngineOnce()),
                         [](const auto& info) { return label(info.param); });

}  // namespace
}  // namespace wtc::testing
