// wtc_bench_dem_load: loading a large GeoTIFF DEM into a compact
// heightfield (issue 53, item 4): wall time and peak memory, each phase in
// its own process so that one's peak does not hide another's.
//
//   wtc_bench_dem_load write PATH [SIDE]  a SIDE x SIDE float32 GeoTIFF at
//                                         1 cm (default 10000: 1e8 samples)
//   wtc_bench_dem_load load PATH          readDem, then the compact field
//                                         and its terrain built
//
// The baseline in the same run is what the field must hold anyway: its
// samples at 8 bytes each. The report gives the peak resident memory
// above the process's own before loading, as a multiple of that.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "wtc/base/error.hpp"
#include "wtc/io/dem_file.hpp"
#include "wtc/terrain/heightfield.hpp"
#include "wtc/terrain/terrain.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point since) { return std::chrono::duration<double>(Clock::now() - since).count(); }

// A line of /proc/self/status in MiB ("VmRSS", "VmHWM").
double statusMiB(const std::string& key) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind(key + ":", 0) == 0) return std::stod(line.substr(key.size() + 1)) / 1024.0;  // kB
  }
  return std::nan("");
}

int write(const std::filesystem::path& path, int side) {
  wtc::Heightfield field;
  field.rows = field.cols = side;
  field.spacing_x = field.spacing_y = 0.01;
  field.heights.resize(static_cast<std::size_t>(side) * side);
  // Long waves and a cell-scale ripple, rounded to 1 mm as a survey's.
  for (int r = 0; r < side; ++r) {
    for (int c = 0; c < side; ++c) {
      const double x = 0.01 * c, y = 0.01 * r;
      const double h = 0.3 * std::sin(x / 7.0) * std::cos(y / 5.0) + 0.02 * std::sin(31.0 * x + 17.0 * y);
      field.heights[static_cast<std::size_t>(r) * side + c] = std::round(h * 1000.0) / 1000.0;
    }
  }
  const auto start = Clock::now();
  wtc::io::DemWriteOptions options;
  options.epsg = 32633;
  wtc::io::writeDemGeoTiff(path, field, options);
  std::printf("wrote %s: %d x %d samples, %.1f MiB, %.1f s\n", path.c_str(), side, side,
              std::filesystem::file_size(path) / 1048576.0, seconds(start));
  return 0;
}

int load(const std::filesystem::path& path) {
  const double before = statusMiB("VmRSS");
  auto start = Clock::now();
  wtc::io::DemInfo info;
  wtc::Heightfield field = wtc::io::readDem(path, {}, &info);
  const double read_s = seconds(start);
  const double samples = static_cast<double>(field.heights.size());
  const double after_read_peak = statusMiB("VmHWM");
  start = Clock::now();
  wtc::TerrainBuilder builder;
  const wtc::MaterialId material = builder.addMaterial(wtc::Material{});
  wtc::addCompactHeightfield(builder, std::move(field), material);
  const wtc::Terrain terrain = std::move(builder).build();
  const double build_s = seconds(start);
  const double peak = statusMiB("VmHWM");
  const double held = statusMiB("VmRSS");
  const double baseline = samples * 8.0 / 1048576.0;  // the samples as doubles
  std::printf("%s: %d x %d samples (%.3g), %zu pieces\n", path.c_str(), info.file_cols, info.file_rows, samples,
              terrain.pieceCount());
  std::printf("  readDem %.2f s (%.1f ns a sample), compact field and terrain %.2f s\n", read_s,
              read_s / samples * 1e9, build_s);
  std::printf("  memory above the process's own (%.0f MiB): peak while reading %.0f MiB, peak %.0f MiB, held %.0f MiB\n",
              before, after_read_peak - before, peak - before, held - before);
  std::printf("  baseline, the samples at 8 bytes: %.0f MiB; peak / baseline = %.2f, held / baseline = %.2f\n",
              baseline, (peak - before) / baseline, (held - before) / baseline);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string usage = "usage: wtc_bench_dem_load write PATH [SIDE] | load PATH";
  try {
    if (argc >= 3 && std::string(argv[1]) == "write") return write(argv[2], argc > 3 ? std::atoi(argv[3]) : 10000);
    if (argc == 3 && std::string(argv[1]) == "load") return load(argv[2]);
  } catch (const wtc::InvalidInputError& e) {
    std::fprintf(stderr, "wtc_bench_dem_load: %s\n", e.what());
    return 1;
  }
  std::fprintf(stderr, "%s\n", usage.c_str());
  return 2;
}
