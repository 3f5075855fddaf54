#pragma once
// The ground: a static set of convex pieces, each with a material, and a
// spatial index that answers "which pieces can touch this box" (a wheel's
// bounding box). Immutable once built; build it with TerrainBuilder.
//
// Index: a static 8-wide bounding-volume hierarchy over the pieces' boxes,
// tested four at a time in single precision, with an exact test on the
// double boxes at the leaves (docs/terrain.md). Chosen over FCL's
// DynamicAABBTreeCollisionManager and Bullet's btDbvt by the benchmark
// bench/wheel_query_bench.cpp.
//
// Stored and formed pieces. A piece is stored (a ConvexPolyhedron kept in
// the terrain) or formed: a compact heightfield (addCompactHeightfield,
// wtc/terrain/heightfield.hpp) keeps its samples, a compact triangle mesh
// (MeshExtrusionOptions::compact, wtc/terrain/triangle_mesh.hpp) its vertices and
// triangles, and each forms a prism when asked, bit for bit the one
// addHeightfield or addTriangleMesh would store. Ids run over all pieces in
// the order they were added. piece(id, scratch) gives either; piece(id)
// only a stored one. A compact part is found by its own index (the grid, or
// the mesh's hierarchy), not the stored pieces'.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "wtc/geometry/aabb.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"
#include "wtc/terrain/material.hpp"
#include "wtc/terrain/soil_region.hpp"

namespace wtc {

using PieceId = std::int32_t;
using MaterialId = std::int32_t;

class Terrain;
struct Heightfield;
struct TriangleMesh;
namespace detail {
class FormedPieces;          // a compact part's pieces, formed on demand (src/terrain/formed_pieces.hpp)
class BoxTree;               // the index (src/terrain/box_tree.hpp)
struct BoxTreeBall;          // a ball the index is walked by (src/terrain/box_tree.hpp)
class PieceArena;            // the stored pieces' memory (src/terrain/piece_arena.hpp)
struct PieceLeaf;            // a stored piece as the index reports it (src/terrain/piece_arena.hpp)
struct PendingPrisms;        // stored prisms made when the terrain is built (src/terrain/pending_prisms.hpp)
struct TerrainBuilderAccess;  // how the compact builders add their parts
}  // namespace detail

/// The ids of the pieces a builder added: [first, first + count). Piece ids
/// are dense and in insertion order, so a builder's pieces are contiguous.
struct PieceRange {
  PieceId first = 0;
  PieceId count = 0;
  PieceId end() const { return first + count; }
};


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
  /// Adds a region where the soft ground remembers (validated, naming
  /// `where`): its soil's ruts and the pressures it carried
  /// (wtc/tyre/ground_memory.hpp).
  void addSoilRegion(const SoilRegion& region, const std::string& where = "TerrainBuilder::addSoilRegion");
  /// Builds the index. Throws InvalidInputError if there are no pieces.
  Terrain build() &&;

 private:
  friend class Terrain;
  friend struct detail::TerrainBuilderAccess;
  // A compact part's pieces: ids first ... first + count - 1.
  struct Field {
    PieceId first = 0;
    PieceId count = 0;
    PieceId formed_before = 0;  // formed ids of the parts before this one
    std::shared_ptr<const detail::FormedPieces> formed;
    MaterialId material = 0;
  };
  // Throws InvalidInputError naming `where` when `count` more ids would
  // pass PieceId's range (requireRoomFor's first check).
  void requireIdsFor(std::uint64_t count, const std::string& where) const;

  std::vector<ConvexPolyhedron> pieces_;  // a pending prism's place holds an empty piece
  std::vector<MaterialId> piece_material_;
  std::vector<Material> materials_;
  std::vector<SoilRegion> soil_regions_;
  std::vector<Field> fields_;
  std::vector<std::shared_ptr<const detail::PendingPrisms>> pending_;  // by first stored position
  std::vector<PieceRange> field_prisms_;                               // addHeightfield's ranges, in id order
  std::size_t next_id_ = 0;
};

class Terrain {
 public:
  Terrain() = default;
  /// A copy has its own pieces (in an arena of its own) and shares the
  /// immutable index.
  Terrain(const Terrain& other);
  Terrain& operator=(const Terrain& other);
  Terrain(Terrain&&) noexcept;
  Terrain& operator=(Terrain&&) noexcept;
  ~Terrain();

