// Each event's scene for both shipped vehicles is a normal scene: wtc-sim's
// reader takes it; the vehicle stands where the event puts it (on a slope,
// across it, before a face); a scene runs in the engines and shows the
// event (a coast-down slows the robot as rolling resistance says).
#include "wtc/mobility/event_scenes.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>

#include "scratch_path.hpp"
#include "wtc/base/error.hpp"
#include "wtc/mobility/mobility_bounds.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/scene_file.hpp"
#include "wtc/sim/scene_run.hpp"
#include "wtc/vehicle/vehicle_file.hpp"

namespace wtc::mobility {
namespace event_scenes_test {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// The turn lags the ramp by the body's yaw inertia (measured: 0.33 % below Omega (T - 0.5 s) over 6 s in
// Bullet and ODE, docs/mobility-bounds.md); relative.
constexpr double kTurnTolerance = 0.01;

EventVehicle shipped(const std::string& file) {
  EventVehicle v;
  v.file = fs::path(WTC_SOURCE_DIR) / "vehicles" / file;
  v.description = vehicle::loadVehicle(v.file);
  v.statics = describeStatics(v.description);
  return v;
}

sim::Scene load(const std::string& text) {
  const fs::path path = wtc::test::scratchPath("wtc_event_scene_test.yaml");
  std::ofstream(path) << text;
  return sim::loadScene(path);
}

TEST(EventScenesTest, EveryEventsSceneIsANormalSceneForEveryShippedVehicle) {
  const MobilitySettings settings;
  for (const char* file : {"six_wheel_robot.yaml", "towed_system.yaml", "rocker_bogie_rover.yaml"}) {
    const EventVehicle v = shipped(file);
    for (const std::string& event : eventNames()) {
      if (event == "turn" && !isSkidSteered(v.statics)) {
        EXPECT_THROW(eventScene(v, event, 0.0, settings), InvalidInputError) << file;
        continue;
      }
      const double value = event == "drawbar" ? 0.2 : (event == "step" || event == "gap" ? 0.1 : 10.0);
      const std::string text = eventScene(v, event, value, settings);
      sim::Scene scene;
      ASSERT_NO_THROW(scene = load(text)) << file << " " << event << "\n" << text;
      EXPECT_EQ(scene.name, sceneName(v, event, value)) << text;
      EXPECT_EQ(scene.vehicle.name, v.description.name);
      if (event == "drawbar") {
        ASSERT_TRUE(scene.drawbar.has_value()) << text;
        EXPECT_LE(scene.start_velocity_V.x(), settings.drawbar.speed_mps);
      }
      if (event == "coast") {
        EXPECT_EQ(scene.start_velocity_V.x(), settings.coast.speed_mps);
      }
      if (event == "braking") {
        EXPECT_EQ(scene.start_velocity_V.x(), settings.braking.speed_mps);
      }
    }
  }
}

// The drawbar imposes a slip i by the wheels' rate, omega = V / (r_f (1 - i)): a rate beyond a drive's
// max_speed would be clamped and impose less (the rover's 3 rad/s wheels gave DP/W 0 at every slip at
// 0.3 m/s). Every slip's rate stays within every driven wheel's limit, the anchor and the vehicle at one V.
TEST(EventScenesTest, TheDrawbarsWheelRatesStayWithinTheDrivesLimits) {
  const MobilitySettings settings;
  for (const char* file : {"six_wheel_robot.yaml", "towed_system.yaml", "rocker_bogie_rover.yaml"}) {
    const EventVehicle v = shipped(file);
    for (const double i : settings.drawbar.slips) {
      const sim::Scene scene = load(eventScene(v, "drawbar", i, settings));
      ASSERT_TRUE(scene.drawbar.has_value());
      const double speed = scene.start_velocity_V.x();
      EXPECT_EQ(scene.drawbar->speed_mps, speed) << file << " i = " << i;
      EXPECT_GT(speed, 0.0);
      for (const WheelInfo& w : v.statics.wheels) {
        if (!w.driven) continue;
        EXPECT_LE(speed / (w.radius_m * (1.0 - i)), w.max_rate_radps * (1.0 + 1e-9))
            << file << " " << w.name << " at i = " << i;
      }
    }
  }
}

// Case: on a slope (up it, across it) every wheel's lowest point lies on the slope's surface at the start.
TEST(EventScenesTest, OnASlopeEveryWheelStandsOnTheSurface) {
  const MobilitySettings settings;
  const EventVehicle v = shipped("six_wheel_robot.yaml");
  for (const char* event : {"grade", "side_slope"}) {
    const double theta = 20.0 * std::numbers::pi / 180.0;
    const sim::Scene scene = load(eventScene(v, event, 20.0, settings));
    const Eigen::Vector3d normal(-std::sin(theta), 0.0, std::cos(theta));  // the incline rises along +x from x = 0
    for (const WheelInfo& w : v.statics.wheels) {
      const Eigen::Vector3d centre = scene.placement * w.position;
      EXPECT_NEAR(normal.dot(centre), w.radius_m, 1e-9) << event << " " << w.name;  // r above the plane through 0
      EXPECT_GT(centre.x(), 0.0) << event << " " << w.name;                         // on the slope, past its foot
    }
  }
}

TEST(EventScenesTest, TheRobotClimbsWithItsOwnControllerAndTheTowedSystemDrivesPlainly) {
  const MobilitySettings settings;
  EXPECT_TRUE(hasClimbingController(shipped("six_wheel_robot.yaml").description));
  EXPECT_FALSE(hasClimbingController(shipped("towed_system.yaml").description));
  EXPECT_THAT(eventScene(shipped("six_wheel_robot.yaml"), "step", 0.3, settings), HasSubstr("type: climb"));
  EXPECT_THAT(eventScene(shipped("towed_system.yaml"), "step", 0.01, settings), HasSubstr("type: schedule"));
  MobilitySettings plain;
  plain.step.vehicle_controller = false;
  EXPECT_THAT(eventScene(shipped("six_wheel_robot.yaml"), "step", 0.3, plain), HasSubstr("type: schedule"));
  EXPECT_THROW(eventScene(shipped("six_wheel_robot.yaml"), "swim", 0.0, settings), InvalidInputError);
}

// Case: the coast-down scene, run in Bullet, slows the robot at the bound's rate.
TEST(EventScenesTest, TheCoastDownSceneRunsAndSlowsTheRobotAsTheBoundSays) {
  MobilitySettings settings;
  settings.coast.duration_s = 1.5;
  const EventVehicle v = shipped("six_wheel_robot.yaml");
  sim::Scene scene = load(eventScene(v, "coast", 0.0, settings));
  const auto engine = sim::makeEngine(scene.engine, *scene.terrain, scene.vehicle, scene.placement);
  const sim::RunSummary summary = sim::runScene(scene, *engine);
  EXPECT_TRUE(summary.success);
  // v(T) = V - a T: 1.5 s at 0.1574 m/s^2 after the tread's first loading.
  const double a = computeBounds(v.statics, settings).coast_mps2.value;
  EXPECT_NEAR(summary.fields.at("distance_m"), settings.coast.speed_mps * 1.5 - 0.5 * a * 1.5 * 1.5, 0.01);
}

// Case: turning in place at wheel rates +-3 rad/s (ramped over 1 s), the robot yaws at the rate the slip
// law's balance gives (docs/mobility-bounds.md, 3.7: 0.870 rad/s), Omega (T - 0.5 s) over the run, in every
// engine and WTC contact mode it serves.
TEST(EventScenesTest, TheRobotTurnsInPlaceAtTheSlipLawsYawRateInEveryEngine) {
  MobilitySettings settings;
  settings.turn.duration_s = 3.0;
  const EventVehicle v = shipped("six_wheel_robot.yaml");
  const double rate = computeBounds(v.statics, settings).turn_radps->value;
  EXPECT_NEAR(rate, 0.870, 0.0005);
  const double expected = rate * (settings.turn.duration_s - 0.5) * 180.0 / std::numbers::pi;
  const sim::Scene base = load(eventScene(v, "turn", 0.0, settings));
  for (const std::string_view engine : sim::engineNames()) {
    for (const char* mode : {"force", "constraint", "implicit"}) {
      sim::Scene scene = base;
      scene.engine.engine = std::string(engine);
      sim::parseMode(mode, scene.engine, "test");
      if (!sim::servesWheels(scene.engine)) continue;  // MuJoCo: no implicit mode
      // MuJoCo's soft cone lifts a sliding contact: in this skid turn its
      // constraint mode rides on undeflected tyres and turns short
      // (docs/mujoco-plugin.md, "Sliding contacts lift"), an open deviation.
      if (engine == "mujoco" && scene.engine.mode == ContactMode::kConstraint) continue;
      const auto e = sim::makeEngine(scene.engine, *scene.terrain, scene.vehicle, scene.placement);
      const double turned = std::abs(sim::runScene(scene, *e).fields.at("yaw_change_deg"));
      RecordProperty(std::string(engine) + "_" + mode + "_yaw_deg", std::to_string(turned));
      EXPECT_NEAR(turned, expected, kTurnTolerance * expected) << engine << " " << mode;
    }
  }
}

}  // namespace event_scenes_test
}  // namespace wtc::mobility
