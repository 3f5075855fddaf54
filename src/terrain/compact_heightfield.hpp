#pragma once
// A heightfield kept as its heights (internal to wtc::core): the prisms of
// addHeightfield (wtc/terrain/heightfield.hpp) are formed when asked for, not
// stored.
//
// A stored prism is a ConvexPolyhedron of about 1.2 kB plus its index
// entry; the field it comes from is 8 bytes a sample. Everything a query
// needs is computed from the samples the same way addHeightfield computes
// it, so piece(k) is bit for bit the prism addHeightfield adds as piece k,
// and pieceBounds(k) its bounds(). The index is the grid itself: the cells
// under a box come from the cell lines and each triangle's top from its
// corners, which decides exactly as Aabb::overlaps on the pieces' bounds
// (Terrain::overlapping's leaf test) would.
//
// Holes. Without holes piece k lies on cell k / 2. With holes the pieces
// skip the hole cells, and a running count of the cells that are ground,
// one per block of kBlockCells cells, maps a cell to its first piece (the
// count, then at most kBlockCells - 1 entries) and a piece to its cell (a
// binary search over the counts, then the block).
//
// Tiles. within() (a wheel's search) skips the cells of a tile of
// kTileCells x kTileCells cells at once when the tile's highest sample
// (kept in single precision, rounded up: 4 bytes a tile, 1/16 of a byte a
// cell) puts all of them beyond the reach. surfaceWithin() passes the
// cells of a tile on which the distance from the wheel centre can have no
// local minimum (SurfaceRun::passed), from the tile's lowest sample and
// steepest slope, its ring of neighbouring cells included, and the tops of
// the tiles around (TileFall: 8 bytes a tile more, 1/8 of a byte a cell).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "formed_pieces.hpp"
#include "wtc/terrain/heightfield.hpp"

namespace wtc::detail {

class CompactHeightfield final : public FormedPieces {
 public:
  /// Validates `field` (wtc::validate(const Heightfield&)) and keeps it.
  explicit CompactHeightfield(Heightfield field);

  /// Two per cell that is not a hole, as Heightfield::pieceCount().
  std::size_t pieceCount() const override { return piece_count_; }
  /// Piece k in addHeightfield's order (the cells row-major, holes skipped,
  /// triangle k % 2): makeTriangularPrism's corners.
  void prismCorners(std::size_t k, std::array<Eigen::Vector3d, 3>& top,
                    std::array<Eigen::Vector3d, 3>& bottom) const override;
  /// Appends first + k for every piece k whose bounds overlap `box` (as
  /// Aabb::overlaps decides), cell by cell in row-major order.
  void overlapping(const Aabb& box, PieceId first, std::vector<PieceId>& out) const override;
  /// The cells of the disc the ball spans, row by row, each cell's two boxes
  /// made from its lines and corners as pieceBounds() makes them.
  void within(const Eigen::Vector3d& point, double reach, PieceId first, std::vector<PieceId>& out) const override;
  /// within()'s cells as runs along rows, before each cell's own test: the
  /// rows of the disc, less the tiles beyond the reach, each row's run in a
  /// tile narrowed by the tile's highest sample.
  bool isSurface() const override { return true; }
  void surfaceWithin(const Eigen::Vector3d& point, double reach, PieceId first, int part,
                     std::vector<SurfaceRun>& runs) const override;
  /// The union of all pieces' bounds.
  const Aabb& bounds() const override { return bounds_; }
  /// The field's samples and description (bytes).
  std::size_t memoryBytes() const override;
  /// The cell's material (two pieces a cell), or `whole` without cell_materials.
  MaterialId materialId(std::size_t k, MaterialId whole) const override {
    return field_.cell_materials.empty() ? whole : field_.cell_materials[cellOf(k)];
  }
  const Heightfield* heightfield() const override { return &field_; }
  const Heightfield& field() const { return field_; }

