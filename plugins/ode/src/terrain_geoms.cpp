#include "wtc/ode/terrain_geoms.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>

#include "wtc/terrain/heightfield.hpp"
#include "wtc/terrain/triangle_mesh.hpp"

namespace wtc::ode {
namespace {

static_assert(sizeof(dTriIndex) == sizeof(std::uint32_t), "WTC builds ODE meshes with 32-bit indices");

// The quadtree's depth: about one level per factor 4 in the piece count, so
// its leaves hold a few pieces, capped where ODE's block array
// ((4^(d+1) - 1) / 3 blocks of ~60 bytes) would pass 5 MB.
constexpr int kQuadTreeMaxDepth = 8;

int quadTreeDepth(std::size_t pieces) {
  const int depth = static_cast<int>(std::ceil(std::log(static_cast<double>(pieces)) / std::log(4.0)));
  return std::clamp(depth, 1, kQuadTreeMaxDepth);
}

}  // namespace

TerrainGeoms::TerrainGeoms(const Terrain& terrain, dSpaceID parent, TerrainShape shape)
    : terrain_(terrain), shape_(shape) {
  const Aabb& bounds = terrain.bounds();
  const Eigen::Vector3d centre = bounds.center(), half = 0.5 * bounds.extent();
  const dVector3 quad_centre = {centre.x(), centre.y(), centre.z(), 0};
  const dVector3 quad_extents = {half.x(), half.y(), half.z(), 0};
  space_ = dQuadTreeSpaceCreate(parent, quad_centre, quad_extents, quadTreeDepth(terrain.pieceCount()));
  dSpaceSetCleanup(space_, 1);  // the geoms go with the space
  const std::span<const ConvexPolyhedron> stored = terrain.pieces();
  geoms_.reserve(stored.size() + terrain.compactFieldCount());
  numbers_.reserve(stored.size());
  indices_.reserve(stored.size());
  for (std::size_t s = 0; s < stored.size(); ++s) {
    const ConvexPolyhedron& piece = stored[s];
    const Eigen::Vector3d origin = shape == TerrainShape::kConvex ? addConvex(piece) : addTriMesh(piece);
    dGeomSetPosition(geoms_.back(), origin.x(), origin.y(), origin.z());
    dGeomSetData(geoms_.back(), reinterpret_cast<void*>(static_cast<std::intptr_t>(terrain.storedId(s))));
    // Into its quadtree block now, while it is still first in the root's
    // list: ODE's quadtree takes a moved geom out of its block by a walk of
    // the block's list, and left to the first collide, every piece would
    // walk the root's whole list (quadratic: a 640,000-piece heightfield
    // did not finish building in 20 minutes).
    dSpaceClean(space_);
  }
  for (std::size_t k = 0; k < terrain.compactFieldCount(); ++k) {
    const Terrain::CompactField part = terrain.compactField(k);
    if (part.field != nullptr && part.field->cell_holes.empty()) {
      addField(k);
    } else if (part.field != nullptr) {
      // ODE's heightfield has no holes: the field's surface as a mesh,
      // triangle k on piece k like a compact mesh's.
      addMesh(k, *field_meshes_.emplace_back(std::make_unique<TriangleMesh>(surfaceMesh(*part.field))));
    } else {
      addMesh(k, *part.mesh);
    }
  }
}

TerrainGeoms::~TerrainGeoms() {
  dSpaceDestroy(space_);
  for (const dTriMeshDataID mesh : meshes_) dGeomTriMeshDataDestroy(mesh);
  for (const dHeightfieldDataID field : fields_) dGeomHeightfieldDataDestroy(field);
}

dGeomID TerrainGeoms::geom(PieceId piece) const {
  const Terrain::Place at = terrain_.place(piece);
  return at.field >= 0 ? geoms_[terrain_.pieces().size() + static_cast<std::size_t>(at.field)] : geoms_[at.stored];
}

// A geom's data: its piece id (>= 0), or -2 - k for compact field k.
PieceId TerrainGeoms::piece(dGeomID geom) const {
  if (dGeomIsSpace(geom) || dGeomGetSpace(geom) != space_) return -1;
  return std::max(static_cast<PieceId>(reinterpret_cast<std::intptr_t>(dGeomGetData(geom))), PieceId{-1});
}

PieceId TerrainGeoms::piece(dGeomID geom, const Eigen::Vector3d& point) const {
  if (dGeomIsSpace(geom) || dGeomGetSpace(geom) != space_) return -1;
  const auto data = static_cast<PieceId>(reinterpret_cast<std::intptr_t>(dGeomGetData(geom)));
  if (data >= 0) return data;
  const Terrain::CompactField part = terrain_.compactField(static_cast<std::size_t>(-2 - data));
  if (part.field != nullptr && part.field->cell_holes.empty()) {
    return *pieceUnder({part.first, part.count}, *part.field, point.x(), point.y());
  }
  return terrain_.nearestPiece(point, part.first, part.count, kMeshContactReachM);
}

bool TerrainGeoms::isField(dGeomID geom) const {
  if (dGeomIsSpace(geom) || dGeomGetSpace(geom) != space_) return false;
  const auto data = static_cast<PieceId>(reinterpret_cast<std::intptr_t>(dGeomGetData(geom)));
  if (data >= 0) return terrain_.isFieldPrism(data);
  return data <= -2 && terrain_.compactField(static_cast<std::size_t>(-2 - data)).field != nullptr;
}

namespace {

// The height of a compact field's sample for ODE: ODE's x is the field's
// column, ODE's z the row counted from the far end (addField turns ODE's z
// onto WTC's -y).
dReal fieldHeight(void* field, int x, int z) {
  const auto* f = static_cast<const Heightfield*>(field);
  return f->height(f->rows - 1 - z, x);
}

}  // namespace

void TerrainGeoms::addMesh(std::size_t k, const TriangleMesh& m) {
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(dReal) && sizeof(m.triangles[0]) == 3 * sizeof(dTriIndex));
  // ODE reads the mesh's own arrays (its indices are unsigned 32-bit, the
  // mesh's signed and non-negative); triangle i is the part's piece i.
  const dTriMeshDataID data = dGeomTriMeshDataCreate();
  dGeomTriMeshDataBuildDouble(data, m.vertices.front().data(), sizeof(Eigen::Vector3d),
                              static_cast<int>(m.vertices.size()),
                              reinterpret_cast<const dTriIndex*>(m.triangles.front().data()),
                              static_cast<int>(3 * m.triangles.size()), sizeof(m.triangles[0]));
  // As addTriMesh: face angles, without which ODE's convex-trimesh collider aborts.
  dGeomTriMeshDataPreprocess2(
      data, (1U << dTRIDATAPREPROCESS_BUILD_CONCAVE_EDGES) | (1U << dTRIDATAPREPROCESS_BUILD_FACE_ANGLES), nullptr);
  meshes_.push_back(data);
  const dGeomID geom = dCreateTriMesh(space_, data, nullptr, nullptr, nullptr);
  dGeomSetData(geom, reinterpret_cast<void*>(static_cast<std::intptr_t>(-2 - static_cast<PieceId>(k))));
  dSpaceClean(space_);
  geoms_.push_back(geom);
}

