#pragma once
// A soil as YAML names it (internal to wtc::io; terrain files' materials,
// wtc-mobility's ground): `soil: toyoura_sand`, a shipped soil, or a map of
// its fields, `base: <a shipped soil>` first when it changes only some.
#include "wtc/terrain/soil.hpp"
#include "yaml_reader.hpp"

namespace wtc::io::detail {

/// The soil at `node`, validated. Throws InvalidInputError at the node's
/// line for an unknown soil (naming the shipped ones), an unknown key or a
/// value out of range.
Soil readSoil(const YamlReader& in, const YAML::Node& node);

}  // namespace wtc::io::detail
