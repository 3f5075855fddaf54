// The tilt table (wtc/sim/tilt_table.hpp) against statics, on a cart made
// for the check (tests/mobility/data/tilt_cart.yaml: half-track 0.18 m,
// half-wheelbase 0.30 m, centre of mass 0.317 m up, mu 0.8, wheels held).
// Issue 52, deliverable 2: set down on a slope of each angle, the cart
// tipped early (27.25 deg) after the drop's settling; on the table it
// settles level and tips where statics says, atan(t / h) = 29.59 deg, and
// slides up a grade at atan(mu) = 38.66 deg, in one run each, and a tilt
// rate halved moves the answer by less than 0.1 deg.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/scene_file.hpp"
#include "wtc/sim/scene_run.hpp"

namespace wtc::testing {
namespace {

namespace fs = std::filesystem;

constexpr double kDeg = 180.0 / std::numbers::pi;
const double kTipDeg = std::atan(0.18 / 0.317) * kDeg;  // 29.59
const double kSlideDeg = std::atan(0.8) * kDeg;          // 38.66
// The tyres' give: the downhill tyres' deflection and the tread's tangential
// spring turn the cart a little before it tips, and the tread creeps under a
// load near its friction (measured: tipped at 29.53, slid at 38.51-38.58 deg).
constexpr double kStaticsToleranceDeg = 0.25;
constexpr double kHalvedRateToleranceDeg = 0.1;  // the issue's

sim::RunSummary tilt(const std::string& engine, const std::string& axis, double rate_deg_s) {
  const std::vector<sim::Override> overrides = {
      {"engine", engine}, {"tilt_table.axis", axis}, {"tilt_table.rate_deg_s", std::to_string(rate_deg_s)}};
  const sim::Scene scene = sim::loadScene(fs::path(WTC_SOURCE_DIR) / "tests/mobility/data/tilt_cart_table.yaml",
                                          overrides, sim::requireEngine);
  const auto e = sim::makeEngine(scene.engine, *scene.terrain, scene.vehicle, scene.placement);
  return sim::runScene(scene, *e);
}

TEST(TiltTableTest, TheCartTipsAcrossTheTableWhereStaticsSaysInEveryEngine) {
  for (const char* engine : {"bullet", "ode"}) {
    const sim::RunSummary r = tilt(engine, "x", 1.0);
    EXPECT_TRUE(r.success) << engine;
    EXPECT_FALSE(r.fields.contains("tilt_slid_deg")) << engine;
    ASSERT_TRUE(r.fields.contains("tilt_tipped_deg")) << engine;
    EXPECT_NEAR(r.fields.at("tilt_tipped_deg"), kTipDeg, kStaticsToleranceDeg) << engine;
    // The run ends soon after the answer: kTiltAfterS, not the scene's 100 s.
    EXPECT_LT(r.sim_time, 1.0 + 31.0) << engine;
  }
}

TEST(TiltTableTest, TheCartSlidesDownTheGradeWhereStaticsSays) {
  for (const char* engine : {"bullet", "ode"}) {
    const sim::RunSummary r = tilt(engine, "y", 1.0);
    EXPECT_FALSE(r.fields.contains("tilt_tipped_deg")) << engine;
    ASSERT_TRUE(r.fields.contains("tilt_slid_deg")) << engine;
    EXPECT_NEAR(r.fields.at("tilt_slid_deg"), kSlideDeg, kStaticsToleranceDeg) << engine;
  }
}

TEST(TiltTableTest, HalvingTheTiltRateMovesTheAnswerByLessThanATenthOfADegree) {
  for (const char* axis : {"x", "y"}) {
    const sim::RunSummary fast = tilt("bullet", axis, 1.0), slow = tilt("bullet", axis, 0.5);
    const char* field = std::string(axis) == "x" ? "tilt_tipped_deg" : "tilt_slid_deg";
    ASSERT_TRUE(fast.fields.contains(field) && slow.fields.contains(field)) << axis;
    EXPECT_NEAR(slow.fields.at(field), fast.fields.at(field), kHalvedRateToleranceDeg) << axis;
  }
}

}  // namespace
}  // namespace wtc::testing
