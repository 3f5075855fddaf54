// The engines build a vehicle as described and hold it as physics says:
// the robot standing on flat ground carries exactly its weight (statics)
// with its joints together, in every engine and contact mode.
#include <gtest/gtest.h>

#include "sim_test_support.hpp"
#include "wtc/constants.hpp"
#include "wtc/sim/make_engine.hpp"
#include "wtc/sim/run.hpp"
#include "wtc/vehicle/schedule_controller.hpp"

namespace wtc::testing {
namespace {

constexpr double kPoseToleranceM = 1e-9;      // built pose = described pose (double precision throughout)
constexpr double kWeightTolerance = 0.005;    // the 0.5 % of m g
constexpr double kJointGapToleranceM = 1e-3;  // the 1 mm
constexpr double kJointAngleToleranceRad = 0.1 * 3.14159265358979 / 180.0;  // and 0.1 deg
constexpr double kSettleSeconds = 1.5;  // the stiffest mode (tyre ~20 Hz, damping ratio 0.3) settles in 0.2 s

class SimEngineTest : public ::testing::TestWithParam<sim::EngineSettings> {};

// The wheels hold zero rate, the sections their reference positions.
std::vector<vehicle::DriveSchedule> holdStill(const vehicle::VehicleDescription& v) {
  vehicle::DriveSchedule wheels{.drives = {}, .mode = vehicle::DriveMode::kVelocity, .points = {{0.0, 0.0}}};
  vehicle::DriveSchedule joints{.drives = {}, .mode = vehicle::DriveMode::kPosition, .points = {{0.0, 0.0}}};
  for (const int b : v.actuated()) (v.bodies[b].wheel ? wheels : joints).drives.push_back(v.bodies[b].name);
  return {wheels, joints};
}

TEST_P(SimEngineTest, BuildsEveryBodyWhereTheDescriptionPlacesIt) {
  const Terrain ground = flatGround();
  const vehicle::VehicleDescription robot = shippedVehicle("six_wheel_robot.yaml");
  const Eigen::Isometry3d placement =
      Eigen::Translation3d(1.0, -2.0, 0.05) * Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ());
  const auto engine = sim::makeEngine(GetParam(), ground, robot, placement);
  for (std::size_t i = 0; i < robot.bodies.size(); ++i) {
    const vehicle::BodyKinematics k = engine->body(static_cast<int>(i));
    const Eigen::Isometry3d expected = placement * robot.bodies[i].pose;
    EXPECT_LT((k.pose.translation() - expected.translation()).norm(), kPoseToleranceM) << robot.bodies[i].name;
    EXPECT_LT((k.pose.linear() - expected.linear()).norm(), kPoseToleranceM) << robot.bodies[i].name;
    EXPECT_EQ(engine->jointPosition(static_cast<int>(i)), 0.0) << robot.bodies[i].name;
  }
}

TEST_P(SimEngineTest, StandingRobotCarriesItsWeightWithItsJointsTogether) {
  const Terrain ground = flatGround();
  const vehicle::VehicleDescription robot = shippedVehicle("six_wheel_robot.yaml");
  const auto engine = sim::makeEngine(GetParam(), ground, robot, Eigen::Isometry3d::Identity());
  vehicle::ScheduleController hold(robot, holdStill(robot), "test");
  sim::Run run(*engine, &hold);
  while (run.time() < kSettleSeconds) run.step();

  double carried = 0.0;
  for (const int w : robot.wheels()) carried += run.state().wheels[w].force.z();
  const double weight = robot.totalMass() * kGravityMps2;
  EXPECT_NEAR(carried, weight, kWeightTolerance * weight);
  EXPECT_FALSE(run.nonFinite());
  EXPECT_LT(run.maxJointError().distance, kJointGapToleranceM);
  EXPECT_LT(run.maxJointError().angle, kJointAngleToleranceRad);
  const int middle = robot.find("middle");
  EXPECT_LT(run.state().bodies[middle].linear_velocity.norm(), 1e-3);
}

INSTANTIATE_TEST_SUITE_P(EveryEngine, SimEngineTest, ::testing::ValuesIn(everyEngine()),
                         [](const auto& info) { return label(info.param); });

}  // namespace
}  // namespace wtc::testing
