#pragma once
// Pieces formed on demand (internal to wtc::core): what a compact
// heightfield (compact_heightfield.hpp) and a compact triangle mesh
// (compact_mesh.hpp) have in common for the terrain. Each keeps its own
// geometry (samples, or vertices and triangles) and its own index, and
// forms piece k bit for bit as the matching builder (addHeightfield,
// addTriangleMesh) would have stored it.
#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "wtc/geometry/aabb.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"
#include "pending_prisms.hpp"
#include "wtc/terrain/terrain.hpp"

namespace wtc {
struct Heightfield;
struct TriangleMesh;
}  // namespace wtc

namespace wtc::detail {

using SurfaceRun = Terrain::SurfaceRun;

class FormedPieces {
 public:
  virtual ~FormedPieces() = default;
  virtual std::size_t pieceCount() const = 0;
  /// The corners of piece k, a prism: its top triangle and, under each
  /// corner, the bottom one (makeCheckedPrism's arguments).
  virtual void prismCorners(std::size_t k, std::array<Eigen::Vector3d, 3>& top,
                            std::array<Eigen::Vector3d, 3>& bottom) const = 0;
  /// Piece k, bit for bit the stored builder's: the prism on its corners,
  /// which were checked when the geometry was added.
  ConvexPolyhedron piece(std::size_t k) const;
  /// piece(k) made into `into`, reusing its buffers.
  void formInto(std::size_t k, ConvexPolyhedron& into) const;
  /// piece(k).bounds(), without forming the piece: the box of its six
  /// corners.
  Aabb pieceBounds(std::size_t k) const;
  /// True when queryPoint, asked for piece(k) within `reach` (m) of
  /// `point`, answers kBeyond by its first two tests (the box, the face
  /// planes), decided without forming the piece; false says nothing.
  bool beyond(std::size_t k, const Eigen::Vector3d& point, double reach) const;
  /// Appends first + k for every piece k whose bounds overlap `box`, exactly
  /// as Aabb::overlaps decides on pieceBounds(k).
  virtual void overlapping(const Aabb& box, PieceId first, std::vector<PieceId>& out) const = 0;
  /// Appends first + k for every piece k whose bounds overlap the cube
  /// `point` +- `reach` and come within `reach` of `point`, exactly as
  /// Aabb::overlaps and Aabb::squaredDistance decide on pieceBounds(k)
  /// (Terrain::within). By default overlapping() on the cube, then the
  /// distance.
  virtual void within(const Eigen::Vector3d& point, double reach, PieceId first, std::vector<PieceId>& out) const;
  /// Whether the part is met as one surface (a heightfield): its
  /// within() comes as surfaceWithin()'s runs.
  virtual bool isSurface() const { return false; }
  /// A surface's within() (isSurface()): runs of its cells
  /// (Terrain::withinSurfaces), `part` their compact part.
  virtual void surfaceWithin(const Eigen::Vector3d& /*point*/, double /*reach*/, PieceId /*first*/, int /*part*/,
                             std::vector<SurfaceRun>& /*runs*/) const {}
  /// The union of all pieces' bounds.
  virtual const Aabb& bounds() const = 0;
  /// The geometry (bytes).
  virtual std::size_t memoryBytes() const = 0;
  /// The index (bytes): 0 for a grid, which is its own index.
  virtual std::size_t indexMemoryBytes() const { return 0; }
  /// Piece k's material, where `whole` is the one given for all of them.
  virtual MaterialId materialId(std::size_t /*k*/, MaterialId whole) const { return whole; }
  /// The geometry, for an engine plugin: one of the two is not null.
  virtual const Heightfield* heightfield() const { return nullptr; }
  virtual const TriangleMesh* mesh() const { return nullptr; }
  /// A mesh's extrusion depth (m); 0 for a heightfield.
  virtual double thickness() const { return 0.0; }
};

/// What the compact builders (heightfields, triangle meshes) may do to a
/// TerrainBuilder that its public face does not offer.
struct TerrainBuilderAccess {
  /// Gives `pieces` the next ids of `builder`; `where` names the caller in
  /// the error thrown when the ids would pass PieceId's range.
  static PieceRange addFormedPieces(TerrainBuilder& builder, std::shared_ptr<const FormedPieces> pieces,
                                    MaterialId material, const std::string& where);
  /// Gives `count` prisms, made from `corners` when the terrain is built
  /// (pending_prisms.hpp), the next ids of `builder` as stored pieces, prism
  /// k of material materialOf(k); `where` names the caller in the error
  /// thrown when they would pass PieceId's range or this machine's memory.
  static PieceRange addPendingPrisms(TerrainBuilder& builder, std::size_t count, PendingPrisms::Corners corners,
                                     const std::function<MaterialId(std::size_t)>& materialOf,
                                     const std::string& where);
  /// Marks `range`, the builder's latest pieces, as a heightfield's stored
  /// prisms (Terrain::isFieldPrism).
  static void noteFieldPrisms(TerrainBuilder& builder, const PieceRange& range);
};

}  // namespace wtc::detail
