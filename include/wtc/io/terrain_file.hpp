#pragma once
// Terrain description files (YAML): materials by name and the pieces that
// use them, placed in the world. terrains/README.md has the full reference
// and terrains/*.yaml are worked examples. In short:
//
//   description: free text (optional)
//   materials:                      # name -> parameters, defaults from wtc::Material
//     asphalt_concrete: {mu_max: 0.8, s1: 0.1, s2: 0.0, rolling_resistance: 0.018}
//   pieces:
//     - type: ledge                 # box | slab | incline | ledge | stairs |
//       material: asphalt_concrete  #   heightfield | mesh | hull
//       height: 0.65                # the fields of the builder's Params (m, rad)
//       translation: [0, 0, 0]      # optional placement (m)
//       rotation: {axis: [0, 0, 1], degrees: 90}   # optional (or radians:)
//   soil_regions:                   # optional: where soft ground remembers
//     - {corners: [x0, y0, x1, y1], spacing: 0.02, memory_cap_mb: 2048,
//        flow_factor: 0, repose_angle_deg: 30}    # bulldozing: off by default
//
// `material` may be left out when the file defines exactly one material.
// Paths (a heightfield's or a mesh's `file`) are relative to the YAML
// file's directory. Unknown keys are errors (a typo must not silently fall
// back to a default).
//
// Errors: InvalidInputError whose message starts with
// "<file.yaml>:<line>:<column>:" (1-based) at the offending node, e.g.
// "ledge.yaml:12:13: pieces[0] (ledge): height: 'tall' is not a number";
// a builder's complaint is reported at its piece, and errors in a
// referenced CSV/PGM/mesh file carry that file's own position after it.
// A key given twice in a mapping is an error; a mesh whose triangles all
// have zero area is an error, one with some gets a warning
// (TerrainFileReport::warnings).
#include <filesystem>
#include <string>
#include <vector>

#include "wtc/terrain/terrain.hpp"
#include "wtc/terrain/terrain_primitives.hpp"

namespace wtc::io {

/// What a terrain file added.
struct TerrainFileReport {
  int materials = 0;                              ///< Materials registered.
  PieceRange pieces;                              ///< Pieces added (all of them, in file order).
  std::int64_t degenerate_triangles_skipped = 0;  ///< From mesh pieces.
  /// What the user should hear of, one line each, placed like errors:
  /// "t.yaml:5:5: pieces[0] (mesh): rock.obj: 3 of 12 triangles are
  /// degenerate (zero area), skipped". wtc-sim adds them to the run's
  /// warnings (summary.json, stderr).
  std::vector<std::string> warnings;
};

/// Adds the file's materials and pieces to `builder`.
TerrainFileReport addTerrainFile(TerrainBuilder& builder, const std::filesystem::path& path);

/// Reads the file and builds the terrain.
Terrain loadTerrain(const std::filesystem::path& path);

}  // namespace wtc::io
