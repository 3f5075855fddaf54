// sim::stepCount: a run's duration in whole steps, refused otherwise; and
// every shipped scene and every run of the accuracy study makes the same
// number of steps as when the count was rounded.
#include "wtc/sim/step_count.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "wtc/base/error.hpp"
#include "wtc/sim/scene_file.hpp"
#include "wtc/study/study_file.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/scene_run.hpp"

namespace wtc::sim {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

TEST(StepCountTest, AWholeNumberOfStepsToRoundoffIsCounted) {
  EXPECT_EQ(stepCount(6.0, 4e-4), 15000u);
  EXPECT_EQ(stepCount(0.3, 0.1), 3u);  // 2.9999999999999996 in doubles
  EXPECT_EQ(stepCount(1e-6, 2.5e-7), 4u);
  EXPECT_EQ(stepCount(0.1, 0.1), 1u);
}

TEST(StepCountTest, AStepLongerThanTheDurationOrNotDividingItIsRefused) {
  EXPECT_THAT([] { stepCount(0.2, 10.0); },
              ::testing::ThrowsMessage<InvalidInputError>(HasSubstr("the step is longer than the duration")));
  EXPECT_THAT([] { stepCount(25.0, 10.0); },  // once rounded to 3 steps: 30 s
              ::testing::ThrowsMessage<InvalidInputError>(
                  HasSubstr("the duration is 2.5 steps, not a whole number of them; the nearest durations that are: "
                            "20 s and 30 s")));
  EXPECT_THROW(stepCount(1.0, 0.0), InvalidInputError);
  EXPECT_THROW(stepCount(1.0, std::nan("")), InvalidInputError);
  EXPECT_THROW(stepCount(1e300, 1e-300), InvalidInputError);
}

// Case: a scene built in code, not read from a file, is refused too: a run
// never makes 0 steps and calls it a success.
TEST(StepCountTest, RunSceneRefusesAStepLongerThanItsDuration) {
  Scene scene = sim::loadScene(fs::path(WTC_SOURCE_DIR) / "scenes/robot_standing.yaml");
  scene.engine.step_seconds = 2.0 * scene.duration_seconds;
  const auto engine = makeEngine(scene.engine, *scene.terrain, scene.vehicle, scene.placement);
  EXPECT_THAT([&] { runScene(scene, *engine); },
              ::testing::ThrowsMessage<InvalidInputError>(HasSubstr("longer than the duration")));
}

// The rule changes no run that was meant: each shipped scene and each run
// of bench/accuracy_study.yaml (steps of 0.05 to 20 ms over 5, 6 and 18 s)
// loads, and makes the number of steps the rounded count made.
TEST(StepCountTest, EveryShippedSceneAndStudyRunKeepsItsStepCount) {
  std::vector<Scene> scenes;
  for (const auto& entry : fs::directory_iterator(fs::path(WTC_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() == ".yaml") scenes.push_back(sim::loadScene(entry.path()));
  }
  const study::StudyPlan plan = study::loadStudyPlan(fs::path(WTC_SOURCE_DIR) / "bench/accuracy_study.yaml");
  for (const study::PlannedRun& run : plan.runs) scenes.push_back(sim::loadScene(run.scene_file, run.overrides));
  ASSERT_GT(scenes.size(), 150u);
  for (const Scene& s : scenes) {
    const double n = s.duration_seconds / s.engine.step_seconds;
    EXPECT_EQ(stepCount(s.duration_seconds, s.engine.step_seconds), static_cast<std::uint64_t>(std::llround(n)))
        << s.name << ": " << s.duration_seconds << " s at " << s.engine.step_seconds << " s";
  }
}

}  // namespace
}  // namespace wtc::sim
