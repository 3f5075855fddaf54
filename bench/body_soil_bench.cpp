// wtc_bench_body_soil: what a body's underside on soft soil costs a step
// (wtc::BodyOnSoil::step; issue 55, a belly dragging in sand): the price of
// the soil under a chassis against a chassis that does not touch it.
//
//   build/bench/wtc_bench_body_soil --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
//
// A 0.5 m x 0.3 m x 0.1 m plate of 150 kg (the belly of
// tests/sim/body_soil_engines_test.cpp) on Toyoura sand, one item = one
// step of 0.4 ms:
//   BodySoil/above                 1 cm above the sand: the pieces under its
//                                  box are looked up, none reaches it.
//   BodySoil/resting_fresh         at Bekker's sinkage on a slab that forgets
//                                  (375 nodes under it).
//   BodySoil/resting_remembered    the same in a 2 cm soil region (its nodes
//                                  read and pressed; at rest, unchanged).
//   BodySoil/sliding_remembered    sliding at 1 m/s through the region (new
//                                  nodes pressed at its front each step).
//   BodySoil/resting_field_2cm     at rest on a heightfield of sand sampled at
//                                  2 cm (two prisms a cell: ~800 pieces under it).
#include <benchmark/benchmark.h>

#include <string>

#include "wtc/terrain/heightfield.hpp"
#include "wtc/terrain/terrain_primitives.hpp"
#include "wtc/tyre/body_soil.hpp"
#include "wtc/tyre/ground_memory.hpp"

namespace {

constexpr double kStepS = 4e-4, kMassKg = 150.0, kThicknessM = 0.1, kRestDepthM = 0.011984;
constexpr double kTravelM = 20.0;

wtc::Terrain sand(bool field, bool remember) {
  wtc::TerrainBuilder builder;
  wtc::Material m;
  m.name = "sand";
  m.soil = *wtc::namedSoil("toyoura_sand");
  const wtc::MaterialId id = builder.addMaterial(m);
  if (field) {
    wtc::Heightfield f;
    f.cols = 101;
    f.rows = 51;
    f.spacing_x = f.spacing_y = 0.02;
    f.origin = {-1.0, -0.5, 0.0};
    f.heights.assign(static_cast<std::size_t>(f.rows * f.cols), 0.0);
    wtc::addHeightfield(builder, f, id);
  } else {
    wtc::SlabParams slab;
    slab.size_x = 2.0 * kTravelM + 4.0;
    slab.size_y = 4.0;
    wtc::addSlab(builder, slab, id);
  }
  if (remember) {
    wtc::SoilRegion r;
    r.origin = {-1.0, -1.0};
    r.size = {kTravelM + 2.0, 2.0};
    builder.addSoilRegion(r);
  }
  return std::move(builder).build();
}

void bodySoil(benchmark::State& state, bool field, bool remember, double height, double speed) {
  const wtc::Terrain terrain = sand(field, remember);
  wtc::GroundMemory memory(terrain);
  wtc::BodyOnSoil body({wtc::ConvexPolyhedron::box({-0.25, -0.15, -kThicknessM / 2}, {0.25, 0.15, kThicknessM / 2})},
                       kMassKg);
  wtc::BodySoilMotion motion;
  motion.pose.translation() = Eigen::Vector3d(0.0, 0.0, height + kThicknessM / 2);
  motion.velocity.x() = speed;
  int nodes = 0;
  for (auto _ : state) {
    const wtc::BodySoilForces f = body.step(terrain, remember ? &memory : nullptr, motion, kStepS);
    benchmark::DoNotOptimize(f.force);
    nodes = f.nodes;
    motion.pose.translation().x() += speed * kStepS;
    if (motion.pose.translation().x() > kTravelM) motion.pose.translation().x() = 0.0;
  }
  state.counters["nodes"] = nodes;
  state.counters["touched_nodes"] = static_cast<double>(memory.touchedNodes());
}

const bool kRegistered = [] {
  benchmark::RegisterBenchmark("BodySoil/above", bodySoil, false, false, 0.01, 0.0);
  benchmark::RegisterBenchmark("BodySoil/resting_fresh", bodySoil, false, false, -kRestDepthM, 0.0);
  benchmark::RegisterBenchmark("BodySoil/resting_remembered", bodySoil, false, true, -kRestDepthM, 0.0);
  benchmark::RegisterBenchmark("BodySoil/sliding_remembered", bodySoil, false, true, -kRestDepthM, 1.0);
  benchmark::RegisterBenchmark("BodySoil/resting_field_2cm", bodySoil, true, false, -kRestDepthM, 0.0);
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