  /// Pieces, stored and formed (ids 0 ... pieceCount() - 1).
  std::size_t pieceCount() const { return piece_count_; }
  /// Which build this terrain is: a number of its own for each
  /// TerrainBuilder::build() (0 for an empty terrain), kept by its copies,
  /// which hold the same pieces. What a contact finder keeps from one call
  /// to the next is kept for one serial.
  std::uint64_t serial() const { return serial_; }
  /// Stored piece `id`. Throws InvalidInputError for a formed one (use the
  /// overload with a scratch).
  const ConvexPolyhedron& piece(PieceId id) const { return fields_.empty() ? pieces_[id] : storedPiece(id); }
  /// Piece `id`: a stored piece itself, or a formed one made into `scratch`
  /// (which the result then refers to).
  const ConvexPolyhedron& piece(PieceId id, std::optional<ConvexPolyhedron>& scratch) const;
  /// Formed piece `id` made into `into`, reusing its buffers (a former
  /// piece's: how the contact finder forms pieces without allocating).
  /// Throws InvalidInputError unless isFormed(id).
  void formPiece(PieceId id, ConvexPolyhedron& into) const;
  /// True for a compact part's piece, formed when asked for.
  bool isFormed(PieceId id) const;
  /// The piece's bounding box, without forming it.
  Aabb pieceBounds(PieceId id) const;
  /// True when queryPoint(piece(id), point, {max_distance = reach}) would
  /// answer kBeyond by its first two tests, the box and the face planes,
  /// leaving a cache untouched; decided from the corners of formed piece
  /// `id` without forming it (how the contact finder forms only the pieces
  /// that may touch). False for a piece that may be within reach, and for a
  /// stored one.
  bool formedPieceBeyond(PieceId id, const Eigen::Vector3d& point, double reach) const;
  /// The stored pieces (all of them when the terrain has no compact field).
  std::span<const ConvexPolyhedron> pieces() const { return pieces_; }
  /// The id of pieces()[stored] (ids skip the compact fields' ranges).
  PieceId storedId(std::size_t stored) const;
  /// Where piece `id` lives: compact part `field` (>= 0), or pieces()[stored]
  /// (field = -1); storedId's inverse for a stored piece.
  struct Place {
    int field = -1;
    std::size_t stored = 0;
  };
  Place place(PieceId id) const;

  /// A compact part of this terrain, a heightfield or a triangle mesh: its
  /// pieces' ids and its geometry (an engine plugin gives it to the engine
  /// as one heightfield or triangle-mesh shape). Exactly one of field and
  /// mesh is set; both live as long as the terrain.
  struct CompactField {
    PieceId first = 0;  ///< Its pieces are first ... first + count - 1.
    PieceId count = 0;
    /// A heightfield's samples; its pieces in addHeightfield's order. Its
    /// cell_holes is empty unless a cell is a hole.
    const Heightfield* field = nullptr;
    /// A mesh's vertices and triangles: piece first + k is triangle k,
    /// wound outward, extruded `thickness` (m) along minus its normal.
    const TriangleMesh* mesh = nullptr;
    double thickness = 0.0;
    MaterialId material = 0;  ///< Of every piece, unless the field has cell_materials.
    Aabb bounds;              ///< Of its pieces: a heightfield's reaches down to its base.
  };
  std::size_t compactFieldCount() const { return fields_.size(); }
  CompactField compactField(std::size_t k) const;
  /// Whether piece `id` is a stored prism of a heightfield (addHeightfield):
  /// one of a surface whose prisms' walls are their neighbours' too, inside
  /// the ground. An engine plugin gives a body's contact with such a piece a
  /// normal the surface can push along, as on a compact field
  /// (wtc/sim/terrain_normal_cone.hpp).
  bool isFieldPrism(PieceId id) const;
  /// The piece among ids first ... first + count - 1 nearest `point`: the
  /// smallest signed distance (queryPoint) among those whose boxes come
  /// within `reach` (m) of it; -1 if none does. How an engine plugin names
  /// the piece a contact met on a compact mesh's engine shape.
  PieceId nearestPiece(const Eigen::Vector3d& point, PieceId first, PieceId count, double reach) const;
  const Material& material(PieceId id) const { return materials_[materialId(id)]; }
  MaterialId materialId(PieceId id) const { return fields_.empty() ? piece_material_[id] : fieldAwareMaterialId(id); }
  std::span<const Material> materials() const { return materials_; }
  /// Where the soft ground remembers (none: every soil forgets).
  std::span<const SoilRegion> soilRegions() const { return soil_regions_; }
  const Aabb& bounds() const { return bounds_; }

