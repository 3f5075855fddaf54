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
#include <vector>

#include "wtc/base/error.hpp"

namespace wtc::io::detail {

/// An error already positioned in the YAML file; passed through unchanged
/// by outer handlers.
class YamlError : public InvalidInputError {
 public:
  using InvalidInputError::InvalidInputError;
};

/// The file's YAML document. Throws InvalidInputError for a missing or
/// unreadable file (file_support.hpp: regular files within
/// kMaxDescriptionFileBytes), "<path>:<line>:<col>: YAML syntax error: ..."
/// and "<path>:<line>:<col>: duplicate key 'mass' (first at line 30) ..."
/// (checkNoDuplicateKeys): every reader of YAML files gets its document here.
YAML::Node loadYamlFile(const std::filesystem::path& path);

/// A key given twice in one mapping: yaml-cpp keeps both entries, and a
/// lookup finds the first, so the second would be ignored without a word.
struct DuplicateKey {
  std::string key;
  YAML::Mark first, second;
};

/// The first key that occurs twice in a mapping anywhere in `root` (in
/// document order of the mappings), or nothing. Keys compare as their
/// scalar text; mappings reached again through an alias are checked once.
std::optional<DuplicateKey> findDuplicateKey(const YAML::Node& root);

/// "duplicate key 'mass' (first at line 30): a key may appear once in a mapping".
std::string duplicateKeyMessage(const DuplicateKey& duplicate);

/// Nodes whose YAML marks do not say where they came from: an override's
/// value (its marks are in the override's own text) or a value a body
/// inherits from wheel_defaults (its marks are right, but the reader of
/// that body should say so).
struct NodeOrigin {
  YAML::Node subtree;              ///< The nodes concerned: this one and all below it.
  std::string label;               ///< "--set dt=-1", or "inherited by wheel 'w' from wheel_defaults".
  bool replaces_position = false;  ///< true: the label stands instead of line:column (an override).
};

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
                            (e.mark.line >= 0
                                 ? std::to_string(e.mark.line + 1) + ":" + std::to_string(e.mark.column + 1) + ":"
                                 : std::string()) +
                            " " + e.msg);
  }
}

class YamlReader {
 public:
  /// `context` prefixes messages (e.g. "pieces[2] (ledge): ").
  YamlReader(const std::filesystem::path& path, std::string context = {}) : path_(path), context_(std::move(context)) {}

  YamlReader with(std::string context) const {
    YamlReader copy = *this;
    copy.context_ = std::move(context);
    return copy;
  }
  /// This reader, naming the nodes of `origin` by its label.
  YamlReader withOrigin(NodeOrigin origin) const {
    YamlReader copy = *this;
    copy.origins_.push_back(std::move(origin));
    return copy;
  }
  /// This reader, placing errors at nodes with no position (mappings a
  /// reader merged itself) at `node`.
  YamlReader withFallback(const YAML::Node& node) const {
    YamlReader copy = *this;
    copy.fallback_ = node;
    return copy;
  }
  const std::filesystem::path& path() const { return path_; }

  /// Throws YamlError "<path>:<line>:<col>: <context><message>" at `node`
  /// (for a node of an override: "<path>: --set key=value: <context><message>").
  [[noreturn]] void fail(const YAML::Node& node, const std::string& message) const;
  /// fail's message, for a warning.
  std::string describe(const YAML::Node& node, const std::string& message) const;

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
  /// A size (m): a number > 0 and at most kMaxLengthM.
  double length(const YAML::Node& node, const std::string& what) const;
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
  std::vector<NodeOrigin> origins_;
  YAML::Node fallback_;
};

}  // namespace wtc::io::detail
