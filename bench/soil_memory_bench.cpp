// wtc_bench_soil_memory: what the ground's memory (issue 55) adds to one
// evaluation of the wheel-soil stresses (wtc::wheelSoilForces), the part of
// a wheel-step a soft soil costs.
//
//   build/bench/wtc_bench_soil_memory --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
//
// Runs (one item = one evaluation; Ishigami's wheel, r 0.09 m, b 0.11 m, on
// Toyoura sand 23 mm deep at slip 0.2, the wheel moved 0.1 mm along x
// between evaluations, wrapping over 10 m):
//   SoilStresses/fresh_surface   part 1: no memory.
//   SoilStresses/untouched_grid  the memory read from a 2 cm grid no wheel has
//                                touched (every sample a miss in the index).
//   SoilStresses/rutted_grid     the same grid with a 23 mm rut 0.11 m wide
//                                under the path (every sample a hit).
// Each item reads the memory at the 24 quadrature points and the entry's
// fixed point (4 more): 28 bilinear samples of 4 nodes each.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "terrain/soil_grid.hpp"
#include "tyre/soil_grid_profile.hpp"
#include "wtc/tyre/wheel_soil.hpp"

namespace {

using wtc::detail::GridProfile;
using wtc::detail::SoilGrid;

constexpr double kRadiusM = 0.09, kWidthM = 0.11, kSinkageM = 0.023, kPathM = 10.0, kStepM = 1e-4;

SoilGrid makeGrid(bool rutted) {
  wtc::SoilRegion spec;
  spec.origin = {-1.0, -1.0};
  spec.size = {kPathM + 2.0, 2.0};
  spec.spacing = 0.02;
  SoilGrid grid(spec);
  if (rutted) {
    for (int i = 0; i < grid.columns(); ++i) {
      for (int j = 47; j <= 53; ++j) grid.set(i, j, {0.023f, 2.0e4f});  // y within +-0.06 m
    }
  }
  return grid;
}

void soilStresses(benchmark::State& state, const std::string& ground) {
  const wtc::Soil soil = *wtc::namedSoil("toyoura_sand");
  const SoilGrid grid = makeGrid(ground == "rutted_grid");
  wtc::WheelSoilState wheel{.radius = kRadiusM, .width = kWidthM, .sinkage = kSinkageM, .slip = 0.2};
  double x = 0.0;
  for (auto _ : state) {
    x = x > kPathM ? 0.0 : x + kStepM;
    const GridProfile profile(grid, {x, 0.0}, {1.0, 0.0});
    wheel.memory = ground == "fresh_surface" ? nullptr : &profile;
    // In the rut the wheel's lowest point is the rut's floor plus the same sinkage.
    wheel.sinkage = ground == "rutted_grid" ? 0.023 + 0.004 : kSinkageM;
    const wtc::WheelSoilForces f = wtc::wheelSoilForces(soil, wheel);
    benchmark::DoNotOptimize(f.normal);
  }
  state.counters["bytes_per_touched_node"] =
      grid.touchedNodes() > 0 ? static_cast<double>(grid.bytes()) / static_cast<double>(grid.touchedNodes()) : 0.0;
}

const bool kRegistered = [] {
  for (const char* ground : {"fresh_surface", "untouched_grid", "rutted_grid"}) {
    benchmark::RegisterBenchmark((std::string("SoilStresses/") + ground).c_str(), soilStresses, std::string(ground));
  }
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