void TerrainGeoms::addField(std::size_t k) {
  const Heightfield& f = *terrain_.compactField(k).field;
  const auto [lo, hi] = std::minmax_element(f.heights.begin(), f.heights.end());
  const dHeightfieldDataID data = dGeomHeightfieldDataCreate();
  fields_.push_back(data);
  // Width along ODE's x (the columns), depth along ODE's z (the rows);
  // solid down to the field's base (thickness below the lowest sample).
  dGeomHeightfieldDataBuildCallback(data, const_cast<Heightfield*>(&f), &fieldHeight, (f.cols - 1) * f.spacing_x,
                                    (f.rows - 1) * f.spacing_y, f.cols, f.rows, /*scale=*/1.0, /*offset=*/0.0,
                                    /*thickness=*/f.base_depth, /*bWrap=*/0);
  dGeomHeightfieldDataSetBounds(data, *lo, *hi);
  const dGeomID geom = dCreateHeightfield(space_, data, /*bPlaceable=*/1);
  // ODE's heightfield has y up; its x stays x, its y goes to z, its z to
  // -y (a right-handed turn). Rows of ODE's 3 x 4 matrix.
  const dMatrix3 turn = {1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0};
  dGeomSetRotation(geom, turn);
  // ODE centres the grid on the geom's position; heights count from it.
  const Eigen::Vector3d centre =
      f.origin + Eigen::Vector3d(0.5 * (f.cols - 1) * f.spacing_x, 0.5 * (f.rows - 1) * f.spacing_y, 0.0);
  dGeomSetPosition(geom, centre.x(), centre.y(), centre.z());
  dGeomSetData(geom, reinterpret_cast<void*>(static_cast<std::intptr_t>(-2 - static_cast<PieceId>(k))));
  dSpaceClean(space_);
  geoms_.push_back(geom);
}

