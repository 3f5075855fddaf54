#pragma once
// Typed access to a YAML document with errors that name the file, the line
// and the column of the offending node, and the key path in the document.
// Internal to wtc::io (the terrain file reader).
#include <yaml-cpp/yaml.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>

#include "wtc/base/error.hpp"

namespace wtc::io::detail {

/// An error already positioned in the YAML file; passed through unchanged
/// by outer handlers.
class YamlError : public InvalidInputError {
 public:
  using InvalidInputError::InvalidInputError;
};

/// The file's YAML document. Throws InvalidInputError for a missing or
/// unreadable file and "<path>:<line>:<col>: YAML syntax error: ..." .
YAML::Node loadYamlFile(const std::filesystem::path& path);

/// Runs `read` (a loader's reading of `path`) and turns any yaml-cpp
/// exception that escapes it (a conversion of a node whose shape no check
/// foresaw: a tagged key, a mapping used as a key; found by fuzzing) into
/// "<path>:<line>:<col>: <yaml-cpp's message>".
template <class Read>
auto withYamlErrors(const std::filesystem::path& path, Read&& read) {
  try {
    return read();
  } catch (const YAML::Exception& e) {
    throw InvalidInputError(path.string() + ":" +
                            (e.mark.line >= 0 ? std::to_string(e.mark.line + 1) + ":" +
                                                    std::to_string(e.mark.column + 1) + ":"
                                              : std::string()) +
                            " " + e.msg);
  }
}

class YamlReader {
 public:
  /// `context` prefixes messages (e.g. "pieces[2] (ledge): ").
  YamlReader(const std::filesystem::path& path, std::string context = {}) : path_(path), context_(std::move(context)) {}

  YamlReader with(std::string context) const { return YamlReader(path_, std::move(context)); }
  const std::filesystem::path& path() const { return path_; }

  /// Throws YamlError "<path>:<line>:<col>: <context><message>" at `node`.
  [[noreturn]] void fail(const YAML::Node& node, const std::string& message) const;

  /// Throws if `map` is not a mapping or has a key outside `allowed`.
  void requireMap(const YAML::Node& map, const char* what) const;
  /// The allowed keys are those of `allowed` and of `also`.
  void checkKeys(const YAML::Node& map, std::initializer_list<const char*> allowed,
                 std::initializer_list<const char*> also = {}) const;

  /// map[key] when present and not null.
  static std::optional<YAML::Node> get(const YAML::Node& map, const char* key);
  /// map[key], or an error at `map` naming the missing key.
  YAML::Node require(const YAML::Node& map, const char* key) const;

  double number(const YAML::Node& node, const std::string& what) const;
  long long integer(const YAML::Node& node, const std::string& what) const;
  bool boolean(const YAML::Node& node, const std::string& what) const;
  std::string string(const YAML::Node& node, const std::string& what) const;
  /// A sequence of exactly N numbers.
  template <int N>
  Eigen::Matrix<double, N, 1> vector(const YAML::Node& node, const std::string& what) const {
    if (!node.IsSequence() || node.size() != N) {
      fail(node, what + ": expected a list of " + std::to_string(N) + " numbers");
    }
    Eigen::Matrix<double, N, 1> v;
    for (int i = 0; i < N; ++i) v[i] = number(node[i], what + "[" + std::to_string(i) + "]");
    return v;
  }

  /// Optional number / integer / boolean with a default.
  double number(const YAML::Node& map, const char* key, double fallback) const;
  long long integer(const YAML::Node& map, const char* key, long long fallback) const;
  bool boolean(const YAML::Node& map, const char* key, bool fallback) const;

  /// The placement of a piece: `translation: [x, y, z]` (m) and `rotation`,
  /// either {axis: [x, y, z], degrees: a} (or radians: a) or a list of such,
  /// applied in the listed order. Both optional (identity).
  Eigen::Isometry3d pose(const YAML::Node& map) const;

 private:
  Eigen::Matrix3d rotation(const YAML::Node& node) const;

  std::filesystem::path path_;
  std::string context_;
};

}  // namespace wtc::io::detail
