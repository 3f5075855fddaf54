// Each event's bound, computed from the vehicle description, against the
// numbers docs/mobility-bounds.md derives by hand and with the groundwork's
// tools/mobility_bounds.py (which this C++ replaces in the report): the
// six-wheel robot and the towed system on asphalt.
#include "wtc/mobility/mobility_bounds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "wtc/base/error.hpp"
#include "wtc/mobility/mobility_settings.hpp"
#include "wtc/mobility/vehicle_statics.hpp"
#include "wtc/tyre/wheel_soil.hpp"
#include "wtc/vehicle/vehicle_file.hpp"

namespace wtc::mobility {
namespace {

// The docs give 4 significant digits (2 decimals in degrees).
constexpr double kDegTolerance = 0.006;
constexpr double kRelTolerance = 6e-4;

VehicleStatics shipped(const std::string& file) {
  return describeStatics(vehicle::loadVehicle(std::string(WTC_SOURCE_DIR) + "/vehicles/" + file));
}

TEST(VehicleStaticsTest, TheRobotsWheelsShareItsWeightAndTheTowedSystemsDriveWheelsCarryASixth) {
  const VehicleStatics robot = shipped("six_wheel_robot.yaml");
  EXPECT_NEAR(robot.mass_kg, 126.2, 1e-9);
  EXPECT_TRUE(robot.allDriven());
  const Loads level = wheelLoads(robot);
  for (const double n : level.normal_N) EXPECT_NEAR(n, robot.weight() / 6.0, 1e-6);

  const VehicleStatics towed = shipped("towed_system.yaml");
  EXPECT_NEAR(towed.mass_kg, 6660.0, 1e-9);
  ASSERT_TRUE(towed.hitch.has_value());
  const Loads t = wheelLoads(towed);
  EXPECT_NEAR(t.driven_N, 12.21e3, 0.01e3);  // docs: 12.21 kN, 18.7 % of W
  for (std::size_t i = 0; i < towed.wheels.size(); ++i) {
    if (towed.wheels[i].driven) {
      EXPECT_NEAR(t.normal_N[i], 6107.0, 1.0) << towed.wheels[i].name;
    }
    if (towed.wheels[i].name == "nose_wheel") {
      EXPECT_NEAR(t.normal_N[i], 11.55e3, 0.01e3);
    }
    if (towed.wheels[i].name.rfind("tug_", 0) == 0 && towed.wheels[i].name.find("caster") != std::string::npos) {
      EXPECT_TRUE(towed.wheels[i].caster) << towed.wheels[i].name;
    }
  }
  double sum = 0.0;
  for (const double n : t.normal_N) sum += n;
  EXPECT_NEAR(sum, towed.weight(), 1e-6 * towed.weight());
}

TEST(MobilityBoundsTest, TheRobotsBoundsAreTheDocsNumbers) {
  const MobilitySettings asphalt;
  const VehicleBounds b = computeBounds(shipped("six_wheel_robot.yaml"), asphalt);
  EXPECT_NEAR(b.grade_deg.value, 38.66, kDegTolerance);
  EXPECT_EQ(b.grade_deg.governs, "traction");
  EXPECT_NEAR(b.parked_deg.value, 38.66, kDegTolerance);
  EXPECT_NEAR(b.side_slide_deg, 38.66, kDegTolerance);
  EXPECT_NEAR(b.side_tip_deg, 55.84, kDegTolerance);
  EXPECT_EQ(b.side_slope_deg.governs, "sliding");
  EXPECT_NEAR(b.coast_mps2.value, 0.1574, 0.1574 * kRelTolerance);
  EXPECT_NEAR(b.braking_m.value, 0.2549, 0.2549 * kRelTolerance);
  EXPECT_NEAR(b.step_m.value, 0.19, 1e-9);  // every axle at its level load: the whole radius
  ASSERT_TRUE(b.step_m.lower.has_value());
  EXPECT_NEAR(*b.step_m.lower, 0.148, 0.0005);  // the middle axle hanging
  EXPECT_NEAR(b.gap_m.value, 0.38, 1e-9);
  EXPECT_NEAR(*b.gap_m.lower, 0.371, 0.0005);
  ASSERT_TRUE(b.turn_radps.has_value());
  EXPECT_NEAR(b.turn_radps->value, 0.870, 0.0005);
  EXPECT_NEAR(b.turn_moment_Nm, 431.0, 0.5);
  // DP/W = mu(s) at 20 % driving slip (s = 0.25): 0.734.
  for (const DrawbarPoint& p : b.drawbar) {
    if (p.slip == 0.2) {
      EXPECT_NEAR(p.dp_per_weight, 0.734, 0.0005);
      EXPECT_NEAR(p.torque_coefficient - p.dp_per_weight, 0.018 * 0.97, 1e-12);
    }
  }
}

TEST(MobilityBoundsTest, TheTowedSystemsBoundsAreTheDocsNumbers) {
  const MobilitySettings asphalt;
  const VehicleBounds b = computeBounds(shipped("towed_system.yaml"), asphalt);
  EXPECT_NEAR(b.grade_deg.value, 6.03, kDegTolerance);
  EXPECT_EQ(b.grade_deg.governs, "traction");
  EXPECT_NEAR(b.parked_deg.value, 6.85, kDegTolerance);
  EXPECT_NEAR(b.side_slide_deg, 15.76, kDegTolerance);
  EXPECT_NEAR(b.side_tip_deg, 44.19, kDegTolerance);
  EXPECT_NEAR(b.coast_mps2.value, 0.1681, 0.1681 * kRelTolerance);
  EXPECT_NEAR(b.braking_m.value, 1.09, 0.005);
  EXPECT_NEAR(b.step_m.value, 0.0127, 0.00005);  // the heavy main axle
  EXPECT_NEAR(b.gap_m.value, 0.20, 0.005);
  EXPECT_FALSE(b.turn_radps.has_value());  // no skid steer
  for (const DrawbarPoint& p : b.drawbar) {
    if (p.slip == 0.2) {
      EXPECT_NEAR(p.dp_per_weight, 0.123, 0.0005);
    }
  }
}

// On soft soil the drawbar bound is the soil's steady state: the test cart's
// four driven wheels each carry a quarter of its weight, so DP/W is one
// wheel's DP at W/4 over W/4 (steadyWheelOnSoil), and sum T/(r W) likewise;
// the events whose bounds come from the slip law are refused on a soil.
TEST(MobilityBoundsTest, OnSoftSoilTheDrawbarBoundIsTheSoilsSteadyState) {
  MobilitySettings sand;
  sand.ground.soil = namedSoil("toyoura_sand");
  sand.events = {"drawbar"};
  const VehicleStatics cart = shipped("soil_test_cart.yaml");
  const VehicleBounds b = computeBounds(cart, sand);
  ASSERT_EQ(b.drawbar.size(), sand.drawbar.slips.size());
  const double quarter = cart.weight() / 4;
  for (const DrawbarPoint& p : b.drawbar) {
    const SoilSteadyState one = steadyWheelOnSoil(*sand.ground.soil, 0.09, 0.11, quarter, p.slip);
    EXPECT_NEAR(p.dp_per_weight, one.forces.drawbar_pull / quarter, 1e-9) << p.slip;
    EXPECT_NEAR(p.torque_coefficient, one.forces.torque / 0.09 / quarter, 1e-9) << p.slip;
  }
  EXPECT_NO_THROW(validate(sand));
  MobilitySettings grade = sand;
  grade.events = {"drawbar", "grade"};
  EXPECT_NO_THROW(validate(grade));
  MobilitySettings parked = sand;
  parked.events = {"drawbar", "parked"};
  EXPECT_THROW(validate(parked), InvalidInputError);
  MobilitySettings implicit = sand;
  implicit.modes = {"force", "constraint", "implicit"};
  EXPECT_NO_THROW(validate(implicit));
  MobilitySettings native = sand;
  native.modes = {"engine_cylinder"};
  EXPECT_THROW(validate(native), InvalidInputError);
}

// On soft soil the grade's bound is where the driven wheels' pull at the
// largest slip the event allows balances the weight down the grade: the
// test cart (four driven wheels, r 0.09 m, drives up to 20 rad/s) at
// 2 rad/s for 6 s must advance 0.3 m, so its rims roll 0.09 x 2 x 5.5 =
// 0.99 m and i_max = 1 - 0.3 / 0.99; on the bound's grade the soil's
// steady state at each wheel's load there pulls exactly W sin theta.
TEST(MobilityBoundsTest, OnSoftSoilTheGradeBoundBalancesTheSoilsPullAgainstTheWeight) {
  MobilitySettings sand;
  sand.ground.soil = namedSoil("toyoura_sand");
  sand.events = {"grade"};
  sand.grade.wheel_rate_radps = 2.0;
  sand.grade.min_progress_m = 0.3;
  sand.grade.duration_s = 6.0;
  const VehicleStatics cart = shipped("soil_test_cart.yaml");
  const double slip = 1.0 - 0.3 / (0.09 * 2.0 * (6.0 - 0.5 * kEventRampS));
  const Bound b = computeBounds(cart, sand).grade_deg;
  const double theta = b.value * std::numbers::pi / 180.0;
  ASSERT_GT(theta, 0.0);
  double pull = 0.0;
  const Loads n = wheelLoads(cart, theta);
  for (std::size_t k = 0; k < cart.wheels.size(); ++k) {
    pull += steadyWheelOnSoil(*sand.ground.soil, 0.09, 0.11, n.normal_N[k], slip).forces.drawbar_pull;
  }
  EXPECT_NEAR(pull, cart.weight() * std::sin(theta), 1e-6 * cart.weight()) << b.detail;
  EXPECT_EQ(b.governs, "the pull of toyoura_sand") << b.detail;
  // A run too short to make the progress even without slip climbs nothing.
  sand.grade.duration_s = 1.5;
  EXPECT_EQ(computeBounds(cart, sand).grade_deg.value, 0.0);
}

TEST(VehicleStaticsTest, AVehicleWithoutWheelsIsRefusedByName) {
  vehicle::VehicleDescription v;
  v.name = "brick";
  vehicle::Body b;
  b.name = "box";
  b.mass = 1.0;
  v.bodies.push_back(b);
  try {
    describeStatics(v);
    FAIL();
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("vehicle 'brick' has no wheels"), std::string::npos);
  }
}

}  // namespace
}  // namespace wtc::mobility
