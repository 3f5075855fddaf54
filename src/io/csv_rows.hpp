#pragma once
// Rows of numbers in a CSV text (internal to wtc::io), as the heightfield
// and ground-memory files hold them: values separated by commas, or by
// spaces and tabs on a line without a comma; blank lines and lines starting
// with '#' skipped; a UTF-8 byte-order mark (spreadsheets) skipped.
#include <filesystem>
#include <functional>
#include <span>
#include <string_view>

namespace wtc::io::detail {

/// Calls on_row(line, values) for each row (line: 1-based in the file).
/// Throws InvalidInputError "<path>:<line>:<column>: 'abc' is not a number
/// (row 3, value 2)", or "empty value" or "is not finite" the same way.
void forEachCsvRow(const std::filesystem::path& path, std::string_view text,
                   const std::function<void(long line, std::span<const double> values)>& on_row);

}  // namespace wtc::io::detail
