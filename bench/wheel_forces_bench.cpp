// wtc_bench_forces: the cost per wheel per step of the tyre model
// (wtc::TyreModel), for the full model and for each effect switched on
// alone, so the README can show what each effect costs.
//
//   build/bench/wtc_bench_forces --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// and for the README's table, the same with --benchmark_format=json > forces.json, then
//   python3 tools/bench_table.py forces.json
//
// Runs (one item = one wheel step of h = 1 ms):
//   WheelForces/<effects>      TyreModel::step, contact search + forces: the
//       whole per-wheel work of a simulation step, along the path below.
//   WheelForcesOnly/<effects>  TyreModel::forces alone, on a contact list
//       found once at the foot of a 0.65 m ledge (the ground and the vertical
//       face, 2 mm deep each): the force half of a step without the contact
//       search. Each model gets the contacts its own contact options give
//       there: both with multiple_contacts, else only the deepest.
//       WheelForcesOnly/tread_truncation runs the same kernel on the same
//       contact as WheelForcesOnly/minimal: their difference is the noise.
// <effects>: full (EffectSet::full()), minimal (EffectSet::minimal(): the
// elastic normal force alone), or an effect name (wtc::effectName): minimal
// plus that effect.
//
// Scenario of WheelForces: a heightfield of 0.5 m cells, 45,000 pieces (the
// cells of wtc_bench_wheel), with a gentle undulation along the path (slopes
// below 5 deg) and a trough under the middle of the path: a V one cell wide
// on each side, 10 deg flanks, 8.8 cm deep, its depth ramping in and out
// over 2 m. In the trough the wheel touches both flanks, so multiple
// contacts matter: measured, 55 % of the steps of the full model have two
// contacts or more (counter multi_contact_fraction), 1.56 contacts per step
// on average (contacts_per_step). The ground is level across the path
// because the wheel is held on the path's line: on a cross slope it would
// touch only the steeper flank of the trough.
// The wheel (WheelDescription defaults, r_f = 0.19 m) rolls along the 20 m
// path at 1 mm per step (1 m/s), its centre placed so that its deepest
// contact is 2 mm deep, turning 5 % faster than rolling (driving slip, so
// traction and rolling resistance work); at the end of a lap it jumps back
// to the start (one step in 20,000). One WheelState per run, warmed up by one
// lap before timing. Counters: contacts_per_step, multi_contact_fraction,
// allocs_per_step (heap allocations per step, counted by the operator new of
// allocation_count.cpp: tyre_model.hpp says a warm step allocates nothing).
//
//   WheelSoil/<ground>  TyreModel::step of the full model with soft_soil on a
//       flat slab: <ground> a shipped soil (wtc::namedSoil), or hard (the same
//       slab without a soil: the same run's baseline). Ishigami's wheel
//       (r 0.09 m, b 0.11 m) 15 mm deep, rolling at 0.1 m/s with slip 0.2.
//   WheelSoil/toyoura_sand_remembers_<s>/<pass>  the same on Toyoura sand
//       whose slab is a soil region of spacing s (wtc::GroundMemory, issue
//       55): first_pass, every step reading the ground ahead and pressing
//       the nodes the lowest point passes (the lap of 30 m is not completed
//       in a run); rut, after one untimed lap, 19 mm deep in the rut it left
//       (every read a stored node).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <wtc/terrain/soil.hpp>
#include <wtc/tyre/ground_memory.hpp>
#include <wtc/tyre/effects.hpp>
#include <wtc/terrain/heightfield.hpp>
#include <wtc/terrain/terrain_primitives.hpp>
#include <wtc/tyre/tyre_model.hpp>

#include "allocation_count.hpp"
#include "resting_centre.hpp"

