// The ruts of soil that remembers, in a file (format in
// include/wtc/io/ground_memory_file.hpp).
#include "wtc/io/ground_memory_file.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "atomic_file.hpp"
#include "csv_rows.hpp"
#include "file_support.hpp"
#include "wtc/base/error.hpp"

namespace wtc::io {
namespace {

// A position's digits: any double back to the bit; a stored float's digits:
// any float back to the bit.
constexpr int kDoubleDigits = std::numeric_limits<double>::max_digits10;
constexpr int kFloatDigits = std::numeric_limits<float>::max_digits10;

struct Row {
  double x, y;
  SoilMemory memory;
};

}  // namespace

void writeGroundMemoryCsv(const std::filesystem::path& path, const GroundMemory& memory) {
  std::vector<Row> rows;
  rows.reserve(memory.touchedNodes());
  memory.forEachTouchedNode([&](double x, double y, const SoilMemory& m) { rows.push_back({x, y, m}); });
  std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.y != b.y ? a.y < b.y : a.x < b.x; });
  std::string text =
      "# The ruts of soil that remembers (wtc::io::writeGroundMemoryCsv, include/wtc/io/ground_memory_file.hpp):\n"
      "# one touched node a line.\n"
      "# x_m,y_m,plastic_sinkage_m,max_pressure_pa\n";
  std::array<char, 128> line{};
  for (const Row& r : rows) {
    const int n = std::snprintf(line.data(), line.size(), "%.*g,%.*g,%.*g,%.*g\n", kDoubleDigits, r.x, kDoubleDigits,
                                r.y, kFloatDigits, r.memory.plastic_sinkage, kFloatDigits, r.memory.max_pressure);
    text.append(line.data(), static_cast<std::size_t>(n));
  }
  writeFileAtomically(path, text);
}

void readGroundMemoryCsv(const std::filesystem::path& path, GroundMemory& memory) {
  if (memory.regionCount() == 0) {
    throw InvalidInputError(detail::where(path) + "ruts given, but the terrain has no soil regions to hold them");
  }
  detail::forEachCsvRow(path, detail::readDataFile(path), [&](long line, std::span<const double> row) {
    const std::string at = detail::where(path, line, 1);
    if (row.size() != 4) {
      throw InvalidInputError(at + std::to_string(row.size()) +
                              " values; a node's line has 4: x_m, y_m, plastic_sinkage_m, max_pressure_pa");
    }
    if (row[3] < 0.0) throw InvalidInputError(at + "max_pressure_pa " + formatNumber(row[3]) + " must be >= 0");
    constexpr double kFloatMax = std::numeric_limits<float>::max();  // what a node stores
    if (std::abs(row[2]) > kFloatMax || row[3] > kFloatMax) {
      throw InvalidInputError(at + "a value beyond single precision, which a node stores");
    }
    if (!memory.setNode(row[0], row[1], {.plastic_sinkage = row[2], .max_pressure = row[3], .fresh = false})) {
      throw InvalidInputError(at + "(" + formatNumber(row[0]) + ", " + formatNumber(row[1]) +
                              ") is no node of the terrain's soil regions");
    }
  });
}

}  // namespace wtc::io
