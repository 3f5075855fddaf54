// Vehicle files: the shipped vehicles load with the spec's numbers, and bad
// files are refused with the file, line, body and problem.
#include "wtc/vehicle/vehicle_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>

#include "scratch_path.hpp"
#include "wtc/base/error.hpp"

namespace wtc::vehicle {
namespace vehicle_file_test {

using ::testing::HasSubstr;
using vehicle::JointType;
constexpr double kTolerance = 1e-12;
const std::filesystem::path kVehicles = std::filesystem::path(WTC_SOURCE_DIR) / "vehicles";

TEST(VehicleFileTest, RobotHasTheSpecsMassWheelbaseAndDrives) {
  const vehicle::VehicleDescription robot = loadVehicle(kVehicles / "six_wheel_robot.yaml");
  // Spec: 126 kg (70 + 2 x 9 + 2 x 8 + 6 x 3.7 = 126.2).
  EXPECT_NEAR(robot.totalMass(), 126.2, 1e-9);
  ASSERT_EQ(robot.wheels().size(), 6u);
  // Spec: wheelbase 0.86 m retracted and level; r_f = 0.19 m.
  const auto centre = [&](const char* name) { return robot.bodies[robot.find(name)].pose.translation(); };
  EXPECT_NEAR(centre("front_left_wheel").x() - centre("rear_left_wheel").x(), 0.86, kTolerance);
  for (const int w : robot.wheels()) {
    const vehicle::Body& wheel = robot.bodies[w];
    EXPECT_EQ(wheel.wheel->geometry.free_radius, 0.19) << wheel.name;
    EXPECT_NEAR(wheel.inertia.y(), 0.5 * 3.7 * 0.19 * 0.19, kTolerance) << wheel.name;
    ASSERT_TRUE(wheel.joint.actuator) << wheel.name;
    EXPECT_EQ(wheel.joint.actuator->max_speed, 5.0);  // spec: 5 rad/s
  }
  // Spec: folds +-90 deg, extensions 0.18 m.
  const vehicle::Body& fold = robot.bodies[robot.find("front_carrier")];
  EXPECT_EQ(fold.joint.type, JointType::kRevolute);
  EXPECT_NEAR(fold.joint.limits->upper, std::numbers::pi / 2, kTolerance);
  const vehicle::Body& slide = robot.bodies[robot.find("rear_slider")];
  EXPECT_EQ(slide.joint.type, JointType::kPrismatic);
  EXPECT_EQ(slide.joint.limits->upper, 0.18);
  EXPECT_EQ(robot.actuated().size(), 10u);  // six wheels, two folds, two slides
}

TEST(VehicleFileTest, TowedSystemHasTwoRootsAndAHitchWhosePointsMeet) {
  const vehicle::VehicleDescription towed = loadVehicle(kVehicles / "towed_system.yaml");
  ASSERT_TRUE(towed.hitch);
  const vehicle::Hitch& h = *towed.hitch;
  const Eigen::Vector3d d1 = towed.bodies[h.body_a].pose * h.point_a;
  const Eigen::Vector3d d2 = towed.bodies[h.body_b].pose * h.point_b;
  EXPECT_NEAR((d1 - d2).norm(), 0.0, kTolerance);  // no preload at the reference
  int roots = 0;
  for (const auto& b : towed.bodies) roots += b.parent < 0;
  EXPECT_EQ(roots, 2);
  EXPECT_EQ(towed.bodies[towed.find("tug_front_caster")].joint.type, JointType::kBall);
  EXPECT_EQ(towed.bodies[towed.find("nose_fork")].joint.axis, Eigen::Vector3d::UnitZ());
  EXPECT_EQ(towed.actuated().size(), 2u);  // only the tug's two drive wheels
}

std::string errorOfFile(const std::string& text) {
  const auto path = wtc::test::scratchPath("wtc_vehicle_file_test.yaml");
  std::ofstream(path) << text;
  try {
    loadVehicle(path);
  } catch (const InvalidInputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(VehicleFileTest, BadFilesAreRefusedWithFileLineBodyAndProblem) {
  const std::string head = "name: v\nbodies:\n  - name: base\n    mass: 10\n    shape: {box: [1, 1, 1]}\n";
  // Case: a typo in a key.
  EXPECT_THAT(errorOfFile(head + "  - name: arm\n    parent: base\n    mas: 2\n"),
              HasSubstr("wtc_vehicle_file_test.yaml:8:5: bodies[1] (arm): unknown key 'mas'"));
  // Case: a list item that is not a mapping (found by wtc_fuzz_vehicle: yaml-cpp's
  // "operator[] call on a scalar" escaped as a YAML::Exception).
  EXPECT_THAT(errorOfFile(head + "  - namee ground is z = 0\n"),
              HasSubstr("wtc_vehicle_file_test.yaml:6:5: bodies[1] must be a mapping (key: value lines)"));
  // Case: a tagged key inside a flow mapping (found by wtc_fuzz_vehicle with a
  // fixed seed: yaml-cpp's "bad conversion" escaped as a YAML::Exception).
  EXPECT_THAT(errorOfFile(head + "  - name: w\n    parent: base\n    mass: 5\n"
                                 "    wheel: {radius: 0.15, width: 0.30,!tyre: {radial_stiffness: 2.0e5}}\n"),
              HasSubstr("wtc_vehicle_file_test.yaml:"));
  // Case: a value of the wrong type.
  EXPECT_THAT(errorOfFile("name: v\nbodies:\n  - name: base\n    mass: heavy\n    shape: {sphere: 1}\n"),
              HasSubstr(":4:11: bodies[0] (base): mass: 'heavy' is not a number"));
  // Case: a parent that does not exist.
  EXPECT_THAT(
      errorOfFile(head + "  - {name: arm, parent: nobody, mass: 1, shape: {sphere: 1}, joint: {type: fixed}}\n"),
      HasSubstr("parent 'nobody' is not a body listed before this one"));
  // Case: a negative radius.
  EXPECT_THAT(errorOfFile(head + "  - {name: w, parent: base, mass: 1, wheel: {radius: -0.2, width: 0.1}, "
                                 "joint: {type: revolute}}\n"),
              HasSubstr(":6:54: bodies[1] (w): wheel.radius: -0.2 must be > 0 (m)"));
  // Case: an unknown joint type, and a drive on a ball joint.
  EXPECT_THAT(errorOfFile(head + "  - {name: a, parent: base, mass: 1, shape: {sphere: 1}, joint: {type: hinge}}\n"),
              HasSubstr("'hinge' is not revolute, prismatic, ball or fixed"));
  EXPECT_THAT(errorOfFile(head + "  - {name: a, parent: base, mass: 1, shape: {sphere: 1}, "
                                 "joint: {type: ball, drive: {max_effort: 1, max_speed: 1}}}\n"),
              HasSubstr("a ball joint cannot be driven"));
  // Case: a body with neither shape nor inertia; a missing file; a hitch to nobody.
  EXPECT_THAT(errorOfFile("name: v\nbodies:\n  - {name: base, mass: 10}\n"),
              HasSubstr("a body without a shape needs 'inertia'"));
  EXPECT_THAT(errorOfFile(head + "hitch: {body_a: base, body_b: ghost, point_a: [0,0,0], point_b: [0,0,0], "
                                 "stiffness: [1,1,1], damping: [1,1,1]}\n"),
              HasSubstr("body_b: no body 'ghost'"));
  try {
    loadVehicle(kVehicles / "no_such_vehicle.yaml");
    FAIL();
  } catch (const InvalidInputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("no_such_vehicle.yaml: file not found"));
  }
}

// A wheel's radius of 0 was reported as its disc's inertia; sizes are now
// checked at the value, with the value.
TEST(VehicleFileTest, SizesAreRefusedAtTheirValue) {
  const std::string head = "name: v\nbodies:\n  - name: base\n    mass: 10\n    shape: {box: [1, 1, 1]}\n";
  const std::string wheel =
      "  - {name: w, parent: base, mass: 1, joint: {type: revolute}, wheel: {width: 0.1, radius: ";
  EXPECT_THAT(
      errorOfFile(head + wheel + "0}}\n"),
      testing::AllOf(HasSubstr("wtc_vehicle_file_test.yaml:6:91: bodies[1] (w): wheel.radius: 0 must be > 0 (m)"),
                     testing::Not(HasSubstr("inertia"))));
  EXPECT_THAT(errorOfFile(head + wheel + "1e300}}\n"),
              HasSubstr(":6:91: bodies[1] (w): wheel.radius: 1e+300 m is beyond the largest length a description may "
                        "give, 1e+06 m (wtc::kMaxLengthM)"));
  EXPECT_THAT(errorOfFile("name: v\nbodies:\n  - {name: base, mass: 10, shape: {box: [0.5, 1e300, 1]}}\n"),
              HasSubstr(":3:47: bodies[0] (base): shape.box[1]: 1e+300 m is beyond the largest length"));
  EXPECT_THAT(
      errorOfFile("name: v\nbodies:\n  - {name: base, mass: 10, shape: {cylinder: {radius: 0.1, length: 0}}}\n"),
      HasSubstr(":3:68: bodies[0] (base): shape.cylinder.length: 0 must be > 0 (m)"));
}

// Values a wheel inherits from wheel_defaults were read from a copy whose
// positions were all 1:1; they are named at their line in wheel_defaults,
// with the wheel that inherited them.
TEST(VehicleFileTest, ErrorsInInheritedValuesNameTheirLineInWheelDefaultsAndTheWheel) {
  const std::string defaults = "name: v\nwheel_defaults:\n  mass: 3.7\n  joint: {type: revolute}\n  wheel:\n";
  const std::string bodies =
      "bodies:\n  - {name: base, mass: 10, shape: {box: [1, 1, 1]}}\n  - {name: w1, parent: base, wheel: {}}\n";
  // Case: a word for a radius, a radius of 0, a negative tyre stiffness.
  EXPECT_THAT(errorOfFile(defaults + "    radius: abc\n    width: 0.1\n" + bodies),
              HasSubstr("wtc_vehicle_file_test.yaml:6:13: bodies[1] (w1): wheel.radius: 'abc' is not a number "
                        "(inherited from wheel_defaults by wheel 'w1')"));
  EXPECT_THAT(errorOfFile(defaults + "    radius: 0\n    width: 0.1\n" + bodies),
              HasSubstr(":6:13: bodies[1] (w1): wheel.radius: 0 must be > 0 (m) (inherited from wheel_defaults by "
                        "wheel 'w1')"));
  EXPECT_THAT(errorOfFile(defaults + "    radius: 0.2\n    width: 0.1\n    tyre: {radial_stiffness: -1}\n" + bodies),
              HasSubstr(":8:30: bodies[1] (w1): wheel: tyre radial_stiffness = -1 must be finite and > 0 (N/m) "
                        "(inherited from wheel_defaults by wheel 'w1')"));
  // Case: the same mistake made by the wheel itself is at its own line, not inherited.
  EXPECT_THAT(errorOfFile(defaults + "    radius: 0.2\n    width: 0.1\n" +
                          "bodies:\n  - {name: base, mass: 10, shape: {box: [1, 1, 1]}}\n"
                          "  - {name: w1, parent: base, wheel: {radius: 0}}\n"),
              testing::AllOf(HasSubstr(":10:46: bodies[1] (w1): wheel.radius: 0 must be > 0 (m)"),
                             testing::Not(HasSubstr("inherited"))));
  // Case: a key misspelt in wheel_defaults, at its line there.
  EXPECT_THAT(errorOfFile(defaults + "    radius: 0.2\n    width: 0.1\n  mas: 2\n" + bodies),
              HasSubstr(":8:3: bodies[1] (w1): unknown key 'mas'"));
}

}  // namespace vehicle_file_test
}  // namespace wtc::vehicle
