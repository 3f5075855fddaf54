#pragma once
// A heightfield kept as its heights (internal to wtc::core): the prisms of
// addHeightfield (wtc/heightfield.hpp) are formed when asked for, not
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
#include <cstddef>
#include <vector>

#include "formed_pieces.hpp"
#include "wtc/heightfield.hpp"

namespace wtc::detail {

class CompactHeightfield final : public FormedPieces {
 public:
  /// Validates `field` (wtc::validate(const Heightfield&)) and keeps it.
  explicit CompactHeightfield(Heightfield field);

  /// 2 (rows - 1)(cols - 1), as Heightfield::pieceCount().
  std::size_t pieceCount() const override { return field_.pieceCount(); }
  /// Piece k in addHeightfield's order (cell k / 2 row-major, triangle k % 2),
  /// bit for bit the prism addHeightfield builds.
  ConvexPolyhedron piece(std::size_t k) const override;
  /// piece(k).bounds(), without forming the piece.
  Aabb pieceBounds(std::size_t k) const override;
  /// Appends first + k for every piece k whose bounds overlap `box` (as
  /// Aabb::overlaps decides), cell by cell in row-major order.
  void overlapping(const Aabb& box, PieceId first, std::vector<PieceId>& out) const override;
  /// The union of all pieces' bounds.
  const Aabb& bounds() const override { return bounds_; }
  /// The field's samples and description (bytes).
  std::size_t memoryBytes() const override;
  /// The cell's material (two pieces a cell), or `whole` without cell_materials.
  MaterialId materialId(std::size_t k, MaterialId whole) const override {
    return field_.cell_materials.empty() ? whole : field_.cell_materials[k / 2];
  }
  const Heightfield* heightfield() const override { return &field_; }
  const Heightfield& field() const { return field_; }

 private:
  // The three corners of piece k (addHeightfield's triangle order).
  void corners(std::size_t k, Eigen::Vector3d p[3]) const;

  Heightfield field_;
  double base_z_ = 0.0;
  Aabb bounds_;
};

}  // namespace wtc::detail
