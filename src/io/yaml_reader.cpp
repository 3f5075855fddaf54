#include "yaml_reader.hpp"

#include <cmath>
#include <numbers>
#include <unordered_map>
#include <unordered_set>

#include "file_support.hpp"
#include "wtc/base/constants.hpp"

namespace wtc::io::detail {

YAML::Node loadYamlFile(const std::filesystem::path& path) {
  const std::string text = readDescriptionFile(path);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw InvalidInputError(where(path, e.mark.line + 1, e.mark.column + 1) + "YAML syntax error: " + e.msg);
  }
  if (const auto duplicate = findDuplicateKey(root)) {
    throw YamlError(where(path, duplicate->second.line + 1, duplicate->second.column + 1) +
                    duplicateKeyMessage(*duplicate));
  }
  return root;
}

std::optional<DuplicateKey> findDuplicateKey(const YAML::Node& root) {
  // Depth first with a stack (no recursion to overflow on deep nesting).
  // An alias is the node it names, mark and all: a container whose start
  // was seen is not walked again, so "a billion laughs" stays linear.
  std::vector<YAML::Node> stack{root};
  std::unordered_set<int> seen;  // mark.pos of the containers walked
  while (!stack.empty()) {
    const YAML::Node node = stack.back();
    stack.pop_back();
    if (!node.IsMap() && !node.IsSequence()) continue;
    if (node.Mark().pos >= 0 && !seen.insert(node.Mark().pos).second) continue;
    std::vector<YAML::Node> children;
    if (node.IsSequence()) {
      for (const auto& item : node) children.push_back(item);
    } else {
      std::unordered_map<std::string, YAML::Mark> keys;
      for (const auto& entry : node) {
        if (entry.first.IsScalar()) {
          const auto [first, added] = keys.try_emplace(entry.first.Scalar(), entry.first.Mark());
          if (!added) return DuplicateKey{entry.first.Scalar(), first->second, entry.first.Mark()};
        }
        children.push_back(entry.second);
      }
    }
    // Reversed, so that the first child is walked first (document order).
    stack.insert(stack.end(), children.rbegin(), children.rend());
  }
  return std::nullopt;
}

std::string duplicateKeyMessage(const DuplicateKey& duplicate) {
  return "duplicate key '" + duplicate.key + "' (first at line " + std::to_string(duplicate.first.line + 1) +
         "): a key may appear once in a mapping";
}

namespace {

// Whether `node` is `subtree` or one of the nodes below it.
bool contains(const YAML::Node& subtree, const YAML::Node& node) {
  try {
    std::vector<YAML::Node> stack{subtree};
    while (!stack.empty()) {
      const YAML::Node n = stack.back();
      stack.pop_back();
      if (n.is(node)) return true;
      if (n.IsSequence()) {
        for (const auto& item : n) stack.push_back(item);
      } else if (n.IsMap()) {
        for (const auto& entry : n) {
          stack.push_back(entry.first);
          stack.push_back(entry.second);
        }
      }
    }
  } catch (const YAML::Exception&) {
    // An invalid node (a missing key of a const map) is in no subtree.
  }
  return false;
}

}  // namespace

std::string YamlReader::describe(const YAML::Node& node, const std::string& message) const {
  std::string note;
  for (const NodeOrigin& origin : origins_) {
    if (!contains(origin.subtree, node)) continue;
    if (origin.replaces_position) return path_.string() + ": " + origin.label + ": " + context_ + message;
    note += " (" + origin.label + ")";
  }
  YAML::Mark mark;
  try {
    mark = node.Mark();
  } catch (const YAML::Exception&) {
    mark = YAML::Mark::null_mark();
  }
  // A node the reader merged itself has no mark: its fallback's.
  if (mark.line < 0 && fallback_.IsDefined()) mark = fallback_.Mark();
  std::string where = path_.string() + ":";
  // yaml-cpp marks are 0-based; a node made up by the reader has none.
  if (mark.line >= 0) where += std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1) + ":";
  return where + " " + context_ + message + note;
}

void YamlReader::fail(const YAML::Node& node, const std::string& message) const {
  throw YamlError(describe(node, message));
}

void YamlReader::requireMap(const YAML::Node& map, const char* what) const {
  if (!map.IsMap()) fail(map, std::string(what) + " must be a mapping (key: value lines)");
}

