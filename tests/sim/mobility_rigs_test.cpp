// The rigs of the mobility events (docs/mobility-bounds.md, "Test rigs"),
// against what mechanics says of them, in every engine and contact mode:
// a vehicle that starts moving with its wheels rolling (coast-down: the
// rolling resistance's deceleration), a drawbar whose anchor imposes the
// speed while the drives impose the wheels' rate (DP/W = mu(s) for an
// all-wheel drive), the rig's work counted as a source of energy, and a
// drive that switches off during a run.
#include <unistd.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "sim_test_support.hpp"
#include "wtc/base/constants.hpp"
#include "wtc/base/error.hpp"
#include "wtc/sim/drawbar.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/run.hpp"
#include "wtc/sim/scene_file.hpp"
#include "wtc/sim/scene_run.hpp"
#include "wtc/sim/start_velocity.hpp"
#include "wtc/terrain/material.hpp"
#include "wtc/tyre/traction_law.hpp"
#include "wtc/vehicle/controllers/schedule_controller.hpp"

namespace wtc::testing {
namespace {

constexpr double kVelocityTolerance = 1e-9;   // (m/s, rad/s) what was set is what the engine holds
constexpr double kCoastSpeedMps = 1.0;        // the coast-down start
constexpr double kCoastFitFromSeconds = 0.3;  // past the tread's first loading (relaxation, ~16 mm)
constexpr double kCoastFitToSeconds = 1.5;
constexpr double kDecelerationTolerance = 0.01;  // relative (measured: 4e-4 in Bullet and ODE, force mode)
constexpr double kRigSpeedMps = 0.3;             // the anchor's and the vehicle's speed
constexpr double kRigSlip = 0.25;                // s = i / (1 - i), driving slip i = 20 %
constexpr double kRigStiffnessNpm = 2.0e4;       // about 4.5 cm of extension at the robot's 0.73 W
constexpr double kRigDampingNspm = 3.0e3;        // near critical for the robot's 126 kg (2 sqrt(k m) = 3.2e3)
// The speed settles on the slip law's slope, with a time constant of about 0.35 s (measured: the pull is
// within 0.1 % of its end value from 2.5 s on, in Bullet and ODE, force mode).
constexpr double kRigSettleSeconds = 2.5;
constexpr double kRigMeanSeconds = 0.5;
constexpr double kPullTolerance = 0.005;  // relative to mu(s) W
constexpr double kPushN = 200.0;          // a constant push (a pull of -200 N) on a free vehicle
constexpr double kPushSeconds = 1.0;

class MobilityRigsTest : public ::testing::TestWithParam<sim::EngineSettings> {};

double totalMass(const vehicle::VehicleDescription& v) {
  double m = 0.0;
  for (const vehicle::Body& b : v.bodies) m += b.mass;
  return m;
}

// The wheels' moments about their axles over r_f^2 (kg): what their spin adds to the mass that a rolling
// vehicle's forces accelerate.
double wheelInertiaMass(const vehicle::VehicleDescription& v) {
  double m = 0.0;
  for (const int w : v.wheels()) {
    const vehicle::Body& b = v.bodies[w];
    const double r = b.wheel->geometry.free_radius;
    m += b.wheel->axle.cwiseAbs().dot(b.inertia) / (r * r);  // the axle is a body axis in the shipped vehicles
  }
  return m;
}

std::vector<vehicle::DriveSchedule> sectionsHeld(const vehicle::VehicleDescription& v) {
  vehicle::DriveSchedule joints{.drives = {}, .mode = vehicle::DriveMode::kPosition, .points = {{0.0, 0.0}}};
  for (const int b : v.actuated()) {
    if (!v.bodies[b].wheel) joints.drives.push_back(v.bodies[b].name);
  }
  return {joints};
}

// Case: wherever the vehicle stands (turned, pitched), each wheel's contact point at -r_f n moves only
// along its axle: the wheels roll without slip at the start.
TEST(StartVelocityTest, EveryWheelRollsWithoutSlipWhereverTheVehicleStands) {
  const vehicle::VehicleDescription robot = shippedVehicle("six_wheel_robot.yaml");
  const Eigen::Isometry3d placement = Eigen::Translation3d(1.0, 2.0, 0.3) *
                                      Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()) *
                                      Eigen::AngleAxisd(-0.2, Eigen::Vector3d::UnitY());
  const Eigen::Vector3d v_V(1.5, 0.2, 0.0);
  const std::vector<sim::BodyVelocity> velocities = sim::startVelocities(robot, placement, v_V);
  ASSERT_EQ(velocities.size(), robot.bodies.size());
  const Eigen::Vector3d n_W = placement.linear().col(2);
  for (std::size_t i = 0; i < robot.bodies.size(); ++i) {
    const vehicle::Body& b = robot.bodies[i];
    EXPECT_LT((velocities[i].linear - placement.linear() * v_V).norm(), kVelocityTolerance) << b.name;
    if (!b.wheel) {
      EXPECT_EQ(velocities[i].angular.norm(), 0.0) << b.name;
      continue;
    }
    const Eigen::Vector3d a_W = placement.linear() * b.pose.linear() * b.wheel->axle;
    const Eigen::Vector3d contact =
        velocities[i].linear + velocities[i].angular.cross(-b.wheel->geometry.free_radius * n_W);
    EXPECT_LT((contact - contact.dot(a_W) * a_W).norm(), kVelocityTolerance) << b.name;
    EXPECT_GT(velocities[i].angular.norm(), 1.0) << b.name;  // it does spin: 1.5 m/s on 0.19 m
  }
}

TEST(StartVelocityTest, ANonFiniteOrDivergedVelocityIsRefusedWithTheValue) {
  const vehicle::VehicleDescription robot = shippedVehicle("six_wheel_robot.yaml");
  const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
  EXPECT_THROW(sim::startVelocities(robot, I, Eigen::Vector3d(NAN, 0, 0)), InvalidInputError);
  try {
    sim::startVelocities(robot, I, Eigen::Vector3d(2e3, 0, 0));
    FAIL() << "2 km/s accepted";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("(2000, 0, 0) m/s must be finite and at most 1000 m/s"), std::string::npos)
        << e.what();
  }
}