bool TerrainGeoms::contains(dGeomID geom) const {
  return geom == reinterpret_cast<dGeomID>(space_) || dGeomGetSpace(geom) == space_;
}

Eigen::Vector3d TerrainGeoms::addConvex(const ConvexPolyhedron& piece) {
  // [points (3 per vertex) | planes (n, d) (4 per face)], relative to the
  // piece's centroid: ODE wants its convex geom's origin inside (every
  // d >= 0; it warns "Plane does not contain the origin"), and the
  // bounding-box centre, WTC's local origin, can lie outside a sliver.
  const Eigen::Vector3d centroid = piece.centroidLocal();
  std::vector<dReal>& numbers = numbers_.emplace_back();
  std::vector<std::uint32_t>& polygons = indices_.emplace_back();
  numbers.reserve(3 * piece.vertexCount() + 4 * piece.faceCount());
  for (int v = 0; v < piece.vertexCount(); ++v) {
    const Eigen::Vector3d p = piece.vertexLocal(v) - centroid;
    numbers.insert(numbers.end(), {p.x(), p.y(), p.z()});
  }
  for (int f = 0; f < piece.faceCount(); ++f) {
    const Eigen::Vector3d n = piece.faceNormal(f);
    numbers.insert(numbers.end(), {n.x(), n.y(), n.z(), piece.faceOffsetLocal(f) - n.dot(centroid)});
    // Each polygon: its vertex count, then its vertices counter-clockwise
    // seen from outside (WTC's order is ODE's).
    const auto face = piece.faceVertices(f);
    polygons.push_back(static_cast<std::uint32_t>(face.size()));
    polygons.insert(polygons.end(), face.begin(), face.end());
  }
  const dReal* points = numbers.data();
  const dReal* planes = points + 3 * piece.vertexCount();
  geoms_.push_back(dCreateConvex(space_, planes, piece.faceCount(), points, piece.vertexCount(), polygons.data()));
  return piece.centroid();
}

Eigen::Vector3d TerrainGeoms::addTriMesh(const ConvexPolyhedron& piece) {
  std::vector<dReal>& points = numbers_.emplace_back();
  std::vector<std::uint32_t>& triangles = indices_.emplace_back();
  points.reserve(3 * piece.vertexCount());
  for (int v = 0; v < piece.vertexCount(); ++v) {
    const Eigen::Vector3d p = piece.vertexLocal(v);
    points.insert(points.end(), {p.x(), p.y(), p.z()});
  }
  // Each convex face as a fan; counter-clockwise from outside, so ODE's
  // triangle normals point out of the piece.
  for (int f = 0; f < piece.faceCount(); ++f) {
    const auto face = piece.faceVertices(f);
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      triangles.insert(triangles.end(), {static_cast<std::uint32_t>(face[0]), static_cast<std::uint32_t>(face[k]),
                                         static_cast<std::uint32_t>(face[k + 1])});
    }
  }
  dTriMeshDataID mesh = dGeomTriMeshDataCreate();
  dGeomTriMeshDataBuildDouble(mesh, points.data(), 3 * sizeof(dReal), piece.vertexCount(), triangles.data(),
                              static_cast<int>(triangles.size()), 3 * sizeof(dTriIndex));
  // Concave edges speed up capsules; face angles are required by ODE's
  // convex-trimesh collider (it aborts without them).
  dGeomTriMeshDataPreprocess2(
      mesh, (1U << dTRIDATAPREPROCESS_BUILD_CONCAVE_EDGES) | (1U << dTRIDATAPREPROCESS_BUILD_FACE_ANGLES), nullptr);
  meshes_.push_back(mesh);
  geoms_.push_back(dCreateTriMesh(space_, mesh, nullptr, nullptr, nullptr));
  return piece.origin();
}

}  // namespace wtc::ode
