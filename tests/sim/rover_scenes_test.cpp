// The rocker-bogie rover from URDF (vehicles/rocker_bogie_rover.yaml): its
// three scenes in both engines and every mode (issue 37, item 4), with
// its differential held (and the sample DEM's scene): the rockers turn by equal and opposite angles
// relative to the chassis (left = -bar, right = +bar, URDF <mimic>), so
// the chassis pitches by their mean. Short runs (seconds each); the step
// climb's measurement is tools/rover_step_climb.sh (docs/rocker-bogie-rover.md).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "sim_test_support.hpp"
#include "wtc/base/error.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/run.hpp"
#include "wtc/sim/run_observer.hpp"
#include "wtc/sim/scene_file.hpp"
#include "wtc/sim/scene_run.hpp"
#include "wtc/vehicle/urdf_file.hpp"

namespace wtc::testing {
namespace rover_scenes_test {

namespace fs = std::filesystem;
const fs::path kRoot = fs::path(WTC_SOURCE_DIR);
// The mimic's position error, held by feedback at ERP 0.2 a step, as the
// test prints it: 1e-5 rad in Bullet, 1e-8 in ODE's dWorldStep, 5e-4 in its
// quickstep over 6 s of rough ground. 5 mrad is ten times the largest, a
// third of the 14 mrad the bar turns there.
constexpr double kMimicToleranceRad = 5e-3;

// The largest |q_left + q_bar| and |q_right - q_bar| over a run, and the
// largest |q_bar| (that the differential moved at all).
class DifferentialWatch final : public sim::RunObserver {
 public:
  explicit DifferentialWatch(const vehicle::VehicleDescription& v)
      : bar_(v.find("differential_bar")), left_(v.find("left_rocker")), right_(v.find("right_rocker")) {}
  void observe(const sim::Run& run) override {
    const auto& q = run.state().joint_position;
    error_ = std::max({error_, std::abs(q[left_] + q[bar_]), std::abs(q[right_] - q[bar_])});
    travel_ = std::max(travel_, std::abs(q[bar_]));
  }
  double error() const { return error_; }
  double travel() const { return travel_; }

