// The .npy reader (format: numpy.lib.format, "NEP 1"; see npy_array.hpp).
#include "npy_array.hpp"

#include <bit>
#include <cstring>
#include <limits>
#include <string_view>

#include "file_support.hpp"
#include "wtc/base/error.hpp"

namespace wtc::io::detail {
namespace {

constexpr std::string_view kMagic = "\x93NUMPY";

// The value of `key` in the header dict: the text after "'key':" up to the
// next top-level ',' or '}' (a tuple's commas are inside its parentheses).
std::string_view dictValue(std::string_view dict, std::string_view key) {
  for (const char quote : {'\'', '"'}) {
    const std::string quoted = std::string(1, quote) + std::string(key) + quote;
    std::size_t at = dict.find(quoted);
    if (at == std::string_view::npos) continue;
    at = dict.find(':', at + quoted.size());
    if (at == std::string_view::npos) return {};
    std::size_t end = at + 1;
    int depth = 0;
    while (end < dict.size() && (depth > 0 || (dict[end] != ',' && dict[end] != '}'))) {
      if (dict[end] == '(') ++depth;
      if (dict[end] == ')') --depth;
      ++end;
    }
    std::string_view value = dict.substr(at + 1, end - at - 1);
    while (!value.empty() && value.front() == ' ') value.remove_prefix(1);
    while (!value.empty() && value.back() == ' ') value.remove_suffix(1);
    return value;
  }
  return {};
}

std::int64_t readDimension(std::string_view& text, const std::filesystem::path& path, std::string_view shape) {
  while (!text.empty() && (text.front() == ' ' || text.front() == ',')) text.remove_prefix(1);
  std::int64_t value = 0;
  std::size_t digits = 0;
  while (digits < text.size() && text[digits] >= '0' && text[digits] <= '9') {
    if (value > std::numeric_limits<std::int64_t>::max() / 10 - 9) {
      throw InvalidInputError(where(path) + "shape " + std::string(shape) + " is too large");
    }
    value = value * 10 + (text[digits] - '0');
    ++digits;
  }
  if (digits == 0) throw InvalidInputError(where(path) + "shape " + std::string(shape) + " is not a tuple of sizes");
  text.remove_prefix(digits);
  return value;
}

}  // namespace

NpyArray::NpyArray(const std::filesystem::path& path) : bytes_(readDataFile(path)) {
  const std::string_view all = bytes_;
  if (!all.starts_with(kMagic) || all.size() < 10) {
    throw InvalidInputError(where(path) + "not a NumPy .npy file (no \\x93NUMPY magic string)");
  }
  const auto major = static_cast<unsigned char>(all[6]);
  std::size_t header_length = 0, header_start = 0;
  if (major == 1) {
    header_length = static_cast<unsigned char>(all[8]) | static_cast<unsigned char>(all[9]) << 8;
    header_start = 10;
  } else if (major == 2 || major == 3) {
    if (all.size() < 12) throw InvalidInputError(where(path) + "truncated .npy header");
    for (int k = 3; k >= 0; --k) header_length = header_length << 8 | static_cast<unsigned char>(all[8 + k]);
    header_start = 12;
  } else {
    throw InvalidInputError(where(path) + ".npy format version " + std::to_string(major) +
                            " is not one WTC reads (1, 2 or 3)");
  }
  if (header_start + header_length > all.size()) throw InvalidInputError(where(path) + "truncated .npy header");
  const std::string_view dict = all.substr(header_start, header_length);
  data_ = header_start + header_length;

  const std::string_view descr = dictValue(dict, "descr");
  if (descr.size() != 5 || (descr.front() != '\'' && descr.front() != '"')) {
    throw InvalidInputError(where(path) + "dtype " + (descr.empty() ? std::string("(none)") : std::string(descr)) +
                            " is not a plain number type (structured or missing 'descr')");
  }
  const char order = descr[1];
  kind_ = descr[2];
  size_ = descr[3] - '0';
  const bool sized = kind_ == 'f' ? (size_ == 4 || size_ == 8) : (size_ == 1 || size_ == 2 || size_ == 4 || size_ == 8);
  if ((kind_ != 'f' && kind_ != 'i' && kind_ != 'u') || !sized || (order != '<' && order != '>' && order != '|')) {
    throw InvalidInputError(where(path) + "dtype " + std::string(descr) +
                            " is not numeric heights (expected float32/64 or an integer type)");
  }
  const bool little = std::endian::native == std::endian::little;
  swap_ = size_ > 1 && ((order == '<') != little);

  const std::string_view fortran = dictValue(dict, "fortran_order");
  if (fortran != "True" && fortran != "False") {
    throw InvalidInputError(where(path) + "header has no fortran_order True or False");
  }
  fortran_ = fortran == "True";

  std::string_view shape = dictValue(dict, "shape");
  const std::string shape_text(shape);
  if (shape.size() < 2 || shape.front() != '(' || shape.back() != ')') {
    throw InvalidInputError(where(path) + "header has no shape tuple");
  }
  shape = shape.substr(1, shape.size() - 2);
  rows_ = readDimension(shape, path, shape_text);
  while (!shape.empty() && shape.front() == ' ') shape.remove_prefix(1);
  if (shape.empty() || shape == ",") {
    throw InvalidInputError(where(path) + "shape " + shape_text + " is one-dimensional: heights need (rows, cols)");
  }
  cols_ = readDimension(shape, path, shape_text);
  while (!shape.empty() && (shape.front() == ' ' || shape.front() == ',')) shape.remove_prefix(1);
  if (!shape.empty()) {
    throw InvalidInputError(where(path) + "shape " + shape_text + " has more than two dimensions: heights need (rows, cols)");
  }
  // rows x cols x size, checked against the bytes there are (the product
  // of two header numbers can overflow 64 bits, so divide instead).
  const std::uint64_t have = all.size() - data_;
  const std::uint64_t per_row = static_cast<std::uint64_t>(size_) * static_cast<std::uint64_t>(cols_);
  const bool fits = per_row == 0 ? rows_ == 0 || cols_ == 0
                                 : static_cast<std::uint64_t>(rows_) <= have / per_row &&
                                       static_cast<std::uint64_t>(rows_) * per_row == have;
  if (!fits) {
    throw InvalidInputError(where(path) + "shape " + shape_text + " of " + std::to_string(size_) +
                            "-byte values does not match the file's " + std::to_string(have) + " bytes of data");
  }
  if (rows_ < 2 || cols_ < 2) {
    throw InvalidInputError(where(path) + "shape " + shape_text + ": a heightfield needs at least 2 x 2 samples");
  }
}

double NpyArray::at(std::int64_t row, std::int64_t col) const {
  const std::int64_t index = fortran_ ? col * rows_ + row : row * cols_ + col;
  unsigned char raw[8];
  std::memcpy(raw, bytes_.data() + data_ + static_cast<std::size_t>(index) * size_, size_);
  if (swap_) {
    for (int k = 0; k < size_ / 2; ++k) std::swap(raw[k], raw[size_ - 1 - k]);
  }
  auto as = [&raw]<typename T>(T) {
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return static_cast<double>(value);
  };
  switch (kind_) {
    case 'f':
      return size_ == 4 ? as(float{}) : as(double{});
    case 'i':
      return size_ == 1 ? as(std::int8_t{}) : size_ == 2 ? as(std::int16_t{}) : size_ == 4 ? as(std::int32_t{}) : as(std::int64_t{});
    default:
      return size_ == 1 ? as(std::uint8_t{}) : size_ == 2 ? as(std::uint16_t{}) : size_ == 4 ? as(std::uint32_t{}) : as(std::uint64_t{});
  }
}

}  // namespace wtc::io::detail
