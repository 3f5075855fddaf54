#pragma once
// A material as YAML gives it (internal to wtc::io; terrain files'
// `materials`, wtc-mobility's `ground`): the slip law's mu_max, s1 and s2
// (or mu_peak, the static coefficient, instead of s2), the rolling
// resistance and a soil.
#include <string>

#include "wtc/terrain/material.hpp"
#include "yaml_reader.hpp"

namespace wtc::io::detail {

/// The material `name` at `node` (a map), fields absent taking Material's
/// defaults. Throws InvalidInputError at the node's line for an unknown key,
/// s2 given with mu_peak, a mu_peak not above mu_max or a bad soil; the
/// caller validates the whole (wtc::validate, or TerrainBuilder::addMaterial).
Material readMaterial(const YamlReader& in, const YAML::Node& node, const std::string& name);

}  // namespace wtc::io::detail