  /// Appends to `out` every piece whose bounding box overlaps `box`
  /// (allocation-free once `out` has capacity). Order unspecified.
  void overlapping(const Aabb& box, std::vector<PieceId>& out) const;
  /// Appends to `out` every piece whose bounding box overlaps the cube
  /// `point` +- `reach` (m) and comes within `reach` of `point` (squared
  /// distance at most reach^2): of overlapping()'s pieces for that cube,
  /// those a point query with max_distance = reach does not turn away at
  /// its first test (queryPoint), found without visiting the others. A
  /// wheel's search: on a fine heightfield the ground within the wheel's
  /// radius is a disc a few cells wide, its cube a square of many.
  void within(const Eigen::Vector3d& point, double reach, std::vector<PieceId>& out) const;

  /// A run of cells along one row of a compact heightfield
  /// (withinSurfaces): cells (row, first_col ... last_col) of
  /// compactField(part).field, the first ground cell among them holding
  /// pieces first_piece and first_piece + 1 (addHeightfield's order: the
  /// next ground cell the next two).
  struct SurfaceRun {
    PieceId first_piece = 0;
    std::int32_t part = 0;
    std::int32_t row = 0, first_col = 0, last_col = 0;
    /// No local minimum of the distance from the point lies on these
    /// cells: from each of their points the distance falls away along the
    /// surface, onto a triangle of a neighbouring cell that is strictly
    /// nearer. They are ground cells, none of them or their neighbours a
    /// hole or on the field's edge.
    bool passed = false;
  };
  /// within(), but a compact heightfield's pieces come as runs of cells
  /// (row-major within each part, parts in id order) that hold every
  /// cell with a piece within the reach, and others near it: its caller
  /// decides each cell (how a wheel meets a fine field as one surface,
  /// wtc/contact/wheel_contact.hpp). Pieces of other parts go to `out`.
  void withinSurfaces(const Eigen::Vector3d& point, double reach, std::vector<PieceId>& out,
                      std::vector<SurfaceRun>& runs) const;
  /// withinSurfaces() in two halves: the pieces it appends to `out` (the
  /// stored pieces and those of parts not met as a surface), and the runs
  /// it appends to `runs`. A rolling wheel walks the runs for a wider reach
  /// about a point of its own and reads them again while it moves less
  /// than the difference (WheelContactFinder).
  void withinBesideSurfaces(const Eigen::Vector3d& point, double reach, std::vector<PieceId>& out) const;
  void surfaceRuns(const Eigen::Vector3d& point, double reach, std::vector<SurfaceRun>& runs) const;

  /// Memory (bytes) of the pieces (stored pieces, and compact parts'
  /// samples, vertices and triangles) and of the index (the stored pieces'
  /// hierarchy and the compact meshes' own).
  std::size_t pieceMemoryBytes() const;
  std::size_t indexMemoryBytes() const;

 private:
  friend class TerrainBuilder;
  using Field = TerrainBuilder::Field;
  const ConvexPolyhedron& storedPiece(PieceId id) const;
  // skip_surfaces: the compact parts met as surfaces are left to
  // surfaceRuns (withinBesideSurfaces), not given as pieces.
  void collect(const Aabb& box, const detail::BoxTreeBall* ball, std::vector<PieceId>& out,
               bool skip_surfaces = false) const;
  // The compact part holding piece `id`; null for a stored piece or no piece.
  const Field* formedField(PieceId id) const;
  MaterialId fieldAwareMaterialId(PieceId id) const;
  // `pending` are the builder's prisms not made yet (their places in
  // pieces_ are empty), made in gatherPieces.
  void buildIndex(std::span<const detail::PendingPrisms* const> pending);
  // Moves the stored pieces' numbers and topologies into arena_, in the
  // index's leaf order, and makes the pending prisms there
  // (detail::PieceArena).
  void gatherPieces(std::span<const detail::PendingPrisms* const> pending = {});

  std::vector<ConvexPolyhedron> pieces_;
  std::vector<MaterialId> piece_material_;
  std::vector<Material> materials_;
  std::vector<SoilRegion> soil_regions_;
  std::vector<Field> fields_;
  std::vector<PieceRange> field_prisms_;  // addHeightfield's stored prisms, in id order
  std::size_t piece_count_ = 0;
  std::uint64_t serial_ = 0;
  std::shared_ptr<const detail::BoxTree> tree_;  // over the stored pieces; null when there are none
  std::vector<detail::PieceLeaf> leaves_;        // the stored pieces in tree order
  Aabb bounds_;
  // Where the stored pieces' numbers and topologies live (the pieces point
  // into it; a piece reads nothing of it when destroyed).
  std::shared_ptr<const detail::PieceArena> arena_;
};

}  // namespace wtc
