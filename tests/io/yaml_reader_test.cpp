// Every YAML file WTC reads goes through detail::loadYamlFile, which
// refuses a key given twice in one mapping (yaml-cpp keeps both entries and
// finds the first: the second value was ignored without a word), naming the
// second one's line and column and the first one's line. Overrides replace
// a value; they never add a second key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "temp_dir.hpp"
#include "wtc/io/terrain_file.hpp"
#include "wtc/sim/scene_file.hpp"
#include "wtc/study/study_file.hpp"
#include "wtc/vehicle/vehicle_file.hpp"

namespace wtc::io {
namespace {

using testing::errorOf;
using ::testing::HasSubstr;
using testing::sourceDir;

class DuplicateKeyTest : public testing::TempDirTest {
 protected:
  std::string at(const std::string& name, int line, int column) const {
    return (dir() / name).string() + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
  }
  // A scene of the shipped flat ground and robot, with `extra` lines.
  std::string scene(const std::string& extra) const {
    return "name: s\nduration: 0.2\nterrain: " + (sourceDir() / "terrains/flat.yaml").string() +
           "\nvehicle: " + (sourceDir() / "vehicles/six_wheel_robot.yaml").string() + "\ncontroller: {type: none}\n" +
           extra;
  }
};

TEST_F(DuplicateKeyTest, EveryFileKindRefusesAKeyGivenTwiceNamingBothLines) {
  // Case: a scene's duration, the (the first, 0.2, used to win).
  const auto s = write("scene.yaml", scene("duration: 100\n"));
  EXPECT_THAT(errorOf([&] { sim::loadScene(s); }),
              HasSubstr(at("scene.yaml", 6, 1) + "duplicate key 'duration' (first at line 2): a key may appear once"));
  // Case: a vehicle body's mass, in a block mapping and in a flow mapping.
  const auto v = write("vehicle.yaml",
                       "name: v\nbodies:\n  - name: base\n    mass: 70\n    shape: {box: [1, 1, 1]}\n"
                       "    mass: -5\n");
  EXPECT_THAT(errorOf([&] { vehicle::loadVehicle(v); }),
              HasSubstr(at("vehicle.yaml", 6, 5) + "duplicate key 'mass' (first at line 4)"));
  const auto flow = write("flow.yaml", "name: v\nbodies:\n  - {name: base, mass: 70, shape: {sphere: 1}, mass: -5}\n");
  EXPECT_THAT(errorOf([&] { vehicle::loadVehicle(flow); }),
              HasSubstr(at("flow.yaml", 3, 48) + "duplicate key 'mass' (first at line 3)"));
  // Case: a terrain material's parameter, deep in the file.
  const auto t =
      write("terrain.yaml",
            "materials:\n  ground: {mu_max: 0.8, s1: 0.1, mu_max: 0.2}\npieces:\n  - {type: box, size: [1, 1, 1]}\n");
  EXPECT_THAT(errorOf([&] { loadTerrain(t); }),
              HasSubstr(at("terrain.yaml", 2, 34) + "duplicate key 'mu_max' (first at line 2)"));
  // Case: a study's sweep (the second would have replaced the first's values).
  const auto st = write("study.yaml",
                        "name: s\nbase: {engine: bullet, mode: force, dt: 0.001}\nreference: {}\nsweeps:\n"
                        "  steps: {dt: [0.001]}\n  steps: {dt: [0.002]}\nscenarios: {}\n");
  EXPECT_THAT(errorOf([&] { study::loadStudyPlan(st); }),
              HasSubstr(at("study.yaml", 6, 3) + "duplicate key 'steps' (first at line 5)"));
}

TEST_F(DuplicateKeyTest, SameKeysInDifferentMappingsAndAliasesAreFine) {
  // `x` in two mappings, and one mapping reached twice through an alias.
  const auto t = write("terrain.yaml",
                       "materials:\n  a: &m {mu_max: 0.8}\n  b: *m\npieces:\n"
                       "  - {type: box, material: a, size: [1, 1, 1]}\n"
                       "  - {type: box, material: b, size: [1, 1, 1], translation: [0, 0, 5]}\n");
  EXPECT_EQ(loadTerrain(t).pieceCount(), 2u);
}

TEST_F(DuplicateKeyTest, OverridesReplaceAValueAndTheirOwnDuplicatesAreRefused) {
  const auto s = write("scene.yaml", scene(""));
  // Case: --set of a key the scene has: one key, the new value.
  EXPECT_EQ(sim::loadScene(s, std::vector<sim::Override>{sim::parseOverride("duration=0.5")}).duration_seconds, 0.5);
  EXPECT_EQ(sim::loadScene(
                s, std::vector<sim::Override>{sim::parseOverride("duration=0.5"), sim::parseOverride("duration=0.7")})
                .duration_seconds,
            0.7);
  // Case: a value that is itself a mapping with a key twice.
  EXPECT_THAT(errorOf([&] {
                sim::loadScene(s, std::vector<sim::Override>{sim::parseOverride("output={rate_hz: 50, rate_hz: 1}")});
              }),
              HasSubstr("--set output={rate_hz: 50, rate_hz: 1}: duplicate key 'rate_hz' (first at line 1)"));
}

}  // namespace
}  // namespace wtc::io
