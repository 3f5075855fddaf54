// wtc_bench_compact: the compact heightfield (src/compact_heightfield.hpp)
// against the stored prisms of addHeightfield, at 10^4 ... 10^7 cells.
//
//   build/bench/wtc_bench_compact --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
//
// Runs (<cells> = cells of 0.5 m, two pieces each):
//   Build/compact/<cells>   validating and keeping the heights (the field's
//       samples are made before timing); counter bytes_per_cell.
//   Build/prisms/<cells>    addHeightfield and the terrain index (up to 10^6
//       cells: 10^7 would take about 26 GB); counter bytes_per_cell.
//   Piece/compact/<cells>   forming one piece (a prism) at a random cell.
//   Overlap/<store>/<cells>/<path>  the pieces under a wheel's box (r_f =
//       0.19 m, 2 mm into the surface) from the grid (compact) or the
//       terrain index (prisms); <path> rolling (1 mm per query along a line)
//       or cold (a random place every query).
//   Contacts/<store>/<cells>/<path>  the whole per-wheel contact step
//       (wtc::WheelContactFinder on a wtc::Terrain: candidates, formed or
//       stored pieces, point queries, seam rule) at the same places;
//       counter contacts_per_query.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <wtc/heightfield.hpp>
#include <wtc/terrain.hpp>
#include <wtc/wheel_contact.hpp>

#include "compact_heightfield.hpp"

namespace {

constexpr double kCellM = 0.5;     // cell size (m)
constexpr double kRadius = 0.19;   // r_f (m)
constexpr double kStepM = 0.001;   // rolling: 1 m/s at a 1 ms step (m)
constexpr int kColdPoints = 4096;  // cold: random positions

double relief(double x, double y) {
  return 0.05 * std::sin(0.7 * x) * std::cos(0.9 * y) + 0.02 * std::sin(2.3 * x + 1.1 * y);
}

// A square field of about `cells` cells.
wtc::Heightfield makeField(long cells) {
  const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(cells))));
  wtc::Heightfield f;
  f.rows = f.cols = side + 1;
  f.spacing_x = f.spacing_y = kCellM;
  f.heights.resize(static_cast<std::size_t>(f.rows) * f.cols);
  for (int r = 0; r < f.rows; ++r)
    for (int c = 0; c < f.cols; ++c)
      f.heights[static_cast<std::size_t>(r) * f.cols + c] = relief(c * kCellM, r * kCellM);
  return f;
}

double cellsOf(const wtc::Heightfield& f) { return static_cast<double>(f.rows - 1) * (f.cols - 1); }

void buildCompact(benchmark::State& state) {
  const wtc::Heightfield field = makeField(state.range(0));
  std::size_t bytes = 0;
  for (auto _ : state) {
    wtc::Heightfield copy = field;  // the user's field, handed over
    const wtc::detail::CompactHeightfield compact(std::move(copy));
    bytes = compact.memoryBytes();
    benchmark::DoNotOptimize(bytes);
  }
  state.counters["bytes_per_cell"] = static_cast<double>(bytes) / cellsOf(field);
}

void buildPrisms(benchmark::State& state) {
  const wtc::Heightfield field = makeField(state.range(0));
  std::size_t bytes = 0;
  for (auto _ : state) {
    wtc::TerrainBuilder builder;
    wtc::addHeightfield(builder, field, builder.addMaterial({}));
    const wtc::Terrain terrain = std::move(builder).build();
    bytes = terrain.pieceMemoryBytes() + terrain.indexMemoryBytes();
  }
  state.counters["bytes_per_cell"] = static_cast<double>(bytes) / cellsOf(field);
}

void formPiece(benchmark::State& state) {
  const wtc::detail::CompactHeightfield compact(makeField(state.range(0)));
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<std::size_t> any(0, compact.pieceCount() - 1);
  for (auto _ : state) {
    const wtc::ConvexPolyhedron piece = compact.piece(any(rng));
    benchmark::DoNotOptimize(piece.bounds());
  }
}

// The wheel's boxes: rolling along y = const across the field, or random.
std::vector<wtc::Aabb> wheelBoxes(const wtc::Heightfield& f, bool cold) {
  std::vector<wtc::Aabb> boxes;
  const double width = (f.cols - 1) * kCellM, depth = (f.rows - 1) * kCellM;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = cold ? kColdPoints : static_cast<int>(std::min(width - 2.0, 100.0) / kStepM);
  for (int i = 0; i < n; ++i) {
    const double x = cold ? 1.0 + u(rng) * (width - 2.0) : 1.0 + i * kStepM;
    const double y = cold ? 1.0 + u(rng) * (depth - 2.0) : 0.5 * depth;
    const Eigen::Vector3d centre(x, y, relief(x, y) + kRadius - 0.002);
    boxes.push_back({centre - Eigen::Vector3d::Constant(kRadius), centre + Eigen::Vector3d::Constant(kRadius)});
  }
  return boxes;
}

