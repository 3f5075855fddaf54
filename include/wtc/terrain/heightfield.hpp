#pragma once
// Heightfield ground: a regular grid of surface heights, each cell split into
// two triangles and each triangle extruded straight down to one flat base, so
// the union of the pieces is a solid block whose top is the triangulated
// surface.
//
// Grid and frames. Sample (r, c) (row r, column c) sits at world point
//   p_W(r, c) = origin + (c spacing_x, r spacing_y, heights[r cols + c]):
// columns run along +x, rows along +y, heights are added to origin.z().
//
// Cell diagonal. Cell (r, c) has corners p00 = p(r, c), p01 = p(r, c+1),
// p10 = p(r+1, c), p11 = p(r+1, c+1); every cell is split along the same
// diagonal p00-p11 into the triangles (p00, p01, p11) and (p00, p11, p10),
// counter-clockwise seen from above. One fixed diagonal keeps the surface a
// pure function of the data (no data-dependent flips that would change under
// a tiny height edit) and makes piece ids computable: see cellPiece().
//
// Base. base_depth is measured below the lowest height of the whole field:
// base_z = origin.z() + min(heights) - base_depth. One flat base for all
// cells makes the pieces' side walls exactly shared and the union a closed
// solid with a flat bottom; every prism has volume because base_depth > 0.
// The price is tall pieces where the relief is large, which only the depth
// of their bounding boxes sees (the wheel queries approach from above).
//
// Prisms. Each triangle becomes a ConvexPolyhedron of 6 vertices and 5
// faces (top triangle, bottom triangle, three vertical quads), built with
// the trusted fromMesh path: with vertical sides and a base below every
// vertex the prism is convex and outward-oriented for any heights.
//
// Holes. A cell marked in cell_holes has no ground: no pieces, no surface.
// The pieces of the other cells keep their order and are numbered without
// gaps, so a hole shifts the ids of every piece after it (cellPiece). The
// walls of the cells around a hole are real edges to a wheel (the seam rule
// covers an edge only where another piece does).
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "wtc/terrain/terrain.hpp"
#include "wtc/terrain/triangle_mesh.hpp"

namespace wtc {

struct Heightfield {
  int rows = 0;                                     ///< Samples along y (count, >= 2).
  int cols = 0;                                     ///< Samples along x (count, >= 2).
  double spacing_x = 1.0;                           ///< Distance between columns (m, > 0).
  double spacing_y = 1.0;                           ///< Distance between rows (m, > 0).
  Eigen::Vector3d origin{Eigen::Vector3d::Zero()};  ///< World position of sample (0, 0) at height 0 (m).
  std::vector<double> heights;                      ///< rows x cols, row-major: heights[r cols + c] (m).
  double base_depth = 1.0;                          ///< Depth of the flat base below the lowest height (m, > 0).
  /// Per-cell materials, (rows - 1) x (cols - 1) row-major: cell (r, c)'s
  /// two pieces take cell_materials[r (cols - 1) + c]. Empty: every cell
  /// takes the material given to addHeightfield.
  std::vector<MaterialId> cell_materials;
  /// Holes, (rows - 1) x (cols - 1) row-major like cell_materials: cell
  /// (r, c) has no ground where cell_holes[r (cols - 1) + c] != 0. Empty:
  /// no holes.
  std::vector<std::uint8_t> cell_holes;

