#include "series.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>

#include "wtc/base/error.hpp"

namespace wtc::study::detail {

std::size_t Series::column(const std::string& name) const {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) throw InvalidInputError(file.string() + ": no column " + name);
  return static_cast<std::size_t>(it - names.begin());
}

Series readSeries(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InvalidInputError(file.string() + ": cannot read the series");
  Series s;
  s.file = file;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::vector<std::string> cells;
    std::size_t start = 0;
    for (std::size_t comma; (comma = line.find(',', start)) != std::string::npos; start = comma + 1) {
      cells.push_back(line.substr(start, comma - start));
    }
    cells.push_back(line.substr(start));
    if (number == 1) {
      s.names = std::move(cells);
      continue;
    }
    if (cells.size() != s.names.size()) {
      throw InvalidInputError(file.string() + ":" + std::to_string(number) + ": " + std::to_string(cells.size()) +
                              " cells, the header has " + std::to_string(s.names.size()));
    }
    std::vector<double> row(cells.size());
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const std::string& cell = cells[c];
      const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), row[c]);
      if (error != std::errc() || end != cell.data() + cell.size()) {
        // nan and inf are written as such by a run that went non-finite.
        if (cell == "nan" || cell == "-nan") {
          row[c] = std::numeric_limits<double>::quiet_NaN();
        } else if (cell == "inf" || cell == "-inf") {
          row[c] = cell[0] == '-' ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
        } else {
          throw InvalidInputError(file.string() + ":" + std::to_string(number) + ": '" + cell + "' in column " +
                                  s.names[c] + " is not a number");
        }
      }
    }
    s.rows.push_back(std::move(row));
  }
  if (s.names.empty()) throw InvalidInputError(file.string() + ": empty (no header)");
  return s;
}

double valueAt(const Series& s, std::size_t c, double t) {
  const auto& rows = s.rows;
  if (rows.empty()) throw InvalidInputError(s.file.string() + ": no rows");
  if (t <= rows.front()[0]) return rows.front()[c];
  if (t >= rows.back()[0]) return rows.back()[c];
  const auto hi = std::lower_bound(rows.begin(), rows.end(), t, [](const auto& row, double v) { return row[0] < v; });
  if ((*hi)[0] == t) return (*hi)[c];  // a sample's own value, exactly (lo + 1 (hi - lo) need not be hi)
  const auto lo = hi - 1;
  const double w = ((*hi)[0] - (*lo)[0]) > 0.0 ? (t - (*lo)[0]) / ((*hi)[0] - (*lo)[0]) : 0.0;
  return (*lo)[c] + w * ((*hi)[c] - (*lo)[c]);
}

}  // namespace wtc::study::detail
