#pragma once
// The WTC terrain as static ODE geoms, so that every pair other than
// wheel-terrain (a chassis scraping the ledge, a box dropped on the ground)
// collides with the same ground through ODE's own colliders.
//
// One geom per convex piece, placed inside the piece (its local origin, or
// its centroid for a convex geom) with its vertices relative to that point
// (a piece far from the world origin keeps its digits), in a quadtree space
// of its own inside the user's space. A quadtree, not a hash space: ODE's
// dxHashSpace::collide2 tests a geom against every geom of the space, and a
// chassis colliding into the terrain space goes through collide2; the
// quadtree descends its blocks. Its plane is ODE's default, x-y: WTC's
// frames have z up.
//
// Two shapes, because Debian's ODE 0.16 collides them differently (measured
// with dCollide, docs/ode-plugin.md):
//  - kTriMesh (default): the piece's faces as a closed triangle mesh. ODE
//    returns full manifolds against it (a box resting on a face: 6
//    contacts; a cylinder: 10) and collides box, sphere, capsule,
//    cylinder, ray and trimesh with it. The data is preprocessed for
//    convex-trimesh, which otherwise aborts inside ODE.
//  - kConvex: dCreateConvex from the piece's planes (outward normal n and
//    offset d: n . x = d, d >= 0 from an interior origin) and faces
//    (counter-clockwise seen from outside); ODE checks both and prints a
//    warning otherwise. Exact solid, but ODE's convex colliders return one
//    contact per pair, so a box resting on it is held at one point per step.
//
// A compact heightfield (addCompactHeightfield) is one dGeomHeightfield
// that reads the field's samples through a callback (nothing copied),
// turned so that its up axis is WTC's z; ODE splits each cell along the
// prisms' diagonal p00-p11 in that orientation (tested). ODE treats the
// ground below its surface, down to the field's base, as solid. ODE's
// heightfield has no holes: a compact field with holes is its surface
// (surfaceMesh) as a trimesh geom, as a compact mesh is.
//
// A compact triangle mesh (MeshExtrusionOptions::compact) is one trimesh
// geom over the mesh's own vertices and triangles (nothing copied): a
// surface, not a solid. A contact on it is named by the piece nearest its
// point (Terrain::nearestPiece): ODE's triangle index (dContactGeom::side1)
// is lost when ODE merges contacts. ODE's trimesh colliders (OPCODE)
// compute in single precision: its contact points lie within a few float
// ulps of the surface, more far from the origin (docs/ode-plugin.md has the
// measured error); the heightfield geom computes in double.
//
// The plugin tells terrain geoms by their space (contains()).
#include <cstdint>
#include <memory>
#include <vector>

#include <ode/ode.h>
#include <Eigen/Core>

#include "wtc/terrain/terrain.hpp"
#include "wtc/terrain/triangle_mesh.hpp"

namespace wtc::ode {

/// How far from a contact point on a compact mesh's geom its piece is
/// looked for (m): ODE's contact points lie on the surface within the
/// penetration depth, millimetres; 5 cm leaves room for a deep one.
inline constexpr double kMeshContactReachM = 0.05;

enum class TerrainShape {
  kTriMesh,  ///< A closed triangle mesh per piece (default: ODE's best-supported static shape).
  kConvex,   ///< dCreateConvex per piece (one contact per pair in ODE).
};

class TerrainGeoms {
 public:
  /// Builds the geoms of every piece of `terrain` (which must outlive this)
  /// in a new space inside `parent` (null: a top-level space).
  TerrainGeoms(const Terrain& terrain, dSpaceID parent, TerrainShape shape);
  /// Destroys the space, its geoms and the mesh data. The parent space must
  /// still exist.
  ~TerrainGeoms();
  TerrainGeoms(const TerrainGeoms&) = delete;
  TerrainGeoms& operator=(const TerrainGeoms&) = delete;

  const Terrain& terrain() const { return terrain_; }
  TerrainShape shape() const { return shape_; }
  dSpaceID space() const { return space_; }
  /// True for the terrain space itself and for each piece's geom.
  bool contains(dGeomID geom) const;
  /// The geom of a piece: its own, or its compact field's.
  dGeomID geom(PieceId piece) const;
  /// The piece a geom of this terrain stands for, -1 for any other geom
  /// and for a compact field's (use the overload with a point).
  PieceId piece(dGeomID geom) const;
  /// The piece a contact of `geom` at world point `point` met: piece(geom),
  /// or for a compact field's geom the triangle under the point, for a
  /// compact mesh's the piece nearest it (-1 if none within
  /// kMeshContactReachM).
  PieceId piece(dGeomID geom, const Eigen::Vector3d& point) const;
  /// True for a geom of a heightfield's surface: a compact field's (ODE's
  /// dHeightfield, or the field's surface as a mesh when it has holes), or
  /// one of a heightfield's stored prisms (Terrain::isFieldPrism).
  bool isField(dGeomID geom) const;

 private:
  // Each adds the piece's geom and returns where to place it (world, m).
  Eigen::Vector3d addConvex(const ConvexPolyhedron& piece);
  Eigen::Vector3d addTriMesh(const ConvexPolyhedron& piece);

  const Terrain& terrain_;
  TerrainShape shape_;
  dSpaceID space_ = nullptr;
  void addField(std::size_t k);
  void addMesh(std::size_t k, const TriangleMesh& mesh);

  std::vector<dGeomID> geoms_;  // the stored pieces' (Terrain::pieces() order), then one per compact field or mesh
  std::vector<std::unique_ptr<TriangleMesh>> field_meshes_;  // the surfaces of the compact fields with holes
  std::vector<dTriMeshDataID> meshes_;                       // the stored pieces' (kTriMesh), then the compact meshes'
  std::vector<dHeightfieldDataID> fields_;                   // one per compact field
  // ODE keeps pointers into these (it copies nothing): one buffer per piece,
  // never resized once its geom exists.
  std::vector<std::vector<dReal>> numbers_;          // points, then planes (convex)
  std::vector<std::vector<std::uint32_t>> indices_;  // polygons (convex) or triangles
};

}  // namespace wtc::ode