  /// Height of sample (r, c) (m, relative to origin.z()).
  double height(int r, int c) const { return heights[static_cast<std::size_t>(r) * cols + c]; }
  /// World position of sample (r, c) (m).
  Eigen::Vector3d sample(int r, int c) const {
    return origin + Eigen::Vector3d(c * spacing_x, r * spacing_y, height(r, c));
  }
  /// Number of cells: (rows - 1)(cols - 1), holes included.
  std::size_t cellCount() const {
    return rows < 2 || cols < 2 ? 0 : static_cast<std::size_t>(rows - 1) * static_cast<std::size_t>(cols - 1);
  }
  /// Whether cell (r, c) is a hole.
  bool isHole(int r, int c) const {
    return !cell_holes.empty() && cell_holes[static_cast<std::size_t>(r) * (cols - 1) + c] != 0;
  }
  /// Whether any cell is a hole (a pass over cell_holes).
  bool hasHoles() const;
  /// Number of pieces addHeightfield makes: two per cell that is not a
  /// hole (a pass over cell_holes).
  std::size_t pieceCount() const;
  /// World z of the flat base (m).
  double baseZ() const;
};

/// Throws InvalidInputError if the grid is malformed: rows or cols < 2, a
/// spacing or base_depth not finite and > 0, a non-finite origin, a heights
/// array of the wrong size, or a non-finite height (named by row and
/// column), a cell_materials or cell_holes array neither empty nor of
/// (rows - 1) x (cols - 1) entries, holes in every cell, or more pieces
/// than a PieceId can number. (Whether the
/// ids are registered is the builder's to check.)
void validate(const Heightfield& field);

/// Adds the field's prisms, two per cell that is not a hole (validated
/// first). Piece order: cell by cell, row-major, holes skipped, the
/// triangle (p00, p01, p11) first. Each
/// cell's material: its cell_materials entry, or `material` if there are
/// none; every id must be registered in `builder`.
PieceRange addHeightfield(TerrainBuilder& builder, const Heightfield& field, MaterialId material);

/// Adds the same pieces as addHeightfield, with the same ids and bit for
/// bit the same prisms, but keeps only the field's samples (8 bytes each,
/// against about 2.6 kB per cell for stored prisms and their index) and
/// forms a prism when a query needs it (Terrain::piece(id, scratch)). The
/// terrain finds its pieces from the grid. Validates the field first.
/// Per-cell materials cost 4 more bytes a cell, holes 1 byte and a
/// running count (4 bytes per 64 cells) that numbers the pieces.
PieceRange addCompactHeightfield(TerrainBuilder& builder, Heightfield field, MaterialId material);

/// The id of triangle `k` (0: (p00, p01, p11), 1: (p00, p11, p10)) of cell
/// (r, c) in the range addHeightfield returned; nullopt if the cell is a
/// hole. O(1) without holes; with holes it counts the holes before the
/// cell (O(r cols)).
std::optional<PieceId> cellPiece(const PieceRange& range, const Heightfield& field, int r, int c, int k);

/// The id of the triangle whose projection on the x-y plane holds (x, y),
/// with (x, y) first clamped onto the grid (a contact point a hair outside
/// the field's edge belongs to the edge's triangle; a non-finite coordinate
/// counts as the grid's low end); nullopt over a hole. The field's pieces
/// start at range.first. Cost as cellPiece.
std::optional<PieceId> pieceUnder(const PieceRange& range, const Heightfield& field, double x, double y);

/// The field's surface as a triangle mesh: its samples (sample(r, c) is
/// vertex r cols + c) and the two triangles of each cell that is not a hole,
/// in addHeightfield's piece order, so that triangle k lies on top of the
/// field's piece k (pieceUnder names both). For an engine or a file that
/// wants triangles.
TriangleMesh surfaceMesh(const Heightfield& field);

/// Samples that measured nothing (a DEM's no-data, a NaN height): every
/// cell with a missing corner becomes a hole (joined with the field's own
/// cell_holes), and each missing sample takes the lowest height of the
/// others, so that it moves neither the base nor any bound. `missing` has
/// one entry per sample (rows x cols, as heights), nonzero where missing.
/// Leaves the field alone when nothing is missing; throws
/// InvalidInputError if no sample or no cell is left.
void holesAtMissingSamples(Heightfield& field, const std::vector<std::uint8_t>& missing);

/// World z of the triangulated surface above (x, y) (m), or nullopt outside
/// the grid or over a hole. The same triangles as the pieces.
std::optional<double> surfaceHeight(const Heightfield& field, double x, double y);

/// The prism under the triangle (a, b, c), counter-clockwise seen from above,
/// reaching down to the plane z = base_z (m). Precondition: the triangle is
/// not vertical and base_z is below all three vertices. Throws
/// InvalidInputError (from fromMesh) if the result is degenerate.
ConvexPolyhedron makeTriangularPrism(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                     double base_z);

}  // namespace wtc
