// CSV and PGM heightfield readers (formats and orientation in
// include/wtc/io/heightfield_file.hpp).
#include "wtc/io/heightfield_file.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <span>
#include <string_view>
#include <vector>

#include "csv_rows.hpp"
#include "file_support.hpp"
#include "wtc/base/error.hpp"

namespace wtc::io {
namespace {

using detail::where;

// Fills rows, cols and heights from `values` (file order, north row first)
// and checks the result, with the path in every message.
Heightfield assemble(const std::filesystem::path& path, const HeightfieldLayout& layout, int rows, int cols,
                     const std::vector<double>& values) {
  if (!std::isfinite(layout.height_scale)) {
    throw InvalidInputError(where(path) + "height_scale = " + std::to_string(layout.height_scale) + " is not finite");
  }
  Heightfield field;
  field.rows = rows;
  field.cols = cols;
  field.spacing_x = layout.spacing_x;
  field.spacing_y = layout.spacing_y;
  field.origin = layout.origin;
  field.base_depth = layout.base_depth;
  field.heights.resize(values.size());
  for (int k = 0; k < rows; ++k) {
    for (int c = 0; c < cols; ++c) {
      field.heights[static_cast<std::size_t>(rows - 1 - k) * cols + c] =
          layout.height_scale * values[static_cast<std::size_t>(k) * cols + c];
    }
  }
  try {
    validate(field);
  } catch (const InvalidInputError& e) {
    throw InvalidInputError(where(path) + e.what());
  }
  return field;
}

}  // namespace

Heightfield readHeightfieldCsv(const std::filesystem::path& path, const HeightfieldLayout& layout) {
  std::vector<double> values;
  int rows = 0;
  long cols = -1;
  long first_line = 0;
  detail::forEachCsvRow(path, detail::readDataFile(path), [&](long line, std::span<const double> row) {
    const auto count = static_cast<long>(row.size());
    if (cols < 0) {
      cols = count;
      first_line = line;
    } else if (count != cols) {
      throw InvalidInputError(where(path, line, 1) + std::to_string(count) + " values, but the first row (line " +
                              std::to_string(first_line) + ") has " + std::to_string(cols));
    }
    values.insert(values.end(), row.begin(), row.end());
    ++rows;
  });
  if (rows == 0) throw InvalidInputError(where(path) + "no rows of heights (empty file or only comments)");
  return assemble(path, layout, rows, static_cast<int>(cols), values);
}

namespace {

// The PGM header: whitespace-separated tokens with '#' comments, tracked by
// line and column for messages.
class PgmScanner {
 public:
  PgmScanner(const std::filesystem::path& path, std::string_view bytes) : path_(path), bytes_(bytes) {}

  // The next token as an unsigned integer; `what` names it in messages.
  long number(const char* what) {
    skipSpaceAndComments();
    const long line = token_line_ = line_, column = token_column_ = column_;
    long value = 0;
    const char* begin = bytes_.data() + pos_;
    const auto [ptr, ec] = std::from_chars(begin, bytes_.data() + bytes_.size(), value);
    if (pos_ >= bytes_.size()) {
      throw InvalidInputError(where(path_, line, column) + "file ends where " + what + " was expected");
    }
    const bool ends_well =
        ptr == bytes_.data() + bytes_.size() || std::isspace(static_cast<unsigned char>(*ptr)) || *ptr == '#';
    if (ec != std::errc() || ptr == begin || !ends_well || value < 0) {
      std::size_t end = pos_;
      while (end < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[end])) && end - pos_ < 20) ++end;
      throw InvalidInputError(where(path_, line, column) + "'" + std::string(bytes_.substr(pos_, end - pos_)) +
                              "' is not a valid " + what);
    }
    advance(static_cast<std::size_t>(ptr - begin));
    return value;
  }
  std::string_view magic() {
    if (bytes_.size() < 2) throw InvalidInputError(where(path_) + "too short for a PGM file");
    advance(2);
    return bytes_.substr(0, 2);
  }
  // After maxval of P5: exactly one whitespace byte, then the raster.
  std::size_t rasterStart() {
    if (pos_ >= bytes_.size() || !std::isspace(static_cast<unsigned char>(bytes_[pos_]))) {
      throw InvalidInputError(where(path_, line_, column_) + "expected one whitespace byte before the pixel data");
    }
    return pos_ + 1;
  }
  // Position of the last token number() read.
  long tokenLine() const { return token_line_; }
  long tokenColumn() const { return token_column_; }

