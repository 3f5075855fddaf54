// Rows of numbers in a CSV text (see csv_rows.hpp).
#include "csv_rows.hpp"

#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include "file_support.hpp"
#include "wtc/base/error.hpp"

namespace wtc::io::detail {
namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

}  // namespace

void forEachCsvRow(const std::filesystem::path& path, std::string_view text,
                   const std::function<void(long line, std::span<const double> values)>& on_row) {
  std::string_view rest = text;
  if (rest.starts_with("\xEF\xBB\xBF")) rest.remove_prefix(3);  // UTF-8 byte-order mark (spreadsheets)
  std::vector<double> values;
  long rows = 0;
  for (long line = 1; !rest.empty(); ++line) {
    const std::size_t eol = rest.find('\n');
    const std::string_view text_line = rest.substr(0, eol);
    rest.remove_prefix(eol == std::string_view::npos ? rest.size() : eol + 1);
    std::size_t start = 0;
    while (start < text_line.size() && isBlank(text_line[start])) ++start;
    if (start == text_line.size() || text_line[start] == '#') continue;

    const bool commas = text_line.find(',') != std::string_view::npos;
    values.clear();
    std::size_t pos = 0;
    while (pos <= text_line.size()) {
      // One field: [pos, end) up to the next separator, then trimmed.
      std::size_t end = pos;
      if (commas) {
        while (end < text_line.size() && text_line[end] != ',') ++end;
      } else {
        while (pos < text_line.size() && isBlank(text_line[pos])) ++pos;
        if (pos == text_line.size()) break;
        end = pos;
        while (end < text_line.size() && !isBlank(text_line[end])) ++end;
      }
      std::size_t a = pos, b = end;
      while (a < b && isBlank(text_line[a])) ++a;
      while (b > a && isBlank(text_line[b - 1])) --b;
      const long column = static_cast<long>(a) + 1;
      const std::string at = " (row " + std::to_string(rows + 1) + ", value " + std::to_string(values.size() + 1) + ")";
      if (a == b) throw InvalidInputError(where(path, line, column) + "empty value" + at);
      const std::string_view token = text_line.substr(a, b - a);
      std::string_view digits = token.starts_with('+') ? token.substr(1) : token;
      double value = 0.0;
      const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
      if (ec != std::errc() || ptr != digits.data() + digits.size()) {
        throw InvalidInputError(where(path, line, column) + "'" + std::string(token) + "' is not a number" + at);
      }
      if (!std::isfinite(value)) {
        throw InvalidInputError(where(path, line, column) + "'" + std::string(token) + "' is not finite" + at);
      }
      values.push_back(value);
      pos = end + 1;
    }
    ++rows;
    on_row(line, values);
  }
}

}  // namespace wtc::io::detail
