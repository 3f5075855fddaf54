// wtc_bench_spacing: one rolling wheel on the same surface sampled at 50, 5,
// 2 and 1 cm (issue 53, "where the time goes"): the contact search and the
// tyre model's whole step, with what the search did counted stage by stage.
//
//   build/bench/wtc_bench_spacing --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
//
// Runs (one item = one wheel step, h = 1 ms, the wheel 1 mm further on):
//   FieldSearch/<storage>/<spacing_mm>[/<ground>]  WheelContactFinder::find alone.
//   FieldStep/<storage>/<spacing_mm>[/<ground>]    TyreModel::step, full effects: search and forces.
// <storage>: prisms (addHeightfield: every prism stored) or compact
// (addCompactHeightfield: the samples, met as one surface, closed-form
// triangles and a contact per local minimum), or compact_per_prism (the same
// field met prism by prism, ContactOptions::field_surface off, FieldSearch
// only: the answer the surface reproduces).
// Counters, per step: candidates (the index's pieces within r_f of the centre),
// queried (point queries run), touching (pieces within r_f, or local minima
// of a surface), contacts (after the seam rule and the tread filter), surface
// (a surface's triangles answered in closed form), allocs_per_step.
//
// The surface (no <ground>): bench_field.hpp's relief (5 cm and 2 cm waves,
// slopes under 5 deg) with a 4 mm roughness of 7 cm wavelength on top, which
// the fine fields resolve and the 50 cm field samples as a few millimetres
// of noise. <ground> smooth: the relief alone; flat: a level plane (compact
// storage only): what a spacing costs where the ground is smooth at the
// scale of the cells.
// The field is 3 m x 1 m and a border of 0.5 m all round; the wheel (r_f
// 0.19 m, w 0.12 m, the robot's) rolls 2 m along the middle of the 3 m x 1 m
// at 1 mm a step, its deepest contact 2 mm deep in the sampled pieces
// (restingCentre), turning 5 % faster than rolling. The border keeps every
// cell the wheel meets off the field's edge by a cell at every spacing, 50 cm
// too: a cell within one of the edge has walls that are ground and is met as
// a prism (field_surface.hpp), so without it every 50 cm cell of the 1 m
// wide field went to GJK and the runs compared two different searches.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <wtc/terrain/heightfield.hpp>
#include <wtc/tyre/effects.hpp>
#include <wtc/tyre/tyre_model.hpp>

#include "bench_field.hpp"
#include "allocation_count.hpp"
#include "resting_centre.hpp"