 private:
  // Cells per running count of the ground cells (count).
  static constexpr std::size_t kBlockCells = 64;
  // Cells along a tile's side.
  static constexpr int kTileCells = 8;
  // The cells whose pieces' boxes may meet `box` (cellSpan along x and y);
  // false when none can (a box below the base, or with a NaN).
  bool cellsUnder(const Aabb& box, int& c0, int& c1, int& r0, int& r1) const;
  // The tops (m) of cell (r, c)'s two pieces, as their boxes have them.
  std::array<double, 2> pieceTops(int r, int c) const;
  void makeTiles();
  // within()'s walk: run(r, lo, hi, k, far, passed) for each run of cells
  // (r, lo ... hi) that may hold a piece within the reach, k the first
  // piece of its first ground cell, far = falls(tile_row, tile_col) of its
  // tile (m: its cells beyond that from the point's vertical pass; asked
  // once a tile). A tile wholly beyond it comes whole, passed = true, not
  // narrowed to the reach.
  template <typename Run, typename Falls>
  void walkRuns(const Eigen::Vector3d& point, double reach, Run&& run, Falls&& falls) const;
  // A tile's sides (m), as Heightfield::sample computes the lines.
  struct TileSides {
    double x0, x1, y0, y1;
  };
  TileSides tileSides(int tile_row, int tile_col) const {
    const Heightfield& f = field_;
    const int c0 = tile_col * kTileCells, c1 = std::min(c0 + kTileCells, f.cols - 1);
    const int r0 = tile_row * kTileCells, r1 = std::min(r0 + kTileCells, f.rows - 1);
    return {f.origin.x() + c0 * f.spacing_x, f.origin.x() + c1 * f.spacing_x, f.origin.y() + r0 * f.spacing_y,
            f.origin.y() + r1 * f.spacing_y};
  }
  // True when no piece of tile (tile_row, tile_col) has a box within
  // `reach2` (m^2, the reach squared) of `point`.
  bool tileBeyond(int tile_row, int tile_col, const Eigen::Vector3d& point, double reach2) const;
  // A tile's samples, its cells' neighbours' included: the lowest (m,
  // above the field's origin, rounded down) and a bound on the slope
  // |grad h| of every triangle among them (rounded up), or an infinite
  // slope when a cell of the tile has a hole or the field's edge for a
  // neighbour (its walls may be ground). Their highest is at most the
  // highest of the 3 x 3 tiles' tops around.
  struct TileFall {
    float low = 0.0f, slope = 0.0f;
  };
  void makeTileFalls();
  // The distance (m) from `point`'s vertical beyond which the cells of
  // tile (tile_row, tile_col) pass (kFallMargin, field_cells.hpp); infinite
  // where none can. A lower bound of it once its square is `enough2` (m^2).
  double fallingFrom(const Eigen::Vector3d& point, int tile_row, int tile_col, double enough2) const;
  // surfaceWithin()'s run (r, lo ... hi) of first piece `id`, within one
  // tile whose cells pass beyond `far` (m, fallingFrom(), finite), split
  // into the cells it passes and those it searches.
  void splitRun(const Eigen::Vector3d& point, double far, int r, int lo, int hi, PieceId id, int part,
                std::vector<SurfaceRun>& runs) const;
  // The tile's highest sample (m, world), rounded up.
  double tileTop(int tile_row, int tile_col) const {
    return field_.origin.z() +
           static_cast<double>(tile_top_[static_cast<std::size_t>(tile_row) * tile_cols_ + tile_col]);
  }

  // The cell (row-major index) piece k lies on.
  std::size_t cellOf(std::size_t k) const;
  // The pieces of the cells before `cell` (row-major index): the first
  // piece of `cell` unless it is a hole.
  std::size_t piecesBefore(std::size_t cell) const;

  Heightfield field_;
  std::size_t piece_count_ = 0;
  // With holes: ground_before_[b] = cells that are not holes among cells
  // 0 ... b kBlockCells - 1. Empty without holes.
  std::vector<std::uint32_t> ground_before_;
  // The highest sample of each tile (row-major over the tiles, each tile's
  // samples on its four sides included), float rounded up (m, above the
  // field's origin).
  std::vector<float> tile_top_;
  std::vector<TileFall> tile_fall_;  // row-major over the tiles, as tile_top_
  int tile_cols_ = 0;
  double base_z_ = 0.0;
  Aabb bounds_;
};

}  // namespace wtc::detail