void overlap(benchmark::State& state, bool compact_store, bool cold) {
  const wtc::Heightfield field = makeField(state.range(0));
  const std::vector<wtc::Aabb> boxes = wheelBoxes(field, cold);
  std::unique_ptr<wtc::detail::CompactHeightfield> compact;
  std::unique_ptr<wtc::Terrain> terrain;
  if (compact_store) {
    compact = std::make_unique<wtc::detail::CompactHeightfield>(field);
  } else {
    wtc::TerrainBuilder builder;
    wtc::addHeightfield(builder, field, builder.addMaterial({}));
    terrain = std::make_unique<wtc::Terrain>(std::move(builder).build());
  }
  std::vector<wtc::PieceId> out;
  out.reserve(64);
  std::size_t i = 0;
  long found = 0, queries = 0;
  for (auto _ : state) {
    out.clear();
    const wtc::Aabb& box = boxes[i];
    i = i + 1 == boxes.size() ? 0 : i + 1;
    if (compact) {
      compact->overlapping(box, 0, out);
    } else {
      terrain->overlapping(box, out);
    }
    found += static_cast<long>(out.size());
    ++queries;
  }
  state.counters["pieces_per_query"] = static_cast<double>(found) / static_cast<double>(queries);
}

void contacts(benchmark::State& state, bool compact_store, bool cold) {
  const wtc::Heightfield field = makeField(state.range(0));
  const std::vector<wtc::Aabb> boxes = wheelBoxes(field, cold);
  wtc::TerrainBuilder builder;
  const wtc::MaterialId material = builder.addMaterial({});
  if (compact_store) {
    wtc::addCompactHeightfield(builder, field, material);
  } else {
    wtc::addHeightfield(builder, field, material);
  }
  const wtc::Terrain terrain = std::move(builder).build();
  const wtc::WheelGeometry wheel{kRadius, 0.12};
  wtc::WheelContactFinder finder;
  std::size_t i = 0;
  long found = 0, queries = 0;
  for (auto _ : state) {
    const wtc::WheelPose pose{boxes[i].center(), Eigen::Vector3d::UnitY()};
    i = i + 1 == boxes.size() ? 0 : i + 1;
    found += static_cast<long>(finder.find(terrain, wheel, pose).size());
    ++queries;
  }
  state.counters["contacts_per_query"] = static_cast<double>(found) / static_cast<double>(queries);
}

// "a" + b, built by appending (GCC 12 warns, wrongly, on const char* + string&&).
std::string join(const char* a, const std::string& b) {
  std::string s(a);
  s += b;
  return s;
}

const bool kRegistered = [] {
  for (long cells : {10'000L, 100'000L, 1'000'000L, 10'000'000L}) {
    const std::string tail = join("/", std::to_string(cells));
    benchmark::RegisterBenchmark(join("Build/compact", tail).c_str(), buildCompact)
        ->Arg(cells)
        ->Unit(benchmark::kMillisecond);
    if (cells <= 1'000'000L) {
      benchmark::RegisterBenchmark(join("Build/prisms", tail).c_str(), buildPrisms)
          ->Arg(cells)
          ->Unit(benchmark::kMillisecond)
          ->Iterations(1);
    }
    benchmark::RegisterBenchmark(join("Piece/compact", tail).c_str(), formPiece)->Arg(cells);
    for (bool cold : {false, true}) {
      const std::string path = cold ? "/cold" : "/rolling";
      benchmark::RegisterBenchmark(join("Overlap/compact", tail + path).c_str(), overlap, true, cold)->Arg(cells);
      if (cells <= 1'000'000L) {
        benchmark::RegisterBenchmark(join("Overlap/prisms", tail + path).c_str(), overlap, false, cold)->Arg(cells);
      }
      benchmark::RegisterBenchmark(join("Contacts/compact", tail + path).c_str(), contacts, true, cold)->Arg(cells);
      if (cells <= 1'000'000L) {
        benchmark::RegisterBenchmark(join("Contacts/prisms", tail + path).c_str(), contacts, false, cold)->Arg(cells);
      }
    }
  }
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
