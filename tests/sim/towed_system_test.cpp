// The towed system against answers derived elsewhere: a steady pull's hitch
// force is the towed body's rolling resistance (statics of free-rolling
// wheels); the source's trajectory controller holds a straight line and an
// S-curve; a tug that cannot hold its path fails, and says so.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "sim_test_support.hpp"
#include "wtc/base/constants.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/run.hpp"
#include "wtc/sim/scene_file.hpp"
#include "wtc/sim/scene_run.hpp"

namespace wtc::testing {
namespace {

namespace fs = std::filesystem;
const fs::path kScenes = fs::path(WTC_SOURCE_DIR) / "scenes";

// Implicit mode at kImplicitModeStep, the others at the scene's step.
sim::Scene scene(const std::string& name, std::vector<sim::Override> overrides) {
  return sim::loadScene(kScenes / (name + ".yaml"), atImplicitModeStep(std::move(overrides)));
}

sim::RunSummary run(const sim::Scene& s) {
  const auto engine = sim::makeEngine(s.engine, *s.terrain, s.vehicle, s.placement);
  return sim::runScene(s, *engine);
}

// Every engine (not ODE's quickstep variant) in every mode it serves.
const std::vector<std::pair<std::string, std::string>> kEngines = everyEngineByName(Variants::kLeftOut);

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

// Up the 2 deg incline (friction case 1, which holds the path), the hitch pulls the towed body (5160 kg with
// its wheels) up the grade, against its free wheels' rolling resistance, and speeds it up: over a stretch
// past the start, the hitch's mean force on it along the slope is m_b (g sin theta + a) + sum f_r R_z r_0 / r_f + sum I
// a / r_f^2 with a the towed body's mean acceleration over the stretch (its change of speed over the time) and the
// resistance summed over the towed wheels' contacts. (docs/validation.md's candidate "the towed pull
// against grade"; docs/towed-system.md: about 3.1 kN.)
TEST(TowedSystemTest, PullUpTheInclineIsTheGradeTheRollingResistanceAndTheAcceleration) {
  // Relative (measured: within 4e-6 in Bullet and ODE, force and constraint mode).
  constexpr double kTolerance = 0.005;
  constexpr double kFromSeconds = 1.5, kToSeconds = 5.0;  // past the start's take-up of the hitch (its peaks)
  for (const auto& [engine, mode] : kEngines) {
    const sim::Scene s = scene("towed_incline", {{"engine", engine}, {"mode", mode}, {"friction_case", "1"}});
    const auto e = sim::makeEngine(s.engine, *s.terrain, s.vehicle, s.placement);
    const auto controller = s.make_controller();
    sim::Run run(*e, controller.get(), s.vehicle_effects);
    const double slope = s.parameters.at("slope_deg") * 3.14159265358979323846 / 180.0;
    const Eigen::Vector3d uphill(std::cos(slope), 0.0, std::sin(slope));  // the path runs up the slope along x
    const int towed = s.vehicle.find("towed");
    double towed_mass = 0.0, spin_mass = 0.0;  // m_b and sum I / r_f^2 of the towed body's wheels (kg)
    std::vector<int> towed_wheels;
    for (std::size_t i = 0; i < s.vehicle.bodies.size(); ++i) {
      int root = static_cast<int>(i);
      while (s.vehicle.bodies[root].parent >= 0) root = s.vehicle.bodies[root].parent;
      if (root != towed) continue;
      const vehicle::Body& b = s.vehicle.bodies[i];
      towed_mass += b.mass;
      if (!b.wheel) continue;
      towed_wheels.push_back(static_cast<int>(i));
      const double r = b.wheel->geometry.free_radius;
      spin_mass += b.wheel->axle.cwiseAbs().dot(b.inertia) / (r * r);
    }
    while (run.time() < kFromSeconds) run.step();
    const Eigen::Vector3d v1 = run.state().bodies[towed].linear_velocity;
    double pull = 0.0, resistance = 0.0;
    long n = 0;
    while (run.time() < kToSeconds) {
      run.step();
      pull += run.hitch()->force_on_b.dot(uphill);  // its vertical part, carrying the nose, counts by sin theta
      for (const int w : towed_wheels) {
        const double r0_over_rf = s.vehicle.bodies[w].wheel->tyre.rolling_radius_ratio;
        for (const ContactForce& c : e->wheelForces(w).contacts) {
          resistance += s.terrain->material(c.contact.piece).rolling_resistance * c.normal_force * r0_over_rf;
        }
      }
      ++n;
    }
    pull /= static_cast<double>(n);
    resistance /= static_cast<double>(n);
    const double a = (run.state().bodies[towed].linear_velocity - v1).norm() / (kToSeconds - kFromSeconds);
    const double expected = towed_mass * (kGravityMps2 * std::sin(slope) + a) + resistance + spin_mass * a;
    RecordProperty(std::string(engine) + "_" + mode + "_pull_N", std::to_string(pull));
    RecordProperty(std::string(engine) + "_" + mode + "_expected_N", std::to_string(expected));
    EXPECT_NEAR(pull, expected, kTolerance * expected)
        << engine << "/" << mode << ": grade " << towed_mass * kGravityMps2 * std::sin(slope) << " N, "
        << "acceleration " << (towed_mass + spin_mass) * a << " N, rolling resistance " << resistance << " N";
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
// Case 2 needs the rising branch of mu(s) (scenes/towed_incline.yaml); in
// MuJoCo's constraint mode the soft cone's friction lets the tug's tread
// slip past it (0.75 at 1 s, where force mode's is 0.14) onto the falling
// branch, and case 2 is lost as well (docs/mujoco-plugin.md, "Friction").
TEST(TowedSystemTest, LowestFrictionCaseFailsAndSaysSo) {
  for (const auto& [engine, mode] : kEngines) {
    for (const char* friction_case : {"1", "2", "3"}) {
      const sim::RunSummary r =
          run(scene("towed_incline", {{"engine", engine}, {"mode", mode}, {"friction_case", friction_case}}));
      const std::string label = std::string("case ") + friction_case + " in " + engine + "/" + mode;
      const bool soft_cone = engine == "mujoco" && mode == "constraint";
      if (std::string(friction_case) == "3" || (soft_cone && std::string(friction_case) == "2")) {
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
