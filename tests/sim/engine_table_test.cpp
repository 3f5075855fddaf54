// The engine table (wtc::sim_engines): it lists exactly the engines this
// build declares (plugins/bullet registers "bullet", plugins/ode "ode" and
// "ode_quick"), each name makes that engine, and a name it does not have is
// refused with the known names and where the name came from.
#include "wtc/sim/engine_table.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "sim_test_support.hpp"
#include "wtc/base/error.hpp"
#include "wtc/sim/scene_file.hpp"

namespace wtc::testing {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;
namespace fs = std::filesystem;

// Each engine declared with wtc_add_engine (WTC_DECLARED_ENGINES, from
// CMake) owns its own name and any "<engine>_<variant>": the table holds
// each declared engine's own name (its registration reached the link), and
// no name that no declared engine owns, none twice.
TEST(EngineTableTest, ListsExactlyTheEnginesThisBuildDeclares) {
  std::vector<std::string> declared;
  for (std::string_view rest = WTC_DECLARED_ENGINES; !rest.empty();) {
    const std::size_t comma = rest.find(',');
    declared.emplace_back(rest.substr(0, comma));
    rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
  }
  ASSERT_FALSE(declared.empty());
  const std::vector<std::string_view> names = sim::engineNames();
  for (const std::string& engine : declared) {
    EXPECT_EQ(std::count(names.begin(), names.end(), engine), 1) << engine << ": declared, not in the table once";
  }
  for (const std::string_view name : names) {
    const auto owns = [&](const std::string& engine) {
      return name == engine || (name.size() > engine.size() + 1 && name.substr(0, engine.size() + 1) == engine + "_");
    };
    EXPECT_EQ(std::count_if(declared.begin(), declared.end(), owns), 1) << name << ": no declared engine owns it";
    EXPECT_EQ(std::count(names.begin(), names.end(), name), 1) << name << ": listed twice";
  }
}

// The names scenes, studies and summaries use for Bullet and ODE, in the
// order plugins/CMakeLists.txt declares the engines.
TEST(EngineTableTest, BulletAndOdeKeepTheirSceneNames) {
  const std::vector<std::string_view> names = sim::engineNames();
  ASSERT_GE(names.size(), 3u);
  EXPECT_EQ(std::vector<std::string_view>(names.begin(), names.begin() + 3),
            (std::vector<std::string_view>{"bullet", "ode", "ode_quick"}));
}

// Case: every name makes an engine that steps; "ode" and "ode_quick" are
// two steppers of one engine, so their first steps of a falling robot
// agree to ODE's solver difference only, not to the bit.
TEST(EngineTableTest, EachNameMakesItsEngine) {
  const Terrain ground = flatGround();
  const vehicle::VehicleDescription robot = shippedVehicle("six_wheel_robot.yaml");
  const Eigen::Isometry3d above(Eigen::Translation3d(0, 0, 0.1));
  std::vector<Eigen::Vector3d> after;
  for (const std::string_view name : sim::engineNames()) {
    const auto engine = sim::makeEngine({.engine = std::string(name)}, ground, robot, above);
    ASSERT_NE(engine, nullptr) << name;
    EXPECT_EQ(engine->settings().engine, name);
    for (int k = 0; k < 600; ++k) engine->step();
    after.push_back(engine->body(0).pose.translation());
    EXPECT_TRUE(after.back().allFinite()) << name;
    EXPECT_LT(after.back().z(), 0.1 + robot.bodies[0].pose.translation().z()) << name << ": it fell";
  }
  ASSERT_GE(after.size(), 3u);
  EXPECT_NE(after[1], after[2]) << "ode and ode_quick stepped alike: one stepper for both names";
}

// Case: an engine that serves only some WTC contact modes (MuJoCo: no
// implicit mode) is refused another with its reason, before anything is
// built, and the table says which it serves; every engine serves its own
// wheels.
TEST(EngineTableTest, AModeAnEngineDoesNotServeIsRefusedWithItsReason) {
  const Terrain ground = flatGround();
  const vehicle::VehicleDescription robot = shippedVehicle("six_wheel_robot.yaml");
  const sim::EngineSettings implicit{.engine = "mujoco", .mode = ContactMode::kImplicit};
  EXPECT_FALSE(sim::servesWheels(implicit));
  EXPECT_TRUE(sim::servesWheels({.engine = "mujoco", .mode = ContactMode::kConstraint}));
  EXPECT_TRUE(sim::servesWheels({.engine = "mujoco", .native_wheels = sim::NativeWheelShape::kSphere}));
  EXPECT_TRUE(sim::servesWheels({.engine = "ode", .mode = ContactMode::kImplicit}));
  EXPECT_FALSE(sim::servesWheels({.engine = "physx"}));
  EXPECT_THAT([&] { sim::makeEngine(implicit, ground, robot, Eigen::Isometry3d::Identity()); },
              ThrowsMessage<InvalidInputError>(AllOf(
                  HasSubstr("engine: engine 'mujoco' does not serve contact mode implicit (MuJoCo 2.2.2's friction "
                            "rows take no target velocity"),
                  HasSubstr("it serves force or constraint"))));
}

// "(expected bullet, ode, ode_quick or mujoco)" for this build: every name of the table.
std::string knownNames() {
  const std::vector<std::string_view> names = sim::engineNames();
  std::string known = "(expected ";
  for (std::size_t i = 0; i < names.size(); ++i) {
    known += std::string(i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + std::string(names[i]);
  }
  return known + ")";
}

TEST(EngineTableTest, AnUnknownNameIsRefusedWithTheKnownNames) {
  const Terrain ground = flatGround();
  const vehicle::VehicleDescription robot = shippedVehicle("six_wheel_robot.yaml");
  const auto make = [&](const sim::EngineSettings& settings) {
    return sim::makeEngine(settings, ground, robot, Eigen::Isometry3d::Identity());
  };
  // Case: set in code, the message names the field.
  EXPECT_THAT([&] { make({.engine = "physx"}); },
              ThrowsMessage<InvalidInputError>(HasSubstr("engine: unknown engine 'physx' " + knownNames())));
  // Case: from a scene file, its line and column (the reader keeps the place).
  const fs::path scene = fs::path(WTC_SOURCE_DIR) / "scenes" / "robot_straight.yaml";
  const sim::Scene from_file = sim::loadScene(scene);
  sim::EngineSettings misspelt = from_file.engine;
  misspelt.engine = "bulet";
  EXPECT_THAT([&] { make(misspelt); }, ThrowsMessage<InvalidInputError>(HasSubstr(
                                           "robot_straight.yaml:9:9: engine: unknown engine 'bulet' " + knownNames())));
  // Case: from an override (wtc-sim --engine), the override.
  const std::vector<sim::Override> overrides = {sim::parseOverride("engine=physx")};
  const sim::Scene overridden = sim::loadScene(scene, overrides);
  EXPECT_THAT([&] { sim::requireEngine(overridden.engine); },
              ThrowsMessage<InvalidInputError>(HasSubstr(
                  "robot_straight.yaml: --set engine=physx: engine: unknown engine 'physx' " + knownNames())));
  // Case: checked as the scene is read (sim::loadScene's EngineCheck), before
  // its terrain is built: here a terrain that is not there is never reached.
  const std::vector<sim::Override> misspelt_first = {sim::parseOverride("engine=bulet"),
                                                     sim::parseOverride("terrain=no_such_terrain.yaml")};
  EXPECT_THAT([&] { sim::loadScene(scene, misspelt_first, sim::requireEngine); },
              ThrowsMessage<InvalidInputError>(HasSubstr("--set engine=bulet: engine: unknown engine 'bulet' ")));
  // Case: this build's names, as scenes/README.md and docs/bad-input.md show them.
  EXPECT_THAT(knownNames(), ::testing::StartsWith("(expected bullet, ode"));
}

}  // namespace
}  // namespace wtc::testing