// Case: the engine holds the velocities it was given, the towed system's ball casters (Bullet's
// spherical joints) and the swivelled nose wheel included.
TEST_P(MobilityRigsTest, TheEngineStartsEveryBodyAtTheVelocityGiven) {
  const Terrain ground = flatGround();
  for (const char* file : {"six_wheel_robot.yaml", "towed_system.yaml"}) {
    const vehicle::VehicleDescription v = shippedVehicle(file);
    const Eigen::Isometry3d placement =
        Eigen::Translation3d(0.0, 0.0, 0.01) * Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ());
    const auto engine = sim::makeEngine(GetParam(), ground, v, placement);
    const std::vector<sim::BodyVelocity> given = sim::startVelocities(v, placement, Eigen::Vector3d(2.0, 0, 0));
    engine->setVelocities(given);
    for (std::size_t i = 0; i < v.bodies.size(); ++i) {
      const vehicle::BodyKinematics k = engine->body(static_cast<int>(i));
      EXPECT_LT((k.linear_velocity - given[i].linear).norm(), kVelocityTolerance) << file << ": " << v.bodies[i].name;
      EXPECT_LT((k.angular_velocity - given[i].angular).norm(), kVelocityTolerance) << file << ": " << v.bodies[i].name;
    }
    EXPECT_THROW(engine->setVelocities(std::span(given).first(1)), InvalidInputError) << file;
  }
}

// Case: started at 1 m/s with its wheel drives off, the robot decelerates at
// a = f_r (r_0 / r_f) g m / (m + sum I / r_f^2) (docs/mobility-bounds.md, 3.5).
TEST_P(MobilityRigsTest, ARobotStartedAt1MpsCoastsDownAsRollingResistanceSays) {
  const Terrain ground = flatGround();
  const vehicle::VehicleDescription robot = shippedVehicle("six_wheel_robot.yaml");
  const auto engine = sim::makeEngine(GetParam(), ground, robot, Eigen::Isometry3d::Identity());
  engine->setVelocities(
      sim::startVelocities(robot, Eigen::Isometry3d::Identity(), Eigen::Vector3d(kCoastSpeedMps, 0, 0)));
  vehicle::ScheduleController hold(robot, sectionsHeld(robot), "test");
  sim::Run run(*engine, &hold);
  // A least-squares line through the chassis's speed.
  double n = 0, st = 0, sv = 0, stt = 0, stv = 0;
  while (run.time() < kCoastFitToSeconds) {
    run.step();
    if (run.time() < kCoastFitFromSeconds) continue;
    const double t = run.time(), v = run.state().bodies.front().linear_velocity.x();
    n += 1;
    st += t;
    sv += v;
    stt += t * t;
    stv += t * v;
  }
  const double measured = -(n * stv - st * sv) / (n * stt - st * st);
  const Material asphalt;
  const double m = totalMass(robot);
  const double ratio = robot.bodies[robot.wheels().front()].wheel->tyre.rolling_radius_ratio;
  const double expected = asphalt.rolling_resistance * ratio * kGravityMps2 * m / (m + wheelInertiaMass(robot));
  RecordProperty("deceleration_mps2", std::to_string(measured));
  EXPECT_NEAR(measured, expected, kDecelerationTolerance * expected);
  EXPECT_NEAR(expected, 0.1574, 5e-5);  // docs/mobility-bounds.md's number, from the same description
}

