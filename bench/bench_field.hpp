#pragma once
// The field of the heightfield benchmarks (wtc_bench_compact): a square
// field of 0.5 m cells with a gentle relief, and the boxes of a wheel that
// rolls across it or jumps to random places.
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include <wtc/geometry/aabb.hpp>
#include <wtc/terrain/heightfield.hpp>
#include <wtc/terrain/terrain.hpp>
#include <wtc/terrain/triangle_mesh.hpp>
#include <wtc/contact/wheel_contact.hpp>

namespace wtc::bench {

inline constexpr double kCellM = 0.5;     // cell size (m)
inline constexpr double kRadius = 0.19;   // r_f (m)
inline constexpr double kStepM = 0.001;   // rolling: 1 m/s at a 1 ms step (m)
inline constexpr int kColdPoints = 4096;  // cold: random positions
// The heightfields' sizes (cells): 10^8 is 0.8 GB of samples, which the
// compact field and Bullet's shape keep; stored prisms, FCL and meshes stop
// earlier (each benchmark says where).
inline constexpr long kFieldCells[] = {10'000L, 100'000L, 1'000'000L, 10'000'000L, 100'000'000L};
inline constexpr long kMillionPieceCells = 500'000L;  // 10^6 pieces, two a cell

inline double relief(double x, double y) {
  return 0.05 * std::sin(0.7 * x) * std::cos(0.9 * y) + 0.02 * std::sin(2.3 * x + 1.1 * y);
}

// A square field of about `cells` cells.
inline Heightfield makeField(long cells) {
  const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(cells))));
  Heightfield f;
  f.rows = f.cols = side + 1;
  f.spacing_x = f.spacing_y = kCellM;
  f.heights.resize(static_cast<std::size_t>(f.rows) * f.cols);
  for (int r = 0; r < f.rows; ++r)
    for (int c = 0; c < f.cols; ++c)
      f.heights[static_cast<std::size_t>(r) * f.cols + c] = relief(c * kCellM, r * kCellM);
  return f;
}

inline double cellsOf(const Heightfield& f) { return static_cast<double>(f.rows - 1) * (f.cols - 1); }

// The wheel's boxes: rolling along y = const across the field, or random.
inline std::vector<Aabb> wheelBoxes(const Heightfield& f, bool cold) {
  std::vector<Aabb> boxes;
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

inline constexpr double kWheelWidthM = 0.12;  // the wheel's width (m)

// The timed loop of a contact-step benchmark: WTC's whole per-wheel step
// (WheelContactFinder::find) at each box's centre in turn, axle along y;
// counter contacts_per_query.
inline void runContactSteps(benchmark::State& state, const Terrain& terrain, const std::vector<Aabb>& boxes) {
  const WheelGeometry wheel{kRadius, kWheelWidthM};
  WheelContactFinder finder;
  std::size_t i = 0;
  long found = 0, queries = 0;
  for (auto _ : state) {
    const WheelPose pose{boxes[i].center(), Eigen::Vector3d::UnitY()};
    i = i + 1 == boxes.size() ? 0 : i + 1;
    found += static_cast<long>(finder.find(terrain, wheel, pose).size());
    ++queries;
  }
  state.counters["contacts_per_query"] = static_cast<double>(found) / static_cast<double>(queries);
}

// "a" + b, built by appending (GCC 12 warns, wrongly, on const char* + string&&).
inline std::string join(const char* a, const std::string& b) {
  std::string s(a);
  s += b;
  return s;
}

}  // namespace wtc::bench
