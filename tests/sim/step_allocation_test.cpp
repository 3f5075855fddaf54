// "The step loop allocates nothing" (issue 15), counted: this executable
// links the counting operator new (tests/support/allocation_counter.hpp) and runs the ledge
// climb's vehicle, controller and run loop (sim::Run) in every engine and
// mode. Once warm, a step of WTC, the vehicle layer and the run loop makes
// no C++ allocation. The engines allocate through malloc (btAlignedAlloc,
// ODE's dAlloc), which this does not count: their allocations are theirs.
// Its own executable, so the counter sees only these tests.
#include <filesystem>

#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "wtc/sim/scene_file.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/run.hpp"

namespace wtc::testing {
namespace {

namespace fs = std::filesystem;

// Steps of 0.4 ms: 1 s to warm up (the robot starts, the controller
// approaches), then 2 s counted, the front wheels reaching the face in it.
constexpr int kWarmSteps = 2500;
constexpr int kCountedSteps = 5000;

TEST(StepAllocationTest, AWarmStepOfTheLedgeClimbAllocatesNothingInAnyEngineOrMode) {
  for (const char* engine : {"bullet", "ode", "ode_quick"}) {
    for (const char* mode : {"force", "constraint", "implicit"}) {
      const sim::Scene s = sim::loadScene(fs::path(WTC_SOURCE_DIR) / "scenes" / "robot_ledge.yaml",
                                         std::vector<sim::Override>{{"engine", engine}, {"mode", mode}});
      const auto e = sim::makeEngine(s.engine, *s.terrain, s.vehicle, s.placement);
      const auto controller = s.make_controller();
      sim::Run run(*e, controller.get(), s.vehicle_effects);
      for (int i = 0; i < kWarmSteps; ++i) run.step();
      const long before = allocationCount();
      for (int i = 0; i < kCountedSteps; ++i) run.step();
      EXPECT_EQ(allocationCount() - before, 0) << engine << ", " << mode << " mode";
      EXPECT_FALSE(run.nonFinite());
    }
  }
}

}  // namespace
}  // namespace wtc::testing