// Case: a drawbar anchor at 0.3 m/s and every wheel at w = V (1 + s) / r_f impose the slip s; an
// all-wheel drive then pulls mu(s) W (docs/mobility-bounds.md, 3.4), whatever its loads.
TEST_P(MobilityRigsTest, ADrawbarAtAnImposedSlipPullsMuOfThatSlipTimesTheWeight) {
  const Terrain ground = flatGround();
  const vehicle::VehicleDescription robot = shippedVehicle("six_wheel_robot.yaml");
  const auto engine = sim::makeEngine(GetParam(), ground, robot, Eigen::Isometry3d::Identity());
  engine->setVelocities(
      sim::startVelocities(robot, Eigen::Isometry3d::Identity(), Eigen::Vector3d(kRigSpeedMps, 0, 0)));
  std::vector<vehicle::DriveSchedule> schedules = sectionsHeld(robot);
  vehicle::DriveSchedule wheels{.drives = {}, .mode = vehicle::DriveMode::kVelocity, .points = {}};
  const double r = robot.bodies[robot.wheels().front()].wheel->geometry.free_radius;
  wheels.points = {{0.0, kRigSpeedMps * (1.0 + kRigSlip) / r}};
  for (const int w : robot.wheels()) wheels.drives.push_back(robot.bodies[w].name);
  schedules.push_back(wheels);
  vehicle::ScheduleController drive(robot, schedules, "test");
  const sim::Drawbar rig{.body = robot.find("middle"),
                         .point_V = Eigen::Vector3d(-0.3, 0.0, 0.19),
                         .force_N = std::nullopt,
                         .speed_mps = kRigSpeedMps,
                         .stiffness_Npm = kRigStiffnessNpm,
                         .damping_Nspm = kRigDampingNspm};
  sim::Run run(*engine, &drive, {}, rig);
  while (run.time() < kRigSettleSeconds) run.step();
  double pull = 0.0;
  int steps = 0;
  while (run.time() < kRigSettleSeconds + kRigMeanSeconds) {
    run.step();
    pull += run.drawbar()->pull_N;
    ++steps;
  }
  const double weight = totalMass(robot) * kGravityMps2;
  const double expected = tractionCoefficient(Material{}, kRigSlip);
  RecordProperty("dp_per_weight", std::to_string(pull / steps / weight));
  EXPECT_NEAR(pull / steps / weight, expected, kPullTolerance * expected);
  EXPECT_NEAR(run.state().bodies.front().linear_velocity.x(), kRigSpeedMps, 1e-3);
  EXPECT_LT(run.energyBalance().maxGrowth(), 1e-3 * weight);  // the drives' and the rig's work explain it
}

// Case: a constant push on a free robot speeds it up; the rig's work is a source in the energy balance,
// so nothing grows unexplained (without it the balance would count the push's work as made from nothing).
TEST_P(MobilityRigsTest, ADrawbarsWorkIsASourceInTheEnergyBalance) {
  const Terrain ground = flatGround();
  const vehicle::VehicleDescription robot = shippedVehicle("six_wheel_robot.yaml");
  const auto engine = sim::makeEngine(GetParam(), ground, robot, Eigen::Isometry3d::Identity());
  vehicle::ScheduleController hold(robot, sectionsHeld(robot), "test");
  const sim::Drawbar push{.body = 0, .point_V = Eigen::Vector3d(-0.3, 0.0, 0.19), .force_N = -kPushN};
  sim::Run run(*engine, &hold, {}, push);
  while (run.time() < kPushSeconds) run.step();
  EXPECT_GT(run.energyBalance().rigWork(), 10.0);  // J: 200 N over about 0.5 m
  EXPECT_LT(run.energyBalance().maxGrowth(), 0.1 * run.energyBalance().rigWork());
  EXPECT_GT(run.state().bodies.front().linear_velocity.x(), 0.5);
}

