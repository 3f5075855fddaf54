#include "wtc/ode/terrain_geoms.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

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
  const auto count = static_cast<PieceId>(terrain.pieceCount());
  geoms_.reserve(count);
  numbers_.reserve(count);
  indices_.reserve(count);
  std::optional<ConvexPolyhedron> scratch;  // a compact field's piece, formed here
  for (PieceId id = 0; id < count; ++id) {
    const ConvexPolyhedron& piece = terrain.piece(id, scratch);
    const Eigen::Vector3d origin = shape == TerrainShape::kConvex ? addConvex(piece) : addTriMesh(piece);
    dGeomSetPosition(geoms_.back(), origin.x(), origin.y(), origin.z());
    dGeomSetData(geoms_.back(), reinterpret_cast<void*>(static_cast<std::intptr_t>(id)));
    // Into its quadtree block now, while it is still first in the root's
    // list: ODE's quadtree takes a moved geom out of its block by a walk of
    // the block's list, and left to the first collide, every piece would
    // walk the root's whole list (quadratic: a 640,000-piece heightfield
    // did not finish building in 20 minutes).
    dSpaceClean(space_);
  }
}

TerrainGeoms::~TerrainGeoms() {
  dSpaceDestroy(space_);
  for (const dTriMeshDataID mesh : meshes_) dGeomTriMeshDataDestroy(mesh);
}

PieceId TerrainGeoms::piece(dGeomID geom) const {
  if (dGeomIsSpace(geom) || dGeomGetSpace(geom) != space_) return -1;
  return static_cast<PieceId>(reinterpret_cast<std::intptr_t>(dGeomGetData(geom)));
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
    numbers.insert(numbers.end(), {n.x(), n.y(), n.z(), piece.pd()[f] - n.dot(centroid)});
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
