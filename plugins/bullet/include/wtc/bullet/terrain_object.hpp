#pragma once
// The WTC terrain as one static Bullet collision object: a compound of
// convex hulls, one per stored piece, so that every pair other than
// wheel-terrain (a chassis scraping the ledge) collides with the same ground
// through Bullet's own algorithms.
//
// A compact heightfield (addCompactHeightfield) is one child: a compound of
// tiles of kFieldTileCells cells a side, each a btHeightfieldTerrainShape
// that reads the field's own samples (Bullet copies nothing), its cells
// split along the same diagonal p00-p11 as the prisms (Bullet's
// flipQuadEdges), so a chassis meets the same surface. A
// compact triangle mesh (MeshExtrusionOptions::compact) is one child too:
// a btBvhTriangleMeshShape over the mesh's own vertices and triangles.
// Bullet's heightfield has no holes, so a compact field with holes is its
// surface as such a mesh (surfaceMesh), at a mesh's memory (docs/terrain.md).
// Unlike the prisms both are surfaces, not solids: a body that has sunk
// through one is not pushed back up. The wheels never see them: WTC
// answers them from the terrain itself.
//
// Large terrains are a two-level compound: pieces in groups of
// kPiecesPerGroup, neighbours together (Morton order of their centres),
// each group a compound. btCompoundCollisionAlgorithm walks every child of
// its compound at every step, overlapping or not; two levels make that walk
// n / G + G instead of n (bench/sim_step_bench.cpp measures the step).
#include <memory>
#include <vector>

#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btHeightfieldTerrainShape.h>
#include <BulletCollision/CollisionShapes/btTriangleIndexVertexArray.h>
#include <btBulletCollisionCommon.h>

#include "wtc/terrain/terrain.hpp"
#include "wtc/terrain/triangle_mesh.hpp"

namespace wtc::bullet {

/// Collision margin of the pieces' hulls (m): Bullet's GJK wants a margin;
/// 1 mm moves a chassis contact by 1 mm and never touches WTC's wheels.
inline constexpr btScalar kTerrainMarginM = 0.001;
/// Pieces per group of a two-level terrain compound (count): about the
/// square root of a large terrain's piece count.
inline constexpr int kPiecesPerGroup = 64;

/// Cells along a side of a compact heightfield's tile in Bullet (count).
/// One heightfield shape's box spans all its heights, and Bullet walks
/// every cell under a body whose box meets it: on a sampled ledge every
/// body below the ledge's top walked the field under it at every step. A
/// tile's box spans its own heights; 64 cells keep a 16 m x 6 m field at
/// 1 cm to 250 tiles.
inline constexpr int kFieldTileCells = 64;

/// Triangles per part of a compact mesh's Bullet shape (count): Bullet's
/// quantized tree keeps a triangle's index in 21 bits and its part's in 10
/// (btQuantizedBvh.h, MAX_NUM_PARTS_IN_BITS), so a part of more than 2^21
/// triangles crashes Bullet (it did, at 2 10^7 triangles in one part).
inline constexpr int kMeshPartTriangles = 1 << 21;

/// A compact mesh's vertices and triangles as Bullet's mesh interface,
/// without a copy (the mesh must outlive it): parts of kMeshPartTriangles
/// triangles in order, so triangle t is part t / kMeshPartTriangles,
/// index t % kMeshPartTriangles.
std::unique_ptr<btTriangleIndexVertexArray> makeMeshArrays(const TriangleMesh& mesh);

class TerrainObject {
 public:
  explicit TerrainObject(const Terrain& terrain);
  TerrainObject(const TerrainObject&) = delete;
  TerrainObject& operator=(const TerrainObject&) = delete;

  const Terrain& terrain() const { return terrain_; }
  /// The piece a contact of this object's met, from the wrapper a contact
  /// callback sees: a hull's user index is its piece id; a heightfield's
  /// or mesh's triangle is found from its part and index. -1 for anything
  /// else.
  PieceId pieceOf(const btCollisionObjectWrapper& ground) const;
  btCollisionObject& object() { return object_; }
  const btCollisionObject& object() const { return object_; }

 private:
  const Terrain& terrain_;
  std::vector<std::unique_ptr<btConvexHullShape>> hulls_;
  std::vector<std::unique_ptr<btConcaveShape>> fields_;      // each compact field's tiles, or its mesh

  std::vector<std::unique_ptr<TriangleMesh>> field_meshes_;  // the surfaces of the compact fields with holes
  std::vector<std::unique_ptr<btTriangleIndexVertexArray>> mesh_arrays_;  // the compact meshes' views
  std::vector<std::unique_ptr<btCompoundShape>> groups_;     // the stored pieces' groups, the fields' tiles
  std::unique_ptr<btCompoundShape> compound_;
  btCollisionObject object_;
};

}  // namespace wtc::bullet