namespace {

using Eigen::Vector3d;

// The step and the wheel's motion.
constexpr double kStepSeconds = 1e-3;             // h (s)
constexpr double kSpeed = 1.0;                    // horizontal speed along the path (m/s)
constexpr double kStepM = kSpeed * kStepSeconds;  // path advance per step (m)
constexpr double kSlip = 0.05;                    // tread speed / rolling speed - 1 (dimensionless)
constexpr double kDepthM = 0.002;                 // deflection of the deepest contact (m)
const Vector3d kForward = Vector3d::UnitX();      // direction of travel
const Vector3d kAxle = Vector3d::UnitY();         // a: spin about +y rolls the wheel toward +x

// The ground of WheelForces.
constexpr double kCellM = 0.5;                                    // heightfield spacing (m)
constexpr int kCells = 150;                                       // cells per side: 2 x 150^2 = 45,000 pieces
constexpr double kPathLengthM = 20.0;                             // one lap (m): 20,000 steps
constexpr double kFieldM = kCells * kCellM;                       // side of the field (m)
constexpr double kPathStartX = 0.5 * (kFieldM - kPathLengthM);    // path from here along +x (m)
constexpr double kPathY = 0.5 * kFieldM;                          // on the grid row kCells / 2 (m)
constexpr double kSwellM = 0.05, kSwellPerM = 0.7;                // undulation: amplitude (m), wavenumber (rad/m)
constexpr double kRippleM = 0.02, kRipplePerM = 2.3;              // a shorter one on top (m, rad/m)
constexpr double kTroughStartM = 4.0, kTroughEndM = 16.0;         // trough along the path (m from its start)
constexpr double kTroughRampM = 2.0;                              // depth ramps from 0 to full over this (m)
constexpr double kTroughFlankRad = 10.0 * M_PI / 180.0;           // flank slope (rad)
const double kTroughDepthM = kCellM * std::tan(kTroughFlankRad);  // full depth (m): flanks one cell wide

// The ground of WheelForcesOnly: the spec's ledge (0.65 m, LedgeParams{}).
constexpr int kForcesOnlyWarmupSteps = 1000;  // tread deflections settle well within this

// Height of the ground at (x, y), relative to the field's origin (m):
// undulating along the path, level across it, the trough's V on the path's row.
double groundHeight(double x, double y) {
  const double along = x - kPathStartX;
  const double trough =
      kTroughDepthM * std::clamp(std::min(along - kTroughStartM, kTroughEndM - along) / kTroughRampM, 0.0, 1.0);
  const double across = std::max(0.0, 1.0 - std::abs(y - kPathY) / kCellM);  // 1 on the row, 0 one row away
  return kSwellM * std::sin(kSwellPerM * x) + kRippleM * std::sin(kRipplePerM * x) - trough * across;
}

struct PathPoint {
  wtc::WheelPose pose;
  wtc::WheelMotion motion;
};

struct Scenario {
  wtc::Terrain terrain;
  std::vector<PathPoint> path;
};

// The centre above (x, y) whose deepest contact (full model's contact
// options) is kDepthM deep. Bisection on the height: the deepest deflection
// falls as the wheel rises; half a radius above the surface is deeper than
// kDepthM, two radii above is clear of the ground.
// The spin that rolls the wheel at `velocity` with kSlip: the tread point
// under the centre moves at -kSlip |velocity|, so traction drives forward.
wtc::WheelMotion drivenMotion(const Vector3d& velocity, double free_radius) {
  wtc::WheelMotion motion;
  motion.velocity = velocity;
  motion.angular_velocity = ((1.0 + kSlip) * velocity.norm() / free_radius) * kAxle;
  return motion;
}

Scenario makeScenario() {
  wtc::Heightfield field;
  field.rows = field.cols = kCells + 1;
  field.spacing_x = field.spacing_y = kCellM;
  field.heights.resize(static_cast<std::size_t>(field.rows) * field.cols);
  for (int r = 0; r < field.rows; ++r)
    for (int c = 0; c < field.cols; ++c) field.heights[r * field.cols + c] = groundHeight(c * kCellM, r * kCellM);
  wtc::TerrainBuilder builder;
  builder.reserve(field.pieceCount());
  wtc::addHeightfield(builder, field, builder.addMaterial({}));
  Scenario s{std::move(builder).build(), {}};

  const wtc::WheelGeometry wheel = wtc::WheelDescription{}.geometry;
  const auto steps = static_cast<std::size_t>(kPathLengthM / kStepM);
  const wtc::ContactOptions options = wtc::TyreModel(wtc::EffectSet::full()).contactOptions();
  wtc::WheelContactFinder finder;
  std::vector<Vector3d> centres;
  for (std::size_t k = 0; k < steps; ++k) {  // along +x (kForward)
    const double x = kPathStartX + k * kStepM;
    const double guess = *wtc::surfaceHeight(field, x, kPathY) + wheel.free_radius - kDepthM;
    centres.push_back(
        wtc::bench::restingCentre(s.terrain, finder, wheel, kAxle, options, x, kPathY, guess, kDepthM).centre);
  }
  // Velocity: the next step's displacement over h (the last one repeats the
  // one before, not the jump back to the start).
  for (std::size_t k = 0; k < steps; ++k) {
    const std::size_t next = std::min(k + 1, steps - 1);
    const Vector3d velocity = (centres[next] - centres[next - 1]) / kStepSeconds;
    s.path.push_back({{centres[k], kAxle}, drivenMotion(velocity, wheel.free_radius)});
  }
  return s;
}

const Scenario& scenario() {
  static const Scenario s = makeScenario();
  return s;
}

struct LedgeFoot {
  wtc::Terrain terrain;
  PathPoint at;
};

// The wheel against the ledge's face (x = 0) on the ground in front of it
// (z = 0), kDepthM into both, moving as on the path.
const LedgeFoot& ledgeFoot() {
  static const LedgeFoot f = [] {
    wtc::TerrainBuilder builder;
    wtc::addLedge(builder, wtc::LedgeParams{}, builder.addMaterial({}));
    const double r = wtc::WheelDescription{}.geometry.free_radius;
    return LedgeFoot{std::move(builder).build(),
                     {{{-(r - kDepthM), 0.0, r - kDepthM}, kAxle}, drivenMotion(kSpeed * kForward, r)}};
  }();
  return f;
}

bool finite(const wtc::WheelForces& result) { return result.force.allFinite() && result.torque.allFinite(); }

void addCounters(benchmark::State& state, double contacts, double multi, std::size_t allocations) {
  state.SetItemsProcessed(state.iterations());
  state.counters["contacts_per_step"] = benchmark::Counter(contacts, benchmark::Counter::kAvgIterations);
  state.counters["multi_contact_fraction"] = benchmark::Counter(multi, benchmark::Counter::kAvgIterations);
  state.counters["allocs_per_step"] =
      benchmark::Counter(static_cast<double>(allocations), benchmark::Counter::kAvgIterations);
}

void wheelForces(benchmark::State& state, wtc::EffectSet effects) {
  const Scenario& s = scenario();
  const wtc::TyreModel model(effects);
  const wtc::WheelDescription wheel;
  wtc::WheelState wheel_state;
  auto step = [&](const PathPoint& p) -> const wtc::WheelForces& {
    return model.step(s.terrain, wheel, p.pose, p.motion, kStepSeconds, wheel_state);
  };
  // Warm-up: one lap fills the state's capacities, warm starts and tread.
  for (const PathPoint& p : s.path) {
    if (!finite(step(p))) {
      state.SkipWithError("non-finite wheel force on the path");
      return;
    }
  }
  double contacts = 0.0, multi = 0.0;
  std::size_t k = 0;
  const std::size_t allocations = wtc::bench::allocationCount();
  for (auto _ : state) {
    const wtc::WheelForces& result = step(s.path[k]);
    k = k + 1 == s.path.size() ? 0 : k + 1;
    contacts += static_cast<double>(result.contacts.size());
    multi += result.contacts.size() >= 2 ? 1.0 : 0.0;
    benchmark::DoNotOptimize(result.force);
  }
  addCounters(state, contacts, multi, wtc::bench::allocationCount() - allocations);
}

void wheelForcesOnly(benchmark::State& state, wtc::EffectSet effects) {
  const LedgeFoot& f = ledgeFoot();
  const wtc::TyreModel model(effects);
  const wtc::WheelDescription wheel;
  wtc::WheelState wheel_state;
  wtc::WheelContactFinder finder;
  const auto found = finder.find(f.terrain, wheel.geometry, f.at.pose, model.contactOptions());
  const std::vector<wtc::WheelContact> contacts(found.begin(), found.end());
  if (contacts.size() != (effects.has(wtc::Effect::kMultipleContacts) ? 2u : 1u)) {
    state.SkipWithError("the ledge foot should give two contacts (one without multiple_contacts)");
    return;
  }
  auto forces = [&]() -> const wtc::WheelForces& {
    return model.forces(f.terrain.materials(), wheel, f.at.pose, f.at.motion, kStepSeconds, contacts, wheel_state);
  };
  for (int k = 0; k < kForcesOnlyWarmupSteps; ++k) {
    if (!finite(forces())) {
      state.SkipWithError("non-finite wheel force at the ledge foot");
      return;
    }
  }
  const std::size_t allocations = wtc::bench::allocationCount();
  for (auto _ : state) {
    const wtc::WheelForces& result = forces();
    benchmark::DoNotOptimize(result.force);
  }
  const double n = static_cast<double>(state.iterations());
  addCounters(state, n * static_cast<double>(contacts.size()), contacts.size() >= 2 ? n : 0.0,
              wtc::bench::allocationCount() - allocations);
}

// A wheel rolling on a flat slab of `soil` (none: hard ground), the slab a
// soil region of `spacing` (m; 0: none), timed in its own rut from a lap
// before when `rut`.
void wheelSoil(benchmark::State& state, const std::string& soil, double spacing, bool rut) {
  wtc::Material material;
  if (!soil.empty()) material.soil = wtc::namedSoil(soil);
  wtc::TerrainBuilder builder;
  wtc::SlabParams slab;
  slab.size_x = slab.size_y = 40.0;
  wtc::addSlab(builder, slab, builder.addMaterial(material));
  if (spacing > 0.0) {
    wtc::SoilRegion region;
    region.origin = {-20.0, -20.0};
    region.size = {40.0, 40.0};
    region.spacing = spacing;
    builder.addSoilRegion(region);
  }
  const wtc::Terrain terrain = std::move(builder).build();
  wtc::GroundMemory memory(terrain);
  wtc::WheelDescription wheel;
  wheel.geometry.free_radius = 0.09;
  wheel.geometry.tread_width = 0.11;
  const wtc::TyreModel model(wtc::EffectSet::full().with(wtc::Effect::kSoftSoil));
  wtc::WheelState wheel_state;
  if (spacing > 0.0) wheel_state.setGroundMemory(&memory);
  wtc::WheelMotion motion;
  const double speed = 0.1, slip = 0.2;
  motion.velocity = speed * kForward;
  motion.angular_velocity = speed / (wheel.geometry.free_radius * (1.0 - slip)) * kAxle;
  Vector3d centre{-15.0, 0.0, wheel.geometry.free_radius - 0.015};
  const auto roll = [&] {
    centre.x() = centre.x() > 15.0 ? -15.0 : centre.x() + speed * kStepSeconds;
    return &model.step(terrain, wheel, {centre, kAxle}, motion, kStepSeconds, wheel_state);
  };
  if (rut) {
    while (centre.x() <= 15.0) roll();
    centre.z() = wheel.geometry.free_radius - 0.019;
  }
  for (auto _ : state) benchmark::DoNotOptimize(roll()->force);
  if (spacing > 0.0) {
    state.counters["touched_nodes"] = static_cast<double>(memory.touchedNodes());
    state.counters["bytes_per_touched_node"] =
        memory.touchedNodes() > 0 ? static_cast<double>(memory.bytes()) / static_cast<double>(memory.touchedNodes()) : 0;
  }
}

const bool kRegistered = [] {
  benchmark::RegisterBenchmark("WheelSoil/hard", wheelSoil, std::string(), 0.0, false);
  for (const std::string& soil : wtc::soilNames()) {
    benchmark::RegisterBenchmark(("WheelSoil/" + soil).c_str(), wheelSoil, soil, 0.0, false);
  }
  for (const auto& [name, spacing] : {std::pair{"2cm", 0.02}, std::pair{"1cm", 0.01}}) {
    for (const bool rut : {false, true}) {
      const std::string label = std::string("WheelSoil/toyoura_sand_remembers_") + name + (rut ? "/rut" : "/first_pass");
      benchmark::RegisterBenchmark(label.c_str(), wheelSoil, std::string("toyoura_sand"), spacing, rut);
    }
  }
  // minimal, each effect alone on top of it (enumerator order), full.
  std::vector<std::pair<std::string, wtc::EffectSet>> sets = {{"minimal", wtc::EffectSet::minimal()}};
  for (int k = 0; k < static_cast<int>(wtc::Effect::kCount); ++k) {
    const auto effect = static_cast<wtc::Effect>(k);
    sets.emplace_back(std::string(wtc::effectName(effect)), wtc::EffectSet::minimal().with(effect));
  }
  sets.emplace_back("full", wtc::EffectSet::full());
  for (const auto& [name, effects] : sets) {
    benchmark::RegisterBenchmark(("WheelForces/" + name).c_str(), wheelForces, effects);
  }
  for (const auto& [name, effects] : sets) {
    benchmark::RegisterBenchmark(("WheelForcesOnly/" + name).c_str(), wheelForcesOnly, effects);
  }
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
