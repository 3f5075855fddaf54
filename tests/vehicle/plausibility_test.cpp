// Plausibility warnings (wtc/vehicle/plausibility.hpp): the shipped vehicles
// give none; the unit slips of issue 57 row 8 each give one naming the body
// and the likely slip (masses in grams, lengths in millimetres, rpy in
// degrees), and nothing is refused.
#include "wtc/vehicle/plausibility.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "wtc/vehicle/vehicle_file.hpp"

namespace wtc::vehicle {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

VehicleDescription shipped(const std::string& name) {
  return loadVehicle(fs::path(WTC_SOURCE_DIR) / "vehicles" / name);
}

TEST(PlausibilityTest, TheShippedVehiclesGiveNone) {
  for (const char* name : {"six_wheel_robot.yaml", "towed_system.yaml", "rocker_bogie_rover.yaml",
                           "six_wheel_robot_urdf.yaml", "towed_system_urdf.yaml"}) {
    EXPECT_THAT(plausibilityWarnings(shipped(name)), ::testing::IsEmpty()) << name;
  }
}

TEST(PlausibilityTest, MassesInGramsLengthsInMillimetresAndRpyInDegreesAreSaid) {
  // Case: every mass a thousand times (grams written as kilograms): the tyres deflect through their wheels.
  VehicleDescription grams = shipped("six_wheel_robot.yaml");
  for (Body& b : grams.bodies) b.mass *= 1000.0;
  const std::vector<std::string> heavy = plausibilityWarnings(grams);
  ASSERT_EQ(heavy.size(), grams.wheels().size());
  EXPECT_THAT(heavy[0], HasSubstr("wheel 'middle_left_wheel': under an equal share of its body's weight"));
  EXPECT_THAT(heavy[0], HasSubstr("masses in grams"));
  // Case: a body placed in millimetres.
  VehicleDescription millimetres = shipped("six_wheel_robot.yaml");
  millimetres.bodies[1].pose.translation() *= 1000.0;
  EXPECT_THAT(plausibilityWarnings(millimetres),
              ::testing::ElementsAre(HasSubstr("body 'middle_left_wheel' is 338.4 m from the vehicle's origin: "
                                               "lengths in millimetres?")));
  // Case: a wheel turned by 90 rad about x (rpy="90 0 0" meant in degrees): its axle leaves the horizontal.
  VehicleDescription degrees = shipped("six_wheel_robot.yaml");
  Body& wheel = degrees.bodies[1];
  wheel.pose.linear() = Eigen::AngleAxisd(90.0, Eigen::Vector3d::UnitX()).toRotationMatrix() * wheel.pose.linear();
  EXPECT_THAT(plausibilityWarnings(degrees),
              ::testing::ElementsAre(HasSubstr("wheel 'middle_left_wheel': its axle is 63 deg off the horizontal")));
}

}  // namespace
}  // namespace wtc::vehicle
