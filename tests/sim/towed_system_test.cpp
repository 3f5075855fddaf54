// The towed system against answers derived elsewhere: a steady pull's hitch
// force is the towed body's rolling resistance (statics of free-rolling
// wheels); the source's trajectory controller holds a straight line and an
// S-curve; a tug that cannot hold its path fails, and says so.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "wtc/sim/scene_file.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/run.hpp"
#include "wtc/sim/scene_run.hpp"

namespace wtc::testing {
namespace {

namespace fs = std::filesystem;
const fs::path kScenes = fs::path(WTC_SOURCE_DIR) / "scenes";

sim::Scene scene(const std::string& name, std::vector<sim::Override> overrides) {
  return sim::loadScene(kScenes / (name + ".yaml"), overrides);
}

sim::RunSummary run(const sim::Scene& s) {
  const auto engine = sim::makeEngine(s.engine, *s.terrain, s.vehicle, s.placement);
  return sim::runScene(s, *engine);
}

const std::vector<std::pair<const char*, const char*>> kEngines = {
    {"bullet", "force"}, {"bullet", "constraint"}, {"ode", "force"}, {"ode", "constraint"}};

// A free-rolling wheel at steady speed carries no torque about its axle, so
// its ground force F along the path balances its rolling-resistance moment
// f_r R_z r_0 about the centre, at the lever r_f of the contact point P
// (on the undeformed tread): F = f_r R_z r_0 / r_f. The towed body at
// steady speed on flat ground is pulled by the hitch with the sum of these.
TEST(TowedSystemTest, SteadyPullEqualsTheTowedBodysRollingResistance) {
  // Relative. The pull comes out 0.5 % (constraint) to 1.3 % (force) below
  // the resistance (docs/towed-system.md); what takes the rest is not
  // accounted for yet, so the bound is 2 %.
  constexpr double kTolerance = 0.02;
  for (const auto& [engine, mode] : kEngines) {
    const sim::Scene s = scene("towed_straight", {{"engine", engine}, {"mode", mode}});
    const auto e = sim::makeEngine(s.engine, *s.terrain, s.vehicle, s.placement);
    const auto controller = s.make_controller();
    sim::Run run(*e, controller.get(), s.vehicle_effects);
    while (run.time() < 4.0) run.step();  // up to speed at 2 s, settled by 4 s
    double pull = 0.0, resistance = 0.0;
    long n = 0;
    const std::vector<int> towed_wheels = {s.vehicle.find("nose_wheel"), s.vehicle.find("main_left_wheel"),
                                           s.vehicle.find("main_right_wheel")};
    while (run.time() < s.duration_seconds) {
      run.step();
      pull += run.hitch()->force_local.x();
      for (const int w : towed_wheels) {
        const vehicle::Body& b = s.vehicle.bodies[w];
        const double r0_over_rf = b.wheel->tyre.rolling_radius_ratio;
        for (const ContactForce& c : e->wheelForces(w).contacts) {
          resistance += s.terrain->material(c.contact.piece).rolling_resistance * c.normal_force * r0_over_rf;
        }
      }
      ++n;
    }
    pull /= static_cast<double>(n);
    resistance /= static_cast<double>(n);
    RecordProperty(std::string(engine) + "_" + mode + "_pull_over_resistance", std::to_string(pull / resistance));
    EXPECT_NEAR(pull, resistance, kTolerance * resistance) << engine << "/" << mode;
  }
}

// Straight line and gentle S-curve (scenes/towed_path.yaml) on flat ground.
TEST(TowedSystemTest, TracksAStraightLineAndAGentleSCurveOnFlatGround) {
  constexpr double kFinalErrorM = 0.1;  // after 12 s; the start (from rest to 0.8 m/s) costs up to 0.35 m
  constexpr double kRmsErrorM = 0.2;
  for (const char* path : {"1", "2"}) {
    for (const auto& [engine, mode] : kEngines) {
      const sim::RunSummary r = run(scene("towed_path", {{"engine", engine}, {"mode", mode}, {"path", path}}));
      const std::string label = std::string("path ") + path + " in " + engine + "/" + mode;
      EXPECT_TRUE(r.success) << label;
      EXPECT_LT(r.fields.at("final_tracking_error_m"), kFinalErrorM) << label;
      EXPECT_LT(r.fields.at("rms_tracking_error_m"), kRmsErrorM) << label;
    }
  }
}

// The source's three friction cases on the 2 deg incline: the first two
// hold the path; the lowest (0.21 / 0.35) cannot, and the run says so.
TEST(TowedSystemTest, LowestFrictionCaseFailsAndSaysSo) {
  for (const auto& [engine, mode] : kEngines) {
    for (const char* friction_case : {"1", "2", "3"}) {
      const sim::RunSummary r =
          run(scene("towed_incline", {{"engine", engine}, {"mode", mode}, {"friction_case", friction_case}}));
      const std::string label = std::string("case ") + friction_case + " in " + engine + "/" + mode;
      if (std::string(friction_case) == "3") {
        EXPECT_FALSE(r.success) << label;
        EXPECT_THAT(r.warnings, ::testing::Contains(::testing::HasSubstr("path lost"))) << label;
      } else {
        EXPECT_TRUE(r.success) << label;
      }
    }
  }
}

// Polynomials run away outside the time they were made for: at the path's
// end_time the tug stops near its last point and stands still; a tug that
// lost its path stops instead of chasing it.
TEST(TowedSystemTest, AtItsEndThePathStopsTheTugAndSoDoesALostPath) {
  constexpr double kStillMps = 0.02;
  for (const auto& [engine, mode] : kEngines) {
    const std::string label = std::string(engine) + "/" + mode;
    const sim::RunSummary held =
        run(scene("towed_path", {{"engine", engine}, {"mode", mode}, {"path", "2"}, {"duration", "30"}}));
    EXPECT_TRUE(held.success) << label;
    EXPECT_LT(held.fields.at("final_speed_mps"), kStillMps) << label;
    // Stopping from 0.8 m/s takes it past the last point by its braking
    // distance (0.16-0.24 m measured), within the path's 0.5 m.
    EXPECT_LT(held.fields.at("final_tracking_error_m"), 0.5) << label;
    const sim::RunSummary lost =
        run(scene("towed_incline", {{"engine", engine}, {"mode", mode}, {"friction_case", "3"}, {"duration", "20"}}));
    EXPECT_FALSE(lost.success) << label;
    EXPECT_LT(lost.fields.at("final_speed_mps"), kStillMps) << label;
  }
}

}  // namespace
}  // namespace wtc::testing
