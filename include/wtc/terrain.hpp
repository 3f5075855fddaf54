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
#include <cstdint>
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

class TerrainBuilder {
 public:
  /// Registers a material (validated); returns its id.
  MaterialId addMaterial(const Material& material);
  /// Adds a piece of the given material; returns its id (ids are dense,
  /// in insertion order). Throws if `material` is not a registered id.
  PieceId addPiece(ConvexPolyhedron piece, MaterialId material);
  /// Reserves room for `count` more pieces (large heightfields).
  void reserve(std::size_t count);
  /// Throws InvalidInputError naming `where` when `count` more pieces would
  /// pass PieceId's range or cannot fit in this machine's memory (counted
  /// at sizeof(ConvexPolyhedron) each, a lower bound): a terrain file
  /// asking for 10^10 tiles is refused before anything is allocated.
  void requireRoomFor(std::uint64_t count, const std::string& where) const;
  std::size_t pieceCount() const { return pieces_.size(); }
  MaterialId materialCount() const { return static_cast<MaterialId>(materials_.size()); }
  /// Builds the index. Throws InvalidInputError if there are no pieces.
  Terrain build() &&;

 private:
  std::vector<ConvexPolyhedron> pieces_;
  std::vector<MaterialId> piece_material_;
  std::vector<Material> materials_;
};

class Terrain {
 public:
  std::size_t pieceCount() const { return pieces_.size(); }
  const ConvexPolyhedron& piece(PieceId id) const { return pieces_[id]; }
  std::span<const ConvexPolyhedron> pieces() const { return pieces_; }
  const Material& material(PieceId id) const { return materials_[piece_material_[id]]; }
  MaterialId materialId(PieceId id) const { return piece_material_[id]; }
  std::span<const Material> materials() const { return materials_; }
  const Aabb& bounds() const { return bounds_; }

  /// Appends to `out` every piece whose bounding box overlaps `box`
  /// (allocation-free once `out` has capacity). Order unspecified.
  void overlapping(const Aabb& box, std::vector<PieceId>& out) const;

  /// Memory (bytes) of the pieces and of the index.
  std::size_t pieceMemoryBytes() const;
  std::size_t indexMemoryBytes() const;

 private:
  friend class TerrainBuilder;
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
  std::vector<Node> nodes_;
  std::vector<PieceId> order_;
  std::vector<Aabb> leaf_boxes_;  // piece boxes in tree (order_) order
  Aabb bounds_;
};

}  // namespace wtc
