// wtc_bench_sim: the cost of one step of a whole vehicle (wtc::sim::Run:
// controller, drives, engine, sensors) in each engine, against the same
// vehicle's contact-free floor measured in the same run.
//
//   robot_rough/<engine>/<mode>: scenes/robot_rough.yaml at 0.4 ms, driving
//     over the rough ground (the speed case); modes force and
//     constraint (WTC), engine_cylinder and engine_sphere (the engine's own
//     wheel contact, the baseline);
//   robot_rough_compact/<engine>/<mode>: the same on the same ground with its
//     heightfield compact (terrains/rough_ground_compact.yaml): one height
//     field for the engine's own collisions instead of 7200 convex pieces;
//   robot_floor/<engine>: the same vehicle and commands, placed 1 km away
//     from any ground: everything but contacts.
// Every engine of the table, in every mode it serves.
//
// Counters: us_per_step (wall time per step), real_time_factor
// (h / wall time per step) and wtc_share (of the wall time, WTC's plugin's:
// Engine::contactSeconds). Usage:
//   build/bench/wtc_bench_sim --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/run.hpp"
#include "wtc/sim/scene_file.hpp"

namespace {

constexpr double kWarmupSeconds = 1.5;  // the robot settles and reaches its speed first

const std::filesystem::path kScene = std::filesystem::path(WTC_SOURCE_DIR) / "scenes/robot_rough.yaml";

const std::string kCompactGround = std::string(WTC_SOURCE_DIR) + "/terrains/rough_ground_compact.yaml";

enum class Ground { kStored, kCompact, kNone };

void stepScene(benchmark::State& state, const std::string& engine, const std::string& mode, Ground ground) {
  std::vector<wtc::sim::Override> overrides = {{"engine", engine}, {"mode", mode}};
  if (ground == Ground::kNone) overrides.push_back({"vehicle.translation", "[1000, 0, 0]"});
  if (ground == Ground::kCompact) overrides.push_back({"terrain", kCompactGround});
  const wtc::sim::Scene scene = wtc::sim::loadScene(kScene, overrides);
  const auto e = wtc::sim::makeEngine(scene.engine, *scene.terrain, scene.vehicle, scene.placement);
  const std::unique_ptr<wtc::vehicle::Controller> controller = scene.make_controller();
  wtc::sim::Run run(*e, controller.get(), scene.vehicle_effects);
  // The floor falls freely: it warms up the same number of steps.
  while (run.time() < kWarmupSeconds) run.step();
  const double wtc0 = e->contactSeconds();
  const auto t0 = std::chrono::steady_clock::now();
  for (auto _ : state) run.step();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  state.counters["wtc_share"] = wall > 0.0 ? (e->contactSeconds() - wtc0) / wall : 0.0;
  const double h = scene.engine.step_seconds;
  state.counters["us_per_step"] = benchmark::Counter(1e-6 * static_cast<double>(state.iterations()),
                                                     benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["real_time_factor"] =
      benchmark::Counter(h * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["nan"] = run.nonFinite() ? 1.0 : 0.0;
}

}  // namespace

int main(int argc, char** argv) {
  for (const std::string_view name : wtc::sim::engineNames()) {
    const std::string engine(name);
    for (const char* mode : {"force", "constraint", "implicit", "engine_cylinder", "engine_sphere"}) {
      wtc::sim::EngineSettings settings{.engine = engine};
      wtc::sim::parseMode(mode, settings, "wtc_bench_sim");
      if (!wtc::sim::servesWheels(settings)) continue;
      for (const auto& [prefix, ground] :
           {std::pair{"robot_rough/", Ground::kStored}, std::pair{"robot_rough_compact/", Ground::kCompact}}) {
        benchmark::RegisterBenchmark((prefix + engine + "/" + mode).c_str(),
                                     [=](benchmark::State& s) { stepScene(s, engine, mode, ground); })
            ->Unit(benchmark::kMicrosecond)
            ->UseRealTime()
            ->MinTime(2.0);
      }
    }
    benchmark::RegisterBenchmark(("robot_floor/" + engine).c_str(),
                                 [=](benchmark::State& s) { stepScene(s, engine, "force", Ground::kNone); })
        ->Unit(benchmark::kMicrosecond)
        ->UseRealTime()
        ->MinTime(2.0);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
