#pragma once
// A run's CSV series read back (wtc::study, internal): the files
// wtc::sim::Recorder writes, columns by header name.
#include <filesystem>
#include <string>
#include <vector>

namespace wtc::study::detail {

struct Series {
  std::vector<std::string> names;         ///< The header.
  std::vector<std::vector<double>> rows;  ///< rows[i][column]
  /// The column named `name`; InvalidInputError naming the file otherwise.
  std::size_t column(const std::string& name) const;
  std::filesystem::path file;
};

/// InvalidInputError naming the file and line for a missing file or a
/// cell that is not a number.
Series readSeries(const std::filesystem::path& file);

/// The value of column `c` at time `t` (column 0), linear between rows;
/// the first or last row's value outside them.
double valueAt(const Series& s, std::size_t c, double t);

}  // namespace wtc::study::detail
