// "The step loop allocates nothing" (issue 15), counted: this executable
// replaces the global operator new with a counting one and runs the ledge
// climb's vehicle, controller and run loop (sim::Run) in every engine and
// mode. Once warm, a step of WTC, the vehicle layer and the run loop makes
// no C++ allocation. The engines allocate through malloc (btAlignedAlloc,
// ODE's dAlloc), which this does not count: their allocations are theirs.
// Its own executable, so the counter sees only these tests.
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <new>

#include <gtest/gtest.h>

#include "wtc/io/scene_file.hpp"
#include "wtc/sim/make_engine.hpp"
#include "wtc/sim/run.hpp"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace wtc::testing {
namespace {

namespace fs = std::filesystem;

// Steps of 0.4 ms: 1 s to warm up (the robot starts, the controller
// approaches), then 2 s counted, the front wheels reaching the face in it.
constexpr int kWarmSteps = 2500;
constexpr int kCountedSteps = 5000;

TEST(StepAllocationTest, AWarmStepOfTheLedgeClimbAllocatesNothingInAnyEngineOrMode) {
  for (const char* engine : {"bullet", "ode", "ode_quick"}) {
    for (const char* mode : {"force", "constraint"}) {
      const sim::Scene s = io::loadScene(fs::path(WTC_SOURCE_DIR) / "scenes" / "robot_ledge.yaml",
                                         std::vector<io::Override>{{"engine", engine}, {"mode", mode}});
      const auto e = sim::makeEngine(s.engine, *s.terrain, s.vehicle, s.placement);
      const auto controller = s.make_controller();
      sim::Run run(*e, controller.get(), s.vehicle_effects);
      for (int i = 0; i < kWarmSteps; ++i) run.step();
      const long before = g_allocations.load();
      for (int i = 0; i < kCountedSteps; ++i) run.step();
      EXPECT_EQ(g_allocations.load() - before, 0) << engine << ", " << mode << " mode";
      EXPECT_FALSE(run.nonFinite());
    }
  }
}

}  // namespace
}  // namespace wtc::testing