 private:
  void advance(std::size_t n) {
    for (std::size_t i = 0; i < n; ++i, ++pos_) {
      if (bytes_[pos_] == '\n') {
        ++line_;
        column_ = 1;
      } else {
        ++column_;
      }
    }
  }
  void skipSpaceAndComments() {
    while (pos_ < bytes_.size()) {
      if (std::isspace(static_cast<unsigned char>(bytes_[pos_]))) {
        advance(1);
      } else if (bytes_[pos_] == '#') {
        while (pos_ < bytes_.size() && bytes_[pos_] != '\n') advance(1);
      } else {
        break;
      }
    }
  }

  const std::filesystem::path& path_;
  std::string_view bytes_;
  std::size_t pos_ = 0;
  long line_ = 1;
  long column_ = 1;
  long token_line_ = 1;
  long token_column_ = 1;
};

}  // namespace

Heightfield readHeightfieldPgm(const std::filesystem::path& path, const HeightfieldLayout& layout) {
  const std::string bytes = detail::readDataFile(path);
  PgmScanner scan(path, bytes);
  const std::string_view magic = scan.magic();
  if (magic != "P2" && magic != "P5") {
    throw InvalidInputError(where(path, 1, 1) + "not a grayscale PGM file (magic number '" + std::string(magic) +
                            "', expected 'P2' or 'P5')");
  }
  const long width = scan.number("width");
  const long height = scan.number("height");
  const long maxval = scan.number("maxval");
  if (width < 1 || height < 1 || width > 1 << 16 || height > 1 << 16) {
    throw InvalidInputError(where(path) + "image size " + std::to_string(width) + " x " + std::to_string(height) +
                            " is out of range (1 ... 65536 per side)");
  }
  if (maxval < 1 || maxval > 65535) {
    throw InvalidInputError(where(path) + "maxval = " + std::to_string(maxval) + " is out of range (1 ... 65535)");
  }
  const auto count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  std::vector<double> values(count);
  if (magic == "P5") {
    const std::size_t start = scan.rasterStart();
    const std::size_t bytes_per_sample = maxval < 256 ? 1 : 2;
    const std::size_t available = bytes.size() - std::min(start, bytes.size());
    if (available < count * bytes_per_sample) {
      throw InvalidInputError(where(path) + "truncated: the " + std::to_string(width) + " x " + std::to_string(height) +
                              " image needs " + std::to_string(count * bytes_per_sample) +
                              " bytes of pixel data, the file has " + std::to_string(available));
    }
    const auto* raster = reinterpret_cast<const unsigned char*>(bytes.data() + start);
    for (std::size_t i = 0; i < count; ++i) {
      // 16-bit samples are big-endian (netpbm).
      values[i] = bytes_per_sample == 1 ? raster[i] : (raster[2 * i] << 8 | raster[2 * i + 1]);
      if (values[i] > maxval) {
        throw InvalidInputError(where(path) + "pixel " + std::to_string(i) + " = " + std::to_string(values[i]) +
                                " exceeds maxval " + std::to_string(maxval));
      }
    }
  } else {
    for (std::size_t i = 0; i < count; ++i) {
      const long value = scan.number("gray level");
      if (value > maxval) {
        throw InvalidInputError(where(path, scan.tokenLine(), scan.tokenColumn()) + "gray level " +
                                std::to_string(value) + " exceeds maxval " + std::to_string(maxval));
      }
      values[i] = static_cast<double>(value);
    }
  }
  return assemble(path, layout, static_cast<int>(height), static_cast<int>(width), values);
}

Heightfield readHeightfieldFile(const std::filesystem::path& path, const HeightfieldLayout& layout) {
  const std::string ext = detail::lowerExtension(path);
  if (ext == ".pgm") return readHeightfieldPgm(path, layout);
  if (ext == ".csv" || ext == ".txt") return readHeightfieldCsv(path, layout);
  throw InvalidInputError(where(path) + "unknown heightfield format '" + ext + "' (expected .csv, .txt or .pgm)");
}

}  // namespace wtc::io
