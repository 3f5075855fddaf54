// Vehicle files that name a URDF: the wheels and drives they add, their
// refusals, and the six-wheel robot from URDF equal to the YAML one.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>

#include "scratch_path.hpp"
#include "wtc/base/error.hpp"
#include "wtc/vehicle/controllers/path_controller.hpp"
#include "wtc/vehicle/vehicle_file.hpp"

namespace wtc::vehicle {
namespace urdf_vehicle_file_test {

using ::testing::HasSubstr;
constexpr double kTolerance = 1e-12;
const std::filesystem::path kSource(WTC_SOURCE_DIR);
const std::filesystem::path kUrdf = kSource / "tests" / "urdf";

// A vehicle file in a fresh folder naming `urdf` (absolute) and `body`.
std::filesystem::path writeVehicleFile(const std::string& test, const std::filesystem::path& urdf,
                                       const std::string& body) {
  const std::filesystem::path dir = wtc::test::scratchPath("wtc_urdf_vehicle_" + test);
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / "vehicle.yaml";
  std::ofstream(file) << "name: test\nurdf: " << urdf.string() << "\n" << body;
  return file;
}

// Every field of two descriptions, exactly: the URDFs' decimals read back to
// the YAML loader's doubles.
void expectEqual(const VehicleDescription& yaml, const VehicleDescription& urdf) {
  EXPECT_EQ(urdf.name, yaml.name);
  ASSERT_EQ(urdf.bodies.size(), yaml.bodies.size());
  for (std::size_t i = 0; i < yaml.bodies.size(); ++i) {
    const Body& a = yaml.bodies[i];
    const Body& b = urdf.bodies[i];
    EXPECT_EQ(b.name, a.name);
    EXPECT_EQ(b.mass, a.mass) << a.name;
    EXPECT_EQ(b.inertia, a.inertia) << a.name;
    EXPECT_EQ(b.pose.matrix(), a.pose.matrix()) << a.name;
    EXPECT_EQ(b.parent, a.parent) << a.name;
    EXPECT_EQ(b.shape.kind, a.shape.kind) << a.name;
    EXPECT_EQ(b.shape.box_size, a.shape.box_size) << a.name;
    EXPECT_EQ(b.shape.cylinder_axis, a.shape.cylinder_axis) << a.name;
    EXPECT_TRUE(b.compound.empty()) << a.name;
    EXPECT_EQ(b.joint.type, a.joint.type) << a.name;
    EXPECT_EQ(b.joint.anchor, a.joint.anchor) << a.name;
    EXPECT_EQ(b.joint.axis, a.joint.axis) << a.name;
    ASSERT_EQ(b.joint.limits.has_value(), a.joint.limits.has_value()) << a.name;
    if (a.joint.limits) {
      EXPECT_EQ(b.joint.limits->upper, a.joint.limits->upper) << a.name;
    }
    ASSERT_EQ(b.joint.actuator.has_value(), a.joint.actuator.has_value()) << a.name;
    if (a.joint.actuator) {
      EXPECT_EQ(b.joint.actuator->max_effort, a.joint.actuator->max_effort) << a.name;
      EXPECT_EQ(b.joint.actuator->max_speed, a.joint.actuator->max_speed) << a.name;
      EXPECT_EQ(b.joint.actuator->position_gain, a.joint.actuator->position_gain) << a.name;
    }
    ASSERT_EQ(b.wheel.has_value(), a.wheel.has_value()) << a.name;
    if (a.wheel) {
      EXPECT_EQ(b.wheel->geometry.free_radius, a.wheel->geometry.free_radius);
      EXPECT_EQ(b.wheel->geometry.tread_width, a.wheel->geometry.tread_width);
      EXPECT_EQ(b.wheel->axle, a.wheel->axle);
      EXPECT_EQ(b.wheel->tyre.radial_stiffness, a.wheel->tyre.radial_stiffness);
      EXPECT_EQ(b.wheel->tyre.radial_damping, a.wheel->tyre.radial_damping);
      EXPECT_EQ(b.wheel->tyre.tangential_stiffness, a.wheel->tyre.tangential_stiffness);
    }
  }
  ASSERT_EQ(urdf.hitch.has_value(), yaml.hitch.has_value());
  if (yaml.hitch) {
    EXPECT_EQ(urdf.hitch->body_a, yaml.hitch->body_a);
    EXPECT_EQ(urdf.hitch->body_b, yaml.hitch->body_b);
    EXPECT_EQ(urdf.hitch->point_a, yaml.hitch->point_a);
    EXPECT_EQ(urdf.hitch->point_b, yaml.hitch->point_b);
    EXPECT_EQ(urdf.hitch->stiffness, yaml.hitch->stiffness);
    EXPECT_EQ(urdf.hitch->damping, yaml.hitch->damping);
  }
}

TEST(UrdfVehicleFileTest, SixWheelRobotFromUrdfEqualsTheYamlRobot) {
  expectEqual(loadVehicle(kSource / "vehicles" / "six_wheel_robot.yaml"),
              loadVehicle(kSource / "vehicles" / "six_wheel_robot_urdf.yaml"));
}

// Two URDFs and two YAML casters in order, with the hitch.
TEST(UrdfVehicleFileTest, TowedSystemFromTwoUrdfsEqualsTheYamlOne) {
  expectEqual(loadVehicle(kSource / "vehicles" / "towed_system.yaml"),
              loadVehicle(kSource / "vehicles" / "towed_system_urdf.yaml"));
}

TEST(UrdfVehicleFileTest, WheelTakesRadiusWidthAndAxleFromItsCylinderAndJoint) {
  // Case 7: a cylinder turned onto the link's x, the joint's axis, on a joint turned by Rz(-90 deg).
  const VehicleDescription v = loadVehicle(writeVehicleFile("case7", kUrdf / "wheel_cylinder_on_rotated_joint.urdf",
                                                            "wheels: [{link: wheel, tyre: {radial_stiffness: 2.0e4}}]\n"
                                                            "drives: {wheel_joint: {}}\n"));
  const Body& wheel = v.bodies.at(v.find("wheel"));
  ASSERT_TRUE(wheel.wheel);
  EXPECT_EQ(wheel.wheel->geometry.free_radius, 0.1);
  EXPECT_EQ(wheel.wheel->geometry.tread_width, 0.08);
  EXPECT_EQ(wheel.wheel->tyre.radial_stiffness, 2.0e4);
  EXPECT_TRUE(wheel.pose.translation().isApprox(Eigen::Vector3d(0, 0.3, 0.1), kTolerance));
  EXPECT_TRUE((wheel.pose.linear() * wheel.wheel->axle).isApprox(Eigen::Vector3d(0, -1, 0), kTolerance));
  EXPECT_EQ(wheel.inertia.x(), 0.005);  // the axial moment about the link's x
  ASSERT_TRUE(wheel.joint.actuator);
  EXPECT_EQ(wheel.joint.actuator->max_effort, 15.0);
  EXPECT_EQ(wheel.joint.actuator->max_speed, 3.0);
}

void expectRefused(const std::string& test, const std::filesystem::path& urdf, const std::string& body,
                   const std::vector<std::string>& fragments) {
  const std::filesystem::path file = writeVehicleFile(test, urdf, body);
  try {
    loadVehicle(file);
    ADD_FAILURE() << test << " was accepted";
  } catch (const InvalidInputError& e) {
    EXPECT_THAT(e.what(), HasSubstr(file.string()));
    for (const std::string& f : fragments) EXPECT_THAT(e.what(), HasSubstr(f));
  }
}

TEST(UrdfVehicleFileTest, RefusesAWheelWhoseCylinderIsNotAlongItsJoint) {
  expectRefused("misaligned", kUrdf / "wheel_cylinder_misaligned.urdf", "wheels: [{link: wheel}]\n",
                {"wheel_cylinder_misaligned.urdf", "link 'wheel'", "cylinder", "axis"});
}

TEST(UrdfVehicleFileTest, RefusesAWheelWithoutCylinderUnlessItsRadiusIsGiven) {
  expectRefused("no_cylinder", kUrdf / "wheel_without_cylinder.urdf", "wheels: [{link: wheel}]\n",
                {"link 'wheel' has no cylinder"});
  const VehicleDescription v = loadVehicle(writeVehicleFile("no_cylinder_given", kUrdf / "wheel_without_cylinder.urdf",
                                                            "wheels: [{link: wheel, radius: 0.1, width: 0.05}]\n"));
  EXPECT_EQ(v.bodies.at(v.find("wheel")).wheel->geometry.free_radius, 0.1);
}

TEST(UrdfVehicleFileTest, RefusesDrivesAndWheelsNamingWhatTheUrdfLacks) {
  const std::filesystem::path rover = kSource / "vehicles" / "rocker_bogie_rover.urdf";
  const std::string package = "package_path: [" + (kSource / "vehicles").string() + "]\n";
  expectRefused(
      "drive_missing", rover, package + "drives: {front_left_wheel: {}}\n",
      {"joint 'front_left_wheel' is not a revolute, continuous or prismatic joint of", "rocker_bogie_rover.urdf"});
  expectRefused("wheel_missing", rover, package + "wheels: [{link: front_left_tyre}]\n",
                {"link 'front_left_tyre' is not a link of", "rocker_bogie_rover.urdf"});
  expectRefused("drive_without_limit", kSource / "vehicles" / "towed_system_towed.urdf",
                "drives: {nose_wheel_joint: {}}\n", {"joint 'nose_wheel_joint' has no <limit effort velocity>"});
}

TEST(UrdfVehicleFileTest, RefusalsInsideTheUrdfNameBothFiles) {
  expectRefused("floating", kUrdf / "floating_joint.urdf", "",
                {"floating_joint.urdf", "joint 'payload_joint' is floating"});
}

// The rover's chassis has products of inertia: the engines integrate it in
// its principal axes, turned from the link's. Its own axes are the link's
// (the root link's: the vehicle frame), and the path controller steers by
// them: C is `lead` ahead of the middle axle along the chassis link's x.
TEST(UrdfVehicleFileTest, PathControllerSteersByTheBodysOwnAxesNotItsPrincipalAxes) {
  const VehicleDescription rover = loadVehicle(kSource / "vehicles" / "rocker_bogie_rover.yaml");
  const Body& chassis = rover.bodies.at(rover.find("chassis"));
  ASSERT_FALSE(chassis.pose.linear().isIdentity(1e-6));
  EXPECT_TRUE(ownFrame(chassis, chassis.pose).linear().isIdentity(1e-12));
  const PathController path(
      rover, {.body = "chassis", .left_drive = "middle_left_wheel", .right_drive = "middle_right_wheel", .lead = 0.2},
      "scene.yaml");
  const Eigen::Vector3d axle = 0.5 * (rover.bodies.at(rover.find("middle_left_wheel")).pose.translation() +
                                      rover.bodies.at(rover.find("middle_right_wheel")).pose.translation());
  const Eigen::Vector2d expected = (axle + Eigen::Vector3d(0.2, 0, 0)).head<2>();
  EXPECT_LT((path.pointC(chassis.pose) - expected).norm(), 1e-12);
  // Turned 90 degrees about z in the world, C turns with the link's x.
  const Eigen::Isometry3d turned = Eigen::Isometry3d(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ())) * chassis.pose;
  EXPECT_LT((path.pointC(turned) - Eigen::Vector2d(-expected.y(), expected.x())).norm(), 1e-12);
}

}  // namespace urdf_vehicle_file_test
}  // namespace wtc::vehicle
