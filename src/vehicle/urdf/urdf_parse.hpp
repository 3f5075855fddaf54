#pragma once
// urdfdom's parse of a URDF text, with what urdfdom only logs turned into
// errors, and the order of the <link> elements (urdfdom keeps its links in
// a std::map, in name order). Private to the URDF reader.
#include <filesystem>
#include <string>
#include <vector>

#include <urdf_model/model.h>
#include <urdf_world/types.h>

namespace wtc::vehicle::detail {

struct ParsedUrdf {
  urdf::ModelInterfaceSharedPtr model;
  std::vector<std::string> link_order;  ///< The <link> elements' names, in the file's order.
};

/// Reads and parses `file`. Throws InvalidInputError "<file>: <urdfdom's
/// messages>" when urdfdom refuses it or logs an error while parsing (an
/// <inertial> without <mass> comes back as a model with mass 0).
ParsedUrdf parseUrdfFile(const std::filesystem::path& file);

}  // namespace wtc::vehicle::detail
