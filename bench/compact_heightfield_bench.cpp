// wtc_bench_compact: the compact heightfield (src/terrain/compact_heightfield.hpp)
// against the stored prisms of addHeightfield, at 10^4 ... 10^8 cells.
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

#include <wtc/terrain/heightfield.hpp>
#include <wtc/terrain/terrain.hpp>
#include <wtc/contact/wheel_contact.hpp>

#include "bench_field.hpp"
#include "terrain/compact_heightfield.hpp"

namespace {

using namespace wtc::bench;

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
  runContactSteps(state, std::move(builder).build(), boxes);
}

// The contact steps at `cells`, rolling or cold, compact and (with_prisms)
// stored.
void registerContactSteps(long cells, bool cold, bool with_prisms) {
  const std::string path = join("/", std::to_string(cells)) + (cold ? "/cold" : "/rolling");
  benchmark::RegisterBenchmark(join("Contacts/compact", path).c_str(), contacts, true, cold)->Arg(cells);
  if (with_prisms)
    benchmark::RegisterBenchmark(join("Contacts/prisms", path).c_str(), contacts, false, cold)->Arg(cells);
}

const bool kRegistered = [] {
  for (const long cells : kFieldCells) {
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
      registerContactSteps(cells, cold, cells <= 1'000'000L);
    }
  }
  // The contact steps also at the size large terrains' targets name: 10^6
  // pieces (two a cell).
  for (bool cold : {false, true}) registerContactSteps(kMillionPieceCells, cold, true);
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
