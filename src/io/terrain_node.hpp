#pragma once
// A terrain description as a YAML node (internal to wtc::io): the body of a
// terrain file, or a scene's inline `terrain:`. Paths in it are relative to
// the directory of the file `in` reads.
#include "wtc/io/terrain_file.hpp"
#include "yaml_reader.hpp"

namespace wtc::io::detail {

TerrainFileReport addTerrainNode(TerrainBuilder& builder, const YamlReader& in, const YAML::Node& root);

}  // namespace wtc::io::detail
