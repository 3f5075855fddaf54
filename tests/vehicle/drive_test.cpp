// Drives: the rate given to the engine's motor and the saturation count.
#include "wtc/vehicle/drive.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "wtc/base/error.hpp"

namespace wtc::vehicle {
namespace {

constexpr double kTolerance = 1e-12;
const ActuatorLimits kFold{.max_effort = 1500.0, .max_speed = 1.0, .position_gain = 5.0};
const JointLimits kTravel{.lower = -1.5, .upper = 1.5};

TEST(DriveTest, VelocityCommandWithinLimitsIsHeldAsGiven) {
  const MotorTarget t = motorTarget(kFold, kTravel, {DriveMode::kVelocity, 0.4}, 0.0, true);
  EXPECT_TRUE(t.active);
  EXPECT_NEAR(t.rate, 0.4, kTolerance);
  EXPECT_EQ(t.max_effort, 1500.0);
  EXPECT_FALSE(t.clamped);
}

TEST(DriveTest, VelocityCommandBeyondMaxSpeedSaturates) {
  const MotorTarget t = motorTarget(kFold, kTravel, {DriveMode::kVelocity, -3.0}, 0.0, true);
  EXPECT_NEAR(t.rate, -1.0, kTolerance);
  EXPECT_TRUE(t.clamped);
}

TEST(DriveTest, WithoutTheLimitsEffectTheDriveIsIdeal) {
  const MotorTarget t = motorTarget(kFold, kTravel, {DriveMode::kVelocity, -3.0}, 0.0, false);
  EXPECT_NEAR(t.rate, -3.0, kTolerance);
  EXPECT_TRUE(std::isinf(t.max_effort));
  EXPECT_FALSE(t.clamped);
}

TEST(DriveTest, PositionCommandGivesProportionalRateClampedToMaxSpeed) {
  // Case: close to the goal, rate = k (q* - q).
  MotorTarget t = motorTarget(kFold, kTravel, {DriveMode::kPosition, 0.5}, 0.45, true);
  EXPECT_NEAR(t.rate, 5.0 * 0.05, kTolerance);
  EXPECT_FALSE(t.clamped);
  // Case: far from it, the drive moves at its rated speed (not saturation).
  t = motorTarget(kFold, kTravel, {DriveMode::kPosition, 1.2}, 0.0, true);
  EXPECT_NEAR(t.rate, 1.0, kTolerance);
  EXPECT_FALSE(t.clamped);
}

TEST(DriveTest, PositionBeyondTheTravelIsClampedAndCounted) {
  const MotorTarget t = motorTarget(kFold, kTravel, {DriveMode::kPosition, 2.0}, 1.45, true);
  EXPECT_NEAR(t.rate, 5.0 * (1.5 - kDriveStopMargin - 1.45), kTolerance);  // held just inside the stop
  EXPECT_TRUE(t.clamped);
  DriveReport report;
  record(report, t, 10.0);
  EXPECT_EQ(report.saturated_steps, 1u);
}

// Commanded to the stop itself, the drive holds just inside it and leaves
// the stop alone: no saturation (the command asked for nothing the drive
// lacks), and no second row on the stop's axis while the load is the drive's.
TEST(DriveTest, PositionAtTheStopIsHeldJustInsideItWithoutSaturation) {
  const MotorTarget at_upper = motorTarget(kFold, kTravel, {DriveMode::kPosition, 1.5}, 1.5, true);
  EXPECT_NEAR(at_upper.rate, -5.0 * kDriveStopMargin, kTolerance);
  EXPECT_FALSE(at_upper.clamped);
  const MotorTarget at_lower = motorTarget(kFold, kTravel, {DriveMode::kPosition, -1.5}, -1.5, true);
  EXPECT_NEAR(at_lower.rate, 5.0 * kDriveStopMargin, kTolerance);
  // A travel narrower than the two margins keeps its own bounds.
  const JointLimits narrow{.lower = 0.0, .upper = kDriveStopMargin};
  EXPECT_NEAR(motorTarget(kFold, narrow, {DriveMode::kPosition, 1.0}, 0.0, true).rate, 5.0 * kDriveStopMargin,
              kTolerance);
}

TEST(DriveTest, EffortAtTheCapCountsAsSaturated) {
  DriveReport report;
  const MotorTarget t = motorTarget(kFold, kTravel, {DriveMode::kVelocity, 0.5}, 0.0, true);
  record(report, t, 1000.0);
  record(report, t, -1500.0);
  record(report, t, 1499.0);  // within kFullEffortFraction of the cap
  record(report, {}, 0.0);    // motor off: not a drive step
  EXPECT_EQ(report.steps, 3u);
  EXPECT_EQ(report.saturated_steps, 2u);
  EXPECT_EQ(report.peak_effort, 1500.0);
}

TEST(DriveTest, OffCommandGivesNoMotor) { EXPECT_FALSE(motorTarget(kFold, kTravel, {}, 0.0, true).active); }

// A wheel's drive in closed form, stepped as a wheel turns (Newton about
// its axle, I dw = (T + tau) h): it lands on the target rate in one step
// whatever the load, when its cap allows; otherwise it gives its cap and
// the wheel gains what the cap and the load give.
TEST(DriveTest, AWheelDriveInClosedFormReachesItsRateInOneStepWithinItsCap) {
  constexpr double kInertia = 0.0668, kStep = 4e-4, kLoad = -40.0;  // kg m^2, s, N m
  const MotorTarget target{.active = true, .rate = 3.0, .max_effort = 100.0};
  const auto stepped = [&](double rate, double torque) { return rate + kStep * (torque + kLoad) / kInertia; };
  const double near = 2.9;  // needs 56.7 N m: within the cap
  EXPECT_NEAR(stepped(near, wheelDriveTorque(target, near, kLoad, kInertia, kStep)), 3.0, kTolerance);
  const double far = 1.0;  // needs 374 N m
  EXPECT_EQ(wheelDriveTorque(target, far, kLoad, kInertia, kStep), 100.0);
  EXPECT_EQ(wheelDriveTorque({.active = true, .rate = -3.0, .max_effort = 100.0}, far, kLoad, kInertia, kStep), -100.0);
  EXPECT_EQ(wheelDriveTorque(MotorTarget{}, near, kLoad, kInertia, kStep), 0.0);
}

TEST(DriveTest, NonFiniteCommandIsRefusedByName) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  try {
    motorTarget(kFold, kTravel, {DriveMode::kVelocity, nan}, 0.0, true);
    FAIL() << "no error";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("command nan"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace wtc::vehicle
