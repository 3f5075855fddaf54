#pragma once
// The ground: a static set of convex pieces, each with a material, and a
// spatial index that answers "which pieces can touch this box" (a wheel's
// bounding box). Immutable once built; build it with TerrainBuilder.
//
// Index: a static 4-wide bounding-volume hierarchy over the pieces' boxes,
// built once (median splits along the widest axis of the centroids), its
// child boxes in single precision rounded outward and tested four at a time;
// leaves end with an exact test on the double boxes (docs/terrain.md). Chosen over FCL's
// DynamicAABBTreeCollisionManager and Bullet's btDbvt by the benchmark bench/wheel_query_bench.cpp.
//
// Stored and formed pieces. A piece is stored (a ConvexPolyhedron kept in
// the terrain) or formed: a compact heightfield (addCompactHeightfield,
// wtc/heightfield.hpp) keeps its samples and forms a prism when asked,
// bit for bit the one addHeightfield would store. Ids run over both in the
// order they were added. piece(id, scratch) gives either; piece(id) only a
// stored one. A compact field is found by its own grid, not the hierarchy.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "wtc/aabb.hpp"
#include "wtc/convex_polyhedron.hpp"
#include "wtc/material.hpp"

namespace wtc {

using PieceId = std::int32_t;
using MaterialId = std::int32_t;

class Terrain;
struct Heightfield;
struct PieceRange;
namespace detail {
class CompactHeightfield;
}

class TerrainBuilder {
 public:
  /// Registers a material (validated); returns its id.
  MaterialId addMaterial(const Material& material);
  /// Adds a piece of the given material; returns its id (ids are dense,
  /// in insertion order, shared with compact fields' pieces). Throws if
  /// `material` is not a registered id.
  PieceId addPiece(ConvexPolyhedron piece, MaterialId material);
  /// Reserves room for `count` more pieces (large heightfields).
  void reserve(std::size_t count);
  /// Throws InvalidInputError naming `where` when `count` more pieces would
  /// pass PieceId's range or cannot fit in this machine's memory (counted
  /// at sizeof(ConvexPolyhedron) each, a lower bound): a terrain file
  /// asking for 10^10 tiles is refused before anything is allocated.
  void requireRoomFor(std::uint64_t count, const std::string& where) const;
  /// Throws InvalidInputError naming `where` unless `material` is a
  /// registered id.
  void requireMaterial(MaterialId material, const char* where) const;
  /// Pieces added so far, stored and formed: the next piece's id.
  std::size_t pieceCount() const { return next_id_; }
  MaterialId materialCount() const { return static_cast<MaterialId>(materials_.size()); }
  /// Builds the index. Throws InvalidInputError if there are no pieces.
  Terrain build() &&;

 private:
  friend class Terrain;
  friend PieceRange addCompactHeightfield(TerrainBuilder& builder, Heightfield field, MaterialId material);
  // A compact field's pieces: ids first ... first + count - 1.
  struct Field {
    PieceId first = 0;
    PieceId count = 0;
    PieceId formed_before = 0;  // formed ids of the fields before this one
    std::shared_ptr<const detail::CompactHeightfield> grid;
    MaterialId material = 0;
  };
  // Throws InvalidInputError naming `where` when `count` more ids would
  // pass PieceId's range (requireRoomFor's first check).
  void requireIdsFor(std::uint64_t count, const std::string& where) const;

  std::vector<ConvexPolyhedron> pieces_;
  std::vector<MaterialId> piece_material_;
  std::vector<Material> materials_;
  std::vector<Field> fields_;
  std::size_t next_id_ = 0;
};

class Terrain {
 public:
  /// Pieces, stored and formed (ids 0 ... pieceCount() - 1).
  std::size_t pieceCount() const { return piece_count_; }
  /// Stored piece `id`. Throws InvalidInputError for a formed one (use the
  /// overload with a scratch).
  const ConvexPolyhedron& piece(PieceId id) const { return fields_.empty() ? pieces_[id] : storedPiece(id); }
  /// Piece `id`: a stored piece itself, or a formed one made into `scratch`
  /// (which the result then refers to).
  const ConvexPolyhedron& piece(PieceId id, std::optional<ConvexPolyhedron>& scratch) const;
  /// True for a compact field's piece, formed when asked for.
  bool isFormed(PieceId id) const;
  /// The piece's bounding box, without forming it.
  Aabb pieceBounds(PieceId id) const;
  /// The stored pieces (all of them when the terrain has no compact field).
  std::span<const ConvexPolyhedron> pieces() const { return pieces_; }
  /// The id of pieces()[stored] (ids skip the compact fields' ranges).
  PieceId storedId(std::size_t stored) const;
  /// Where piece `id` lives: compact field `field` (>= 0), or pieces()[stored]
  /// (field = -1); storedId's inverse for a stored piece.
  struct Place {
    int field = -1;
    std::size_t stored = 0;
  };
  Place place(PieceId id) const;

  /// A compact heightfield of this terrain: its pieces' ids and its samples
  /// (an engine plugin gives it to the engine as one heightfield shape).
  struct CompactField {
    PieceId first = 0;  ///< Its pieces are first ... first + count - 1, in addHeightfield's order.
    PieceId count = 0;
    const Heightfield* field = nullptr;  ///< Lives as long as the terrain.
    MaterialId material = 0;             ///< Of every cell, unless the field has cell_materials.
  };
  std::size_t compactFieldCount() const { return fields_.size(); }
  CompactField compactField(std::size_t k) const;
  const Material& material(PieceId id) const { return materials_[materialId(id)]; }
  MaterialId materialId(PieceId id) const { return fields_.empty() ? piece_material_[id] : fieldAwareMaterialId(id); }
  std::span<const Material> materials() const { return materials_; }
  const Aabb& bounds() const { return bounds_; }

  /// Appends to `out` every piece whose bounding box overlaps `box`
  /// (allocation-free once `out` has capacity). Order unspecified.
  void overlapping(const Aabb& box, std::vector<PieceId>& out) const;

  /// Memory (bytes) of the pieces (stored pieces, and compact fields'
  /// samples) and of the index.
  std::size_t pieceMemoryBytes() const;
  std::size_t indexMemoryBytes() const;

 private:
  friend class TerrainBuilder;
  using Field = TerrainBuilder::Field;
  const ConvexPolyhedron& storedPiece(PieceId id) const;
  MaterialId fieldAwareMaterialId(PieceId id) const;
  // A 4-wide node: the boxes of its four children in single precision,
  // structure-of-arrays so one vector compare tests all four. child >= 0 is
  // an inner node; child < 0 is a leaf holding pieces order_[~child ..
  // ~child + count). Unused slots have empty boxes (min > max).
  using Float4 = float __attribute__((vector_size(16)));
  struct alignas(16) Node {
    Float4 min_x, min_y, min_z, max_x, max_y, max_z;
    std::int32_t child[4];
    std::int32_t count[4];
  };
  void buildIndex();

  std::vector<ConvexPolyhedron> pieces_;
  std::vector<MaterialId> piece_material_;
  std::vector<Material> materials_;
  std::vector<Field> fields_;
  std::size_t piece_count_ = 0;
  std::vector<Node> nodes_;       // over the stored pieces; empty when there are none
  std::vector<PieceId> order_;    // piece ids in tree order
  std::vector<Aabb> leaf_boxes_;  // piece boxes in tree (order_) order
  Aabb bounds_;
};

}  // namespace wtc
