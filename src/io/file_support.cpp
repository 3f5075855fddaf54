#include "file_support.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "wtc/base/error.hpp"

namespace wtc::io::detail {

std::string readWholeFile(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InvalidInputError(where(path) + "file not found");
  if (std::filesystem::is_directory(path, ec)) throw InvalidInputError(where(path) + "is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidInputError(where(path) + "cannot open: " + std::strerror(errno));
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) throw InvalidInputError(where(path) + "cannot read: " + std::strerror(errno));
  return std::move(bytes).str();
}

std::string where(const std::filesystem::path& path, long line, long column) {
  return path.string() + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
}

std::string where(const std::filesystem::path& path) { return path.string() + ": "; }

}  // namespace wtc::io::detail