void YamlReader::checkKeys(const YAML::Node& map, std::initializer_list<const char*> allowed,
                           std::initializer_list<const char*> also) const {
  for (const auto& entry : map) {
    const std::string key = entry.first.Scalar();
    bool known = false;
    for (const auto& list : {allowed, also}) {
      for (const char* a : list) known = known || key == a;
    }
    if (!known) {
      std::string list;
      for (const auto& keys : {allowed, also}) {
        for (const char* a : keys) list += (list.empty() ? "" : ", ") + std::string(a);
      }
      fail(entry.first, "unknown key '" + key + "' (allowed: " + list + ")");
    }
  }
}

std::optional<YAML::Node> YamlReader::get(const YAML::Node& map, const char* key) {
  const YAML::Node node = map[key];
  if (!node.IsDefined() || node.IsNull()) return std::nullopt;
  return node;
}

YAML::Node YamlReader::require(const YAML::Node& map, const char* key) const {
  const auto node = get(map, key);
  if (!node) fail(map, std::string("missing key '") + key + "'");
  return *node;
}

double YamlReader::number(const YAML::Node& node, const std::string& what) const {
  if (!node.IsScalar()) fail(node, what + ": expected a number");
  double value = 0.0;
  try {
    value = node.as<double>();
  } catch (const YAML::Exception&) {
    fail(node, what + ": '" + node.Scalar() + "' is not a number");
  }
  if (!std::isfinite(value)) fail(node, what + ": '" + node.Scalar() + "' is not a finite number");
  return value;
}

double YamlReader::length(const YAML::Node& node, const std::string& what) const {
  const double value = number(node, what);
  if (!(value > 0.0)) fail(node, what + ": " + formatNumber(value) + " must be > 0 (m)");
  if (value > kMaxLengthM) {
    fail(node, what + ": " + formatNumber(value) + " m is beyond the largest length a description may give, " +
                   formatNumber(kMaxLengthM) + " m (wtc::kMaxLengthM)");
  }
  return value;
}

long long YamlReader::integer(const YAML::Node& node, const std::string& what) const {
  if (!node.IsScalar()) fail(node, what + ": expected an integer");
  try {
    return node.as<long long>();
  } catch (const YAML::Exception&) {
    fail(node, what + ": '" + node.Scalar() + "' is not an integer");
  }
}

bool YamlReader::boolean(const YAML::Node& node, const std::string& what) const {
  if (!node.IsScalar()) fail(node, what + ": expected true or false");
  try {
    return node.as<bool>();
  } catch (const YAML::Exception&) {
    fail(node, what + ": '" + node.Scalar() + "' is not true or false");
  }
}

std::string YamlReader::string(const YAML::Node& node, const std::string& what) const {
  if (!node.IsScalar()) fail(node, what + ": expected a string");
  return node.Scalar();
}

double YamlReader::number(const YAML::Node& map, const char* key, double fallback) const {
  const auto node = get(map, key);
  return node ? number(*node, key) : fallback;
}

long long YamlReader::integer(const YAML::Node& map, const char* key, long long fallback) const {
  const auto node = get(map, key);
  return node ? integer(*node, key) : fallback;
}

bool YamlReader::boolean(const YAML::Node& map, const char* key, bool fallback) const {
  const auto node = get(map, key);
  return node ? boolean(*node, key) : fallback;
}

Eigen::Matrix3d YamlReader::rotation(const YAML::Node& node) const {
  if (node.IsSequence()) {
    // Listed in the order they apply: R = R_n ... R_2 R_1.
    Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
    for (const auto& step : node) r = rotation(step) * r;
    return r;
  }
  if (!node.IsMap()) fail(node, "rotation: expected {axis: [x, y, z], degrees: angle} or a list of such");
  checkKeys(node, {"axis", "degrees", "radians"});
  const YAML::Node axis_node = require(node, "axis");
  const Eigen::Vector3d axis = vector<3>(axis_node, "rotation axis");
  if (!(axis.norm() > 0.0)) fail(axis_node, "rotation axis " + formatVector(axis) + " has zero length");
  const auto degrees = get(node, "degrees");
  const auto radians = get(node, "radians");
  if (degrees.has_value() == radians.has_value()) fail(node, "rotation: give exactly one of 'degrees' and 'radians'");
  const double angle = degrees ? number(*degrees, "degrees") * std::numbers::pi / 180.0 : number(*radians, "radians");
  if (!std::isfinite(angle)) fail(degrees ? *degrees : *radians, "rotation angle is not finite");
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

Eigen::Isometry3d YamlReader::pose(const YAML::Node& map) const {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  if (const auto t = get(map, "translation")) {
    pose.translation() = vector<3>(*t, "translation");
    if (!pose.translation().allFinite()) fail(*t, "translation is not finite");
  }
  if (const auto r = get(map, "rotation")) pose.linear() = rotation(*r);
  return pose;
}

}  // namespace wtc::io::detail