 private:
  int bar_, left_, right_;
  double error_ = 0.0, travel_ = 0.0;
};

struct Outcome {
  sim::RunSummary summary;
  double mimic_error = 0.0;
  double bar_travel = 0.0;
};

// Implicit mode at kImplicitModeStep unless `scene_step`.
Outcome run(const std::string& scene, const std::string& engine, const std::string& mode,
            std::vector<sim::Override> overrides, bool scene_step = false) {
  overrides.push_back({"engine", engine});
  overrides.push_back({"mode", mode});
  if (!scene_step) overrides = atImplicitModeStep(std::move(overrides));
  const sim::Scene s = sim::loadScene(kRoot / "scenes" / (scene + ".yaml"), overrides);
  const auto e = sim::makeEngine(s.engine, *s.terrain, s.vehicle, s.placement);
  DifferentialWatch watch(s.vehicle);
  Outcome out;
  sim::RunOptions options;
  options.observer = &watch;
  out.summary = sim::runScene(s, *e, options);
  out.mimic_error = watch.error();
  out.bar_travel = watch.travel();
  return out;
}

// Every engine (not ODE's quickstep variant) in every mode it serves.
const std::vector<std::pair<std::string, std::string>> kEngines = everyEngineByName(Variants::kLeftOut);

TEST(RoverScenesTest, DrivesStraightOnFlatGroundInBothEnginesAndModes) {
  for (const auto& [engine, mode] : kEngines) {
    const std::string label = engine + ", " + mode;
    const Outcome o = run("rover_flat", engine, mode, {{"duration", "3"}});
    // 2 rad/s on 0.1 m wheels from 1 s: about 0.2 m/s for 2 s, 0.1 m in the ramp.
    EXPECT_GT(o.summary.fields.at("distance_m"), 0.45) << label;
    EXPECT_LT(o.summary.fields.at("distance_m"), 0.55) << label;
    EXPECT_LT(o.summary.fields.at("max_tilt_deg"), 1.0) << label;
    EXPECT_LT(o.mimic_error, kMimicToleranceRad) << label;
    EXPECT_FALSE(o.summary.diverged) << label;
  }
}

TEST(RoverScenesTest, CrossesRoughGroundWithItsDifferentialHeldInBothEnginesAndModes) {
  for (const auto& [engine, mode] : everyEngineByName()) {
    if (engine == "ode_quick" && mode == "constraint") continue;
    // MuJoCo in force mode alone: its collision tests every stored prism of
    // the rough ground against every body each step (docs/mujoco-plugin.md),
    // 30 s of a run here; its constraint mode's mimic is the same equality.
    if (engine == "mujoco" && mode != "force") continue;
    const std::string label = engine + ", " + mode;
    // At the scene's step in every mode: the mimic is held by feedback
    // once a step, so its error grows with the step, in every mode
    // (docs/rocker-bogie-rover.md).
    const Outcome o = run("rover_rough", engine, mode, {{"duration", "6"}}, /*scene_step=*/true);
    EXPECT_GT(o.summary.fields.at("distance_m"), 0.6) << label;
    EXPECT_LT(o.summary.fields.at("max_tilt_deg"), 30.0) << label;
    EXPECT_GT(o.bar_travel, 0.01) << label << ": the rockers did not move on rough ground";
    EXPECT_LT(o.mimic_error, kMimicToleranceRad) << label;
    std::printf("%s: mimic error %.3g rad, bar travel %.3g rad\n", label.c_str(), o.mimic_error, o.bar_travel);
  }
}

TEST(RoverScenesTest, ClimbsALowStepInBothEnginesAndModes) {
  for (const auto& [engine, mode] : kEngines) {
    const std::string label = engine + ", " + mode;
    // 5 cm (half a wheel radius) at mu 0.8, at 0.2 m/s: every wheel ends on the top.
    const Outcome o =
        run("rover_step", engine, mode, {{"step_height", "0.05"}, {"wheel_rate", "2.0"}, {"duration", "8"}});
    EXPECT_TRUE(o.summary.success) << label;
    EXPECT_GT(o.summary.fields.at("lowest_wheel_height_m"), 0.05) << label;
    EXPECT_LT(o.mimic_error, kMimicToleranceRad) << label;
  }
}

// The rover over a GeoTIFF DEM (scenes/rover_dem.yaml: terrains/sample_dem.yaml,
// 2 cm cells kept compact, the engines' bodies on their own heightfield
// shapes): it starts with its front right wheel on a 3.1 cm rock, which its
// middle right wheel climbs after 0.36 m (2.8 s); the differential moves,
// nothing tips.
TEST(RoverScenesTest, CrossesASampleDemAndItsRockInEveryEngine) {
  for (const std::string& engine : everyEngineName(Variants::kLeftOut)) {
    const Outcome o = run("rover_dem", engine, "force", {{"duration", "4"}, {"success.min_distance", "0.5"}},
                          /*scene_step=*/true);
    EXPECT_TRUE(o.summary.success) << engine;                      // its energy check included
    EXPECT_GT(o.summary.fields.at("distance_m"), 0.55) << engine;  // 0.2 m/s after the 1 s ramp
    EXPECT_LT(o.summary.fields.at("max_tilt_deg"), 10.0) << engine;
    EXPECT_GT(o.bar_travel, 0.01) << engine << ": the rockers did not move over the rock";
    EXPECT_LT(o.mimic_error, kMimicToleranceRad) << engine;
  }
}

// A mimic between two joints about parallel axes (right rocker = -left
// rocker, tests/urdf/mimic_parallel_axes.urdf) ties three bodies: Bullet
// holds it (a gear constraint on one multibody), MuJoCo too (a joint
// equality ties any two joints' coordinates), ODE refuses it by name.
TEST(RoverScenesTest, AMimicAboutParallelAxesIsHeldByBulletAndMujocoAndRefusedByOdeByName) {
  for (const char* engine : {"bullet", "ode", "mujoco"}) {
    sim::Scene s = sim::loadScene(kRoot / "scenes" / "rover_flat.yaml", std::vector<sim::Override>{{"engine", engine}});
    s.vehicle = vehicle::readUrdf(kRoot / "tests" / "urdf" / "mimic_parallel_axes.urdf").vehicle;
    if (std::string(engine) != "ode") {
      EXPECT_NO_THROW(sim::makeEngine(s.engine, *s.terrain, s.vehicle, s.placement));
      continue;
    }
    try {
      sim::makeEngine(s.engine, *s.terrain, s.vehicle, s.placement);
      ADD_FAILURE() << "ODE built a mimic about parallel axes";
    } catch (const InvalidInputError& e) {
      EXPECT_NE(std::string(e.what()).find("mimic joint 'right_rocker_joint'"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("parallel"), std::string::npos) << e.what();
    }
  }
}

}  // namespace rover_scenes_test
}  // namespace wtc::testing
