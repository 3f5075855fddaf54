#pragma once
// A seeded heightfield for the terrain tests: heights uniform in
// [-amplitude, amplitude] from the raw mt19937 stream (fully specified by
// the standard, unlike its distributions), on the grid given. And the
// engine plugins' compact-field scene: such a field with a flat patch, next
// to a stored ledge.
#include <algorithm>
#include <cstdint>
#include <ostream>
#include <random>

#include <Eigen/Core>

#include "wtc/geometry/convex_polyhedron.hpp"
#include "wtc/terrain/heightfield.hpp"
#include "wtc/terrain/terrain.hpp"
#include "wtc/terrain/terrain_primitives.hpp"
#include "wtc/terrain/triangle_mesh.hpp"

namespace wtc::testing {

struct RandomGrid {
  double spacing_x = 0.5, spacing_y = 0.75;  // (m)
  Eigen::Vector3d origin{-3.0, 2.0, 10.0};   // (m)
  double base_depth = 0.4;                   // (m)
};

inline Heightfield randomHeightfield(int rows, int cols, double amplitude, std::uint32_t seed,
                                     const RandomGrid& grid = {}) {
  std::mt19937 gen(seed);
  Heightfield f;
  f.rows = rows;
  f.cols = cols;
  f.spacing_x = grid.spacing_x;
  f.spacing_y = grid.spacing_y;
  f.origin = grid.origin;
  f.base_depth = grid.base_depth;
  for (int i = 0; i < rows * cols; ++i) f.heights.push_back(amplitude * (2.0 * (gen() / 4294967296.0) - 1.0));
  return f;
}

/// The plugins' compact-field scene: a 16 x 20 random field (heights
/// within +-amplitude, the RandomGrid: x in [-3, 6.5], y in [2, 13.25], z about 10 m)
/// whose cells x in [1, 3], y in [6.5, 9.5] are flat at kPatchHeightM, and
/// the spec's ledge (stored) beside it. `compact`: the field by
/// addCompactHeightfield, else addHeightfield (the same pieces and ids).
/// `part`: the field; the field's surface as a triangle mesh (surfaceMesh,
/// extruded base_depth; compact or not by MeshExtrusionOptions::compact);
/// or the field with holes in seven cells, none near the patch or on the
/// line y = 5 m (the plugins' wheel tests roll along it).
enum class CompactPart { kField, kMesh, kFieldWithHoles };

/// Its name, for test names and messages.
inline const char* nameOf(CompactPart part) {
  return part == CompactPart::kField ? "Field" : part == CompactPart::kMesh ? "Mesh" : "FieldWithHoles";
}
inline void PrintTo(CompactPart part, std::ostream* out) { *out << nameOf(part); }

struct PluginFieldScene {
  static constexpr double kPatchHeightM = 0.25;  // above the field's origin (m)
  Heightfield field;
  PieceRange range;
  Terrain terrain;
};

inline PluginFieldScene pluginFieldScene(bool compact, double amplitude = 0.15,
                                         CompactPart part = CompactPart::kField) {
  Heightfield field = randomHeightfield(16, 20, amplitude, 20261124);
  for (int r = 6; r <= 10; ++r) {
    for (int c = 8; c <= 12; ++c) field.heights[r * field.cols + c] = PluginFieldScene::kPatchHeightM;
  }
  if (part == CompactPart::kFieldWithHoles) {
    field.cell_holes.assign(field.cellCount(), 0);
    for (const int cell : {12 * 19 + 2, 12 * 19 + 3, 13 * 19 + 2, 13 * 19 + 3, 13 * 19 + 4, 1 * 19 + 15, 18}) {
      field.cell_holes[cell] = 1;
    }
  }
  TerrainBuilder builder;
  const MaterialId material = builder.addMaterial({});
  addLedge(builder, {}, material);
  const PieceRange range =
      part == CompactPart::kMesh
          ? addTriangleMesh(builder, surfaceMesh(field), material, {.thickness = field.base_depth, .compact = compact})
                .pieces
      : compact ? addCompactHeightfield(builder, field, material)
                : addHeightfield(builder, field, material);
  return {field, range, std::move(builder).build()};
}

/// A uniform point of the field's x-y rectangle, `inset` (m) inside its
/// edges, from the raw mt19937 stream.
inline Eigen::Vector2d randomPointOn(const Heightfield& f, std::mt19937& gen, double inset) {
  const auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * (gen() / 4294967296.0); };
  return {uniform(f.origin.x() + inset, f.origin.x() + (f.cols - 1) * f.spacing_x - inset),
          uniform(f.origin.y() + inset, f.origin.y() + (f.rows - 1) * f.spacing_y - inset)};
}

/// How far `point` lies outside `piece` (m; <= 0 inside): the largest
/// signed distance to a face plane.
inline double outside(const ConvexPolyhedron& piece, const Eigen::Vector3d& point) {
  double worst = -1e300;
  for (int f = 0; f < piece.faceCount(); ++f)
    worst = std::max(worst, piece.faceNormal(f).dot(point) - piece.faceOffset(f));
  return worst;
}

}  // namespace wtc::testing