// Case: a schedule with off_after drives its wheels, then lets them go: the command is the schedule's
// before, off from then on.
TEST(ScheduleOffAfterTest, TheDrivesFollowTheScheduleThenAreOff) {
  const vehicle::VehicleDescription robot = shippedVehicle("six_wheel_robot.yaml");
  vehicle::DriveSchedule wheels{.drives = {"front_left_wheel"},
                                .mode = vehicle::DriveMode::kVelocity,
                                .points = {{0.0, 0.0}, {1.0, 4.0}},
                                .off_after = 2.0};
  vehicle::ScheduleController controller(robot, {wheels}, "test");
  vehicle::VehicleState state;
  std::vector<vehicle::DriveCommand> commands(robot.bodies.size());
  const int b = robot.find("front_left_wheel");
  state.time = 1.5;
  controller.update(state, commands);
  EXPECT_EQ(commands[b].mode, vehicle::DriveMode::kVelocity);
  EXPECT_EQ(commands[b].value, 4.0);
  state.time = 2.0;
  controller.update(state, commands);
  EXPECT_EQ(commands[b].mode, vehicle::DriveMode::kOff);
  wheels.off_after = -1.0;
  EXPECT_THROW(vehicle::ScheduleController(robot, {wheels}, "test"), InvalidInputError);
  wheels.off_after = 1.0;
  wheels.mode = vehicle::DriveMode::kOff;
  EXPECT_THROW(vehicle::ScheduleController(robot, {wheels}, "test"), InvalidInputError);
}

// Case: a robot driving backward 1 m passes min_distance but not min_advance, which counts going back as
// negative (a vehicle sliding down a grade must not pass a climb), nor max_final_speed (still moving); a
// robot standing passes max_final_speed (a parked vehicle that settled and holds).
TEST(MinAdvanceTest, GoingBackCountsNegativeAndAVehicleStillMovingFailsMaxFinalSpeed) {
  const std::filesystem::path path = std::filesystem::path(WTC_SOURCE_DIR) / "scenes" /
                                          ("wtc_min_advance_test_" + std::to_string(::getpid()) + ".yaml.tmp");
  std::ofstream(path) << "name: back\nduration: 3\nterrain: ../terrains/flat.yaml\n"
                         "vehicle: ../vehicles/six_wheel_robot.yaml\n"
                         "controller: {type: schedule, schedules: [{drives: [front_left_wheel, front_right_wheel, "
                         "middle_left_wheel, middle_right_wheel, rear_left_wheel, rear_right_wheel], mode: velocity, "
                         "points: [[0, 0], [0.5, -3]]}]}\n"
                         "success: {min_distance: 0.5, min_advance: 0.5, max_final_speed: 0.01}\n";
  const sim::Scene scene = sim::loadScene(path);
  std::filesystem::remove(path);
  ASSERT_EQ(scene.success.min_advance, 0.5);
  const auto engine = sim::makeEngine(scene.engine, *scene.terrain, scene.vehicle, scene.placement);
  const sim::RunSummary summary = sim::runScene(scene, *engine);
  EXPECT_GT(summary.fields.at("distance_m"), 0.5);
  EXPECT_LT(summary.fields.at("advance_m"), -0.5);
  ASSERT_EQ(summary.failed_criteria.size(), 2u);
  EXPECT_EQ(summary.failed_criteria[0].criterion, "max_final_speed");  // still driving at 0.57 m/s
  EXPECT_EQ(summary.failed_criteria[1].criterion, "min_advance");
  EXPECT_FALSE(summary.success);

  // Case: standing, it settles and holds: max_final_speed passes.
  std::ofstream(path) << "name: stand\nduration: 1\nterrain: ../terrains/flat.yaml\n"
                         "vehicle: ../vehicles/six_wheel_robot.yaml\ncontroller: {type: none}\n"
                         "success: {max_final_speed: 0.01}\n";
  const sim::Scene standing = sim::loadScene(path);
  std::filesystem::remove(path);
  const auto e2 = sim::makeEngine(standing.engine, *standing.terrain, standing.vehicle, standing.placement);
  EXPECT_TRUE(sim::runScene(standing, *e2).success);
}

INSTANTIATE_TEST_SUITE_P(EveryEngine, MobilityRigsTest, ::testing::ValuesIn(everyEngine()),
                         [](const auto& info) { return label(info.param); });

}  // namespace
}  // namespace wtc::testing