namespace {

using Eigen::Vector3d;

constexpr double kStepSeconds = 1e-3;                  // h (s)
constexpr double kStepM = 0.001;                       // advance per step (m): 1 m/s
constexpr double kSlip = 0.05;                         // tread speed / rolling speed - 1
constexpr double kDepthM = 0.002;                      // the deepest contact's deflection (m)
constexpr double kFieldXM = 3.0, kFieldYM = 1.0;       // the field's extent, without its border (m)
constexpr double kBorderM = 0.5;                       // the border all round (m): a 50 cm cell and more
constexpr double kPathStartM = 0.5, kPathEndM = 2.5;   // the wheel's path along x, at y = kFieldYM / 2 (m)
constexpr double kRoughM = 0.004, kRoughPerM = 90.0;   // roughness: amplitude (m), wavenumber (rad/m)
constexpr int kSpacingsMm[] = {500, 50, 20, 10};        // the fields' cells (mm)
const Vector3d kAxle = Vector3d::UnitY();

enum class Ground { kRough, kSmooth, kFlat };

double surface(Ground ground, double x, double y) {
  if (ground == Ground::kFlat) return 0.0;
  const double relief = wtc::bench::relief(x, y);
  if (ground == Ground::kSmooth) return relief;
  return relief + kRoughM * std::sin(kRoughPerM * x) * std::sin(0.9 * kRoughPerM * y);
}

struct PathPoint {
  wtc::WheelPose pose;
  wtc::WheelMotion motion;
};

struct Scenario {
  wtc::Terrain terrain;
  std::vector<PathPoint> path;
};

wtc::WheelDescription robotWheel() {
  wtc::WheelDescription wheel;
  wheel.geometry = {0.19, 0.12};
  return wheel;
}

Scenario makeScenario(Ground ground, bool compact, double spacing) {
  wtc::Heightfield field;
  field.cols = static_cast<int>(std::lround((kFieldXM + 2.0 * kBorderM) / spacing)) + 1;
  field.rows = static_cast<int>(std::lround((kFieldYM + 2.0 * kBorderM) / spacing)) + 1;
  field.spacing_x = field.spacing_y = spacing;
  field.origin = Vector3d(-kBorderM, -kBorderM, 0.0);
  field.heights.resize(static_cast<std::size_t>(field.rows) * field.cols);
  for (int r = 0; r < field.rows; ++r)
    for (int c = 0; c < field.cols; ++c)
      field.heights[static_cast<std::size_t>(r) * field.cols + c] =
          surface(ground, field.origin.x() + c * spacing, field.origin.y() + r * spacing);
  wtc::TerrainBuilder builder;
  const wtc::MaterialId material = builder.addMaterial({});
  if (compact) {
    wtc::addCompactHeightfield(builder, field, material);
  } else {
    builder.reserve(field.pieceCount());
    wtc::addHeightfield(builder, field, material);
  }
  Scenario s{std::move(builder).build(), {}};

  const wtc::WheelDescription wheel = robotWheel();
  const wtc::ContactOptions options = wtc::TyreModel(wtc::EffectSet::full()).contactOptions();
  wtc::WheelContactFinder finder;
  const double y = 0.5 * kFieldYM;
  std::vector<Vector3d> centres;
  for (double x = kPathStartM; x < kPathEndM; x += kStepM) {
    const double guess = surface(ground, x, y) + wheel.geometry.free_radius - kDepthM;
    centres.push_back(
        wtc::bench::restingCentre(s.terrain, finder, wheel.geometry, kAxle, options, x, y, guess, kDepthM).centre);
  }
  for (std::size_t k = 0; k < centres.size(); ++k) {
    const std::size_t next = std::min(k + 1, centres.size() - 1);
    const Vector3d velocity = (centres[next] - centres[next - 1]) / kStepSeconds;
    wtc::WheelMotion motion;
    motion.velocity = velocity;
    motion.angular_velocity = ((1.0 + kSlip) * velocity.norm() / wheel.geometry.free_radius) * kAxle;
    s.path.push_back({{centres[k], kAxle}, motion});
  }
  return s;
}

// One scenario at a time: the 1 cm field's stored prisms are 160,000 pieces.
const Scenario& scenario(Ground ground, bool compact, int spacing_mm) {
  static std::unique_ptr<Scenario> s;
  static Ground made_ground = Ground::kRough;
  static bool made_compact = false;
  static int made_mm = 0;
  if (!s || made_ground != ground || made_compact != compact || made_mm != spacing_mm) {
    s.reset();
    s = std::make_unique<Scenario>(makeScenario(ground, compact, spacing_mm * 1e-3));
    made_ground = ground, made_compact = compact, made_mm = spacing_mm;
  }
  return *s;
}

struct Totals {
  double candidates = 0, queried = 0, touching = 0, contacts = 0, surface = 0;
  void add(const wtc::ContactSearchCounts& c) {
    candidates += static_cast<double>(c.candidates);
    surface += static_cast<double>(c.surface);
    queried += static_cast<double>(c.queried);
    touching += static_cast<double>(c.touching);
    contacts += static_cast<double>(c.contacts);
  }
  void report(benchmark::State& state, std::size_t allocations) const {
    state.SetItemsProcessed(state.iterations());
    const auto avg = [](double v) { return benchmark::Counter(v, benchmark::Counter::kAvgIterations); };
    state.counters["candidates"] = avg(candidates);
    state.counters["queried"] = avg(queried);
    state.counters["touching"] = avg(touching);
    state.counters["contacts"] = avg(contacts);
    state.counters["surface"] = avg(surface);
    state.counters["allocs_per_step"] = avg(static_cast<double>(allocations));
  }
};

void fieldSearch(benchmark::State& state, Ground ground, bool compact, int spacing_mm, bool field_surface) {
  const Scenario& s = scenario(ground, compact, spacing_mm);
  const wtc::WheelGeometry wheel = robotWheel().geometry;
  wtc::ContactOptions options = wtc::TyreModel(wtc::EffectSet::full()).contactOptions();
  options.field_surface = field_surface;
  wtc::WheelContactFinder finder;
  for (const PathPoint& p : s.path) finder.find(s.terrain, wheel, p.pose, options);  // warm-up lap
  Totals totals;
  std::size_t k = 0;
  const std::size_t allocations = wtc::bench::allocationCount();
  for (auto _ : state) {
    benchmark::DoNotOptimize(finder.find(s.terrain, wheel, s.path[k].pose, options).data());
    totals.add(finder.counts());
    k = k + 1 == s.path.size() ? 0 : k + 1;
  }
  if (compact && field_surface && totals.queried > 0.0) {
    // The runs compare one search at every spacing: a compact cell queried
    // as a prism means the wheel came within a cell of the field's edge.
    state.SkipWithError("the wheel met a cell at the field's edge, answered as a prism: widen kBorderM");
    return;
  }
  totals.report(state, wtc::bench::allocationCount() - allocations);
}

void fieldStep(benchmark::State& state, Ground ground, bool compact, int spacing_mm) {
  const Scenario& s = scenario(ground, compact, spacing_mm);
  const wtc::TyreModel model(wtc::EffectSet::full());
  const wtc::WheelDescription wheel = robotWheel();
  wtc::WheelState wheel_state;
  auto step = [&](const PathPoint& p) -> const wtc::WheelForces& {
    return model.step(s.terrain, wheel, p.pose, p.motion, kStepSeconds, wheel_state);
  };
  for (const PathPoint& p : s.path) {
    const wtc::WheelForces& f = step(p);
    if (!f.force.allFinite() || f.contacts.empty()) {
      state.SkipWithError("a step on the path without a finite force or without a contact");
      return;
    }
  }
  double contacts = 0.0;
  std::size_t k = 0;
  const std::size_t allocations = wtc::bench::allocationCount();
  for (auto _ : state) {
    const wtc::WheelForces& result = step(s.path[k]);
    contacts += static_cast<double>(result.contacts.size());
    benchmark::DoNotOptimize(result.force);
    k = k + 1 == s.path.size() ? 0 : k + 1;
  }
  Totals totals;
  totals.contacts = contacts;
  totals.report(state, wtc::bench::allocationCount() - allocations);
}

const bool kRegistered = [] {
  // The rough ground's runs carry no ground in their names, and only it is
  // also run on stored prisms and prism by prism (the answer the surface
  // reproduces, issue 53).
  for (const auto& [ground, name] :
       {std::pair{Ground::kRough, ""}, std::pair{Ground::kSmooth, "/smooth"}, std::pair{Ground::kFlat, "/flat"}}) {
    for (const bool compact : {false, true}) {
      if (!compact && ground != Ground::kRough) continue;
      for (const int mm : kSpacingsMm) {
        const std::string tail = std::string(compact ? "compact/" : "prisms/") + std::to_string(mm) + name;
        benchmark::RegisterBenchmark(("FieldSearch/" + tail).c_str(), fieldSearch, ground, compact, mm, true);
        benchmark::RegisterBenchmark(("FieldStep/" + tail).c_str(), fieldStep, ground, compact, mm);
        if (compact && ground == Ground::kRough) {
          benchmark::RegisterBenchmark(("FieldSearch/compact_per_prism/" + std::to_string(mm)).c_str(), fieldSearch,
                                       ground, compact, mm, false);
        }
      }
    }
  }
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
