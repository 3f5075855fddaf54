#pragma once
// A two-dimensional NumPy array file (.npy, format versions 1.0 to 3.0:
// numpy.lib.format), read whole. Internal to wtc::io: readDem's source of
// heights for .npy files. Written by hand because Debian packages no C++
// reader of the format, and the format is a 10-byte preamble, a Python
// dict literal and the raw array.
#include <cstdint>
#include <filesystem>
#include <string>

namespace wtc::io::detail {

class NpyArray {
 public:
  /// Reads and checks the file: the magic string, the header dict
  /// ('descr', 'fortran_order', 'shape'), a 2-D shape, a numeric dtype
  /// (f4, f8, i1..i8, u1..u8, either byte order) and the data's length.
  /// Throws InvalidInputError "<path>: <reason>".
  explicit NpyArray(const std::filesystem::path& path);

  std::int64_t rows() const { return rows_; }
  std::int64_t cols() const { return cols_; }
  bool isInteger() const { return kind_ != 'f'; }
  /// Element (row, col) of the array as written (row 0 first), as a double.
  double at(std::int64_t row, std::int64_t col) const;

 private:
  std::string bytes_;
  std::size_t data_ = 0;  // offset of the first element
  std::int64_t rows_ = 0, cols_ = 0;
  char kind_ = 'f';       // 'f', 'i' or 'u'
  int size_ = 8;          // bytes per element
  bool swap_ = false;     // stored in the other byte order than this machine's
  bool fortran_ = false;  // column-major
};

}  // namespace wtc::io::detail
