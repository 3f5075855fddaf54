#pragma once
// The scene of wtc_bench_bullet and wtc_bench_ode, defined once: six 21 kg
// wheels (cylinders r = 0.19 m, w = 0.12 m, upright), each on its own line
// across the rough ground of scenario 3 (terrains/rough_ground.yaml), driven
// by 3 N m from rest; 2 s of warm-up, then 10 s of timed 1 ms steps. An
// engine's scene class, made as Scene(kind, wheels), provides step(),
// contacts() and speed(); runScene times it. Registered runs:
// <Engine>Step/{native, wtc_force, wtc_constraint} with the six wheels, and
// <Engine>Wheels/<kind>/<n> with n = 1 ... 64 wheels on the same ground (8
// lines 1.5 m apart, rows 1 m apart along them): how a step's cost grows
// with the number of wheels.
#include <benchmark/benchmark.h>

#include <string>

#include <wtc/io/terrain_file.hpp>

namespace wtc::bench {

inline constexpr int kWheels = 6;
inline constexpr double kRadius = 0.19, kWidth = 0.12;      // (m)
inline constexpr double kMass = 21.0;                       // a sixth of the robot (kg)
inline constexpr double kStepSeconds = 1e-3;                // (s)
inline constexpr double kDriveTorque = 3.0;                 // per wheel (N m): twice the soil's rolling resistance
inline constexpr double kLaneSpacingM = 1.5;                // between the wheels' lines (m)
inline constexpr double kStartX = -12.0, kDropM = 0.05;     // start (m) and height above the ground (m)
inline constexpr double kStartZ = 0.15 + kRadius + kDropM;  // above the ground's highest bumps (m)
inline constexpr int kWarmupSteps = 2000;                   // settle and spin up
inline constexpr int kTimedSteps = 10000;                   // 10 s: every wheel stays on the 30 m ground

inline constexpr int kMaxLanes = 8;          // lines side by side; more wheels start in rows
inline constexpr double kRowSpacingM = 1.0;  // between rows along a line (m)
inline constexpr int kMaxWheels = 64;

/// Where wheel i of n starts: its line's y, and x a row further for every
/// kMaxLanes wheels (m).
inline double laneY(int i, int n) {
  const int lanes = n < kMaxLanes ? n : kMaxLanes;
  return ((i % kMaxLanes) - 0.5 * (lanes - 1)) * kLaneSpacingM;
}
inline double startX(int i) { return kStartX + (i / kMaxLanes) * kRowSpacingM; }

inline const Terrain& roughGround() {
  static const Terrain terrain = io::loadTerrain(WTC_SOURCE_DIR "/terrains/rough_ground.yaml");
  return terrain;
}

/// Times Scene(kind) over kTimedSteps steps; counters: wheels, contacts per
/// step (over all wheels), the first wheel's final speed.
template <typename Scene>
void runScene(benchmark::State& state, const std::string& kind, int wheels) {
  Scene scene(kind, wheels);
  for (int k = 0; k < kWarmupSteps; ++k) scene.step();
  long contacts = 0, steps = 0;
  for (auto _ : state) {
    scene.step();
    contacts += scene.contacts();
    ++steps;
  }
  state.SetItemsProcessed(steps);
  state.counters["wheels"] = wheels;
  state.counters["contacts"] = steps > 0 ? static_cast<double>(contacts) / steps : 0.0;
  state.counters["speed_mps"] = scene.speed();
}

/// Registers <engine>Step/<kind> (six wheels) and <engine>Wheels/<kind>/<n>
/// for kind in native, wtc_force, wtc_constraint.
template <typename Scene>
void registerScenes(const std::string& engine) {
  for (const char* kind : {"native", "wtc_force", "wtc_constraint"}) {
    benchmark::RegisterBenchmark((engine + "Step/" + kind).c_str(), &runScene<Scene>, std::string(kind), kWheels)
        ->Iterations(kTimedSteps)
        ->Unit(benchmark::kMicrosecond);
  }
  for (const char* kind : {"native", "wtc_force", "wtc_constraint"}) {
    for (int n = 1; n <= kMaxWheels; n *= 2) {
      benchmark::RegisterBenchmark((engine + "Wheels/" + kind + "/" + std::to_string(n)).c_str(), &runScene<Scene>,
                                   std::string(kind), n)
          ->Iterations(kTimedSteps)
          ->Unit(benchmark::kMicrosecond);
    }
  }
}

}  // namespace wtc::bench
