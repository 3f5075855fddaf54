#pragma once
// The scene of wtc_bench_bullet and wtc_bench_ode, defined once: six 21 kg
// wheels (cylinders r = 0.19 m, w = 0.12 m, upright), each on its own line
// across the rough ground of scenario 3 (terrains/rough_ground.yaml), driven
// by 3 N m from rest; 2 s of warm-up, then 10 s of timed 1 ms steps. An
// engine's scene class provides step(), contacts() and speed(); runScene
// times it and registers the three runs <Engine>Step/{native, wtc_force,
// wtc_constraint}.
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

/// The y of wheel i's line (m).
inline double laneY(int i) { return (i - 0.5 * (kWheels - 1)) * kLaneSpacingM; }

inline const Terrain& roughGround() {
  static const Terrain terrain = io::loadTerrain(WTC_SOURCE_DIR "/terrains/rough_ground.yaml");
  return terrain;
}

/// Times Scene(kind) over kTimedSteps steps; counters: wheels, contacts per
/// step (over all wheels), the first wheel's final speed.
template <typename Scene>
void runScene(benchmark::State& state, const std::string& kind) {
  Scene scene(kind);
  for (int k = 0; k < kWarmupSteps; ++k) scene.step();
  long contacts = 0, steps = 0;
  for (auto _ : state) {
    scene.step();
    contacts += scene.contacts();
    ++steps;
  }
  state.SetItemsProcessed(steps);
  state.counters["wheels"] = kWheels;
  state.counters["contacts"] = steps > 0 ? static_cast<double>(contacts) / steps : 0.0;
  state.counters["speed_mps"] = scene.speed();
}

/// Registers <prefix>/native, <prefix>/wtc_force, <prefix>/wtc_constraint.
template <typename Scene>
void registerScenes(const std::string& prefix) {
  for (const char* kind : {"native", "wtc_force", "wtc_constraint"}) {
    benchmark::RegisterBenchmark((prefix + "/" + kind).c_str(), &runScene<Scene>, std::string(kind))
        ->Iterations(kTimedSteps)
        ->Unit(benchmark::kMicrosecond);
  }
}

}  // namespace wtc::bench
