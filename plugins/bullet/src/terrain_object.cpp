#include "wtc/bullet/terrain_object.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <span>

#include "field_tile.hpp"
#include "wtc/terrain/heightfield.hpp"
#include "wtc/terrain/triangle_mesh.hpp"

namespace wtc::bullet {
namespace {

// Interleaves the low 16 bits of x and y (a Morton code).
std::uint32_t interleave(std::uint32_t x, std::uint32_t y) {
  const auto spread = [](std::uint32_t v) {
    v &= 0xffff;
    v = (v | (v << 8)) & 0x00ff00ff;
    v = (v | (v << 4)) & 0x0f0f0f0f;
    v = (v | (v << 2)) & 0x33333333;
    return (v | (v << 1)) & 0x55555555;
  };
  return spread(x) | (spread(y) << 1);
}

// Stored pieces (indices into `pieces`) with neighbours next to each
// other: Morton order of the centres of their boxes on a 2^16 grid over
// the pieces' box.
std::vector<std::size_t> spatialOrder(std::span<const ConvexPolyhedron> pieces) {
  const std::size_t count = pieces.size();
  std::vector<Eigen::Vector3d> centres(count);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (std::size_t s = 0; s < count; ++s) {
    centres[s] = pieces[s].bounds().center();
    lo = lo.cwiseMin(centres[s]);
    hi = hi.cwiseMax(centres[s]);
  }
  const Eigen::Vector3d scale = (65535.0 / (hi - lo).cwiseMax(1e-9).array()).matrix();
  std::vector<std::uint32_t> code(count);
  for (std::size_t s = 0; s < count; ++s) {
    const Eigen::Vector3d q = (centres[s] - lo).cwiseProduct(scale);
    code[s] = interleave(static_cast<std::uint32_t>(q.x()), static_cast<std::uint32_t>(q.y()));
  }
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return code[a] < code[b]; });
  return order;
}

// The tile of `f` whose first sample is (row0, col0), and where it goes.
std::unique_ptr<detail::FieldTile> makeFieldTile(const Heightfield& f, int row0, int col0, btTransform& placement) {
  const int rows = std::min(kFieldTileCells + 1, f.rows - row0), cols = std::min(kFieldTileCells + 1, f.cols - col0);
  double lo = f.height(row0, col0), hi = lo;
  for (int r = row0; r < row0 + rows; ++r) {
    for (int c = col0; c < col0 + cols; ++c) lo = std::min(lo, f.height(r, c)), hi = std::max(hi, f.height(r, c));
  }
  auto tile = std::make_unique<detail::FieldTile>(f, row0, col0, rows, cols, lo, hi);
  tile->setLocalScaling(btVector3(f.spacing_x, f.spacing_y, 1.0));
  tile->setMargin(kTerrainMarginM);
  // Bullet centres the grid on its local origin, and the heights on the
  // middle of [lo, hi].
  const Eigen::Vector3d centre = f.origin + Eigen::Vector3d((col0 + 0.5 * (cols - 1)) * f.spacing_x,
                                                            (row0 + 0.5 * (rows - 1)) * f.spacing_y, 0.5 * (lo + hi));
  placement = btTransform(btQuaternion::getIdentity(), btVector3(centre.x(), centre.y(), centre.z()));
  return tile;
}

// A compact mesh as Bullet's triangle-mesh shape over its own arrays.
std::unique_ptr<btBvhTriangleMeshShape> makeMeshShape(const TriangleMesh& m,
                                                      std::unique_ptr<btTriangleIndexVertexArray>& arrays) {
  arrays = makeMeshArrays(m);
  auto shape = std::make_unique<btBvhTriangleMeshShape>(arrays.get(), /*useQuantizedAabbCompression=*/true);
  shape->setMargin(kTerrainMarginM);
  return shape;
}

}  // namespace

std::unique_ptr<btTriangleIndexVertexArray> makeMeshArrays(const TriangleMesh& m) {
  static_assert(sizeof(btScalar) == sizeof(double) && sizeof(Eigen::Vector3d) == 3 * sizeof(double));
  static_assert(sizeof(m.triangles[0]) == 3 * sizeof(int));
  auto arrays = std::make_unique<btTriangleIndexVertexArray>();
  const auto count = static_cast<std::int64_t>(m.triangles.size());
  for (std::int64_t first = 0; first < count; first += kMeshPartTriangles) {
    btIndexedMesh part;
    part.m_numTriangles = static_cast<int>(std::min<std::int64_t>(kMeshPartTriangles, count - first));
    part.m_triangleIndexBase = reinterpret_cast<const unsigned char*>(m.triangles[first].data());
    part.m_triangleIndexStride = sizeof(m.triangles[0]);
    part.m_indexType = PHY_INTEGER;
    part.m_numVertices = static_cast<int>(m.vertices.size());
    part.m_vertexBase = reinterpret_cast<const unsigned char*>(m.vertices.front().data());
    part.m_vertexStride = sizeof(Eigen::Vector3d);
    part.m_vertexType = PHY_DOUBLE;
    arrays->addIndexedMesh(part, PHY_INTEGER);
  }
  return arrays;
}

TerrainObject::TerrainObject(const Terrain& terrain) : terrain_(terrain) {
  const std::span<const ConvexPolyhedron> stored = terrain.pieces();
  const std::size_t count = stored.size();
  hulls_.reserve(count);
  std::vector<btTransform> origins;  // each hull's child transform: its piece's local origin
  origins.reserve(count);
  for (std::size_t s = 0; s < count; ++s) {
    const ConvexPolyhedron& piece = stored[s];
    // Vertices relative to the piece's local origin keep their digits far
    // from the world origin; the child transform puts them back.
    auto hull = std::make_unique<btConvexHullShape>();
    for (int v = 0; v < piece.vertexCount(); ++v) {
      const Eigen::Vector3d p = piece.vertexLocal(v);
      hull->addPoint(btVector3(p.x(), p.y(), p.z()), false);
    }
    hull->recalcLocalAabb();
    hull->setMargin(kTerrainMarginM);
    hull->setUserIndex(terrain.storedId(s));
    hulls_.push_back(std::move(hull));
    const Eigen::Vector3d& o = piece.origin();
    origins.emplace_back(btQuaternion::getIdentity(), btVector3(o.x(), o.y(), o.z()));
  }
  const int field_count = static_cast<int>(terrain.compactFieldCount());
  if (count <= kPiecesPerGroup) {
    compound_ = std::make_unique<btCompoundShape>(true, static_cast<int>(count) + field_count);
    for (std::size_t s = 0; s < count; ++s) compound_->addChildShape(origins[s], hulls_[s].get());
  } else {
    const std::vector<std::size_t> order = spatialOrder(stored);
    const int group_count = static_cast<int>((count + kPiecesPerGroup - 1) / kPiecesPerGroup);
    compound_ = std::make_unique<btCompoundShape>(true, group_count + field_count);
    for (std::size_t first = 0; first < count; first += kPiecesPerGroup) {
      const std::size_t end = std::min(count, first + kPiecesPerGroup);
      auto group = std::make_unique<btCompoundShape>(true, static_cast<int>(end - first));
      for (std::size_t k = first; k < end; ++k) group->addChildShape(origins[order[k]], hulls_[order[k]].get());
      compound_->addChildShape(btTransform::getIdentity(), group.get());
      groups_.push_back(std::move(group));
    }
  }
  for (int k = 0; k < field_count; ++k) {
    const Terrain::CompactField part = terrain.compactField(k);
    btTransform placement = btTransform::getIdentity();
    if (part.field != nullptr && part.field->cell_holes.empty()) {
      // Tiles, in a compound of their own: a body beside a tall tile (a
      // ledge) walks only the cells of the tiles its box meets in height.
      const Heightfield& f = *part.field;
      auto tiles = std::make_unique<btCompoundShape>(true);
      for (int row0 = 0; row0 + 1 < f.rows; row0 += kFieldTileCells) {
        for (int col0 = 0; col0 + 1 < f.cols; col0 += kFieldTileCells) {
          btTransform at;
          fields_.push_back(makeFieldTile(f, row0, col0, at));
          fields_.back()->setUserIndex(k);
          tiles->addChildShape(at, fields_.back().get());
        }
      }
      compound_->addChildShape(placement, tiles.get());
      groups_.push_back(std::move(tiles));
      continue;
    } else if (part.field != nullptr) {
      // Bullet's heightfield has no holes: the field's surface as a mesh,
      // triangle k on piece k like a compact mesh's.
      const TriangleMesh& surface =
          *field_meshes_.emplace_back(std::make_unique<TriangleMesh>(surfaceMesh(*part.field)));
      fields_.push_back(makeMeshShape(surface, mesh_arrays_.emplace_back()));
    } else {
      fields_.push_back(makeMeshShape(*part.mesh, mesh_arrays_.emplace_back()));
    }
    fields_.back()->setUserIndex(k);
    compound_->addChildShape(placement, fields_.back().get());
  }
  object_.setCollisionShape(compound_.get());
  object_.setCollisionFlags(object_.getCollisionFlags() | btCollisionObject::CF_STATIC_OBJECT);
}

PieceId TerrainObject::pieceOf(const btCollisionObjectWrapper& ground) const {
  const btCollisionShape* shape = ground.getCollisionShape();
  const btCollisionObjectWrapper* parent = ground.m_parent;
  const int parent_type = parent != nullptr ? parent->getCollisionShape()->getShapeType() : -1;
  if (shape->getShapeType() != TRIANGLE_SHAPE_PROXYTYPE ||
      (parent_type != TERRAIN_SHAPE_PROXYTYPE && parent_type != TRIANGLE_MESH_SHAPE_PROXYTYPE)) {
    return shape->getUserIndex();  // a hull's piece id, or -1
  }
  const int k = parent->getCollisionShape()->getUserIndex();
  if (k < 0 || k >= static_cast<int>(terrain_.compactFieldCount())) return -1;
  if (parent_type == TRIANGLE_MESH_SHAPE_PROXYTYPE) {
    return terrain_.compactField(k).first + ground.m_partId * kMeshPartTriangles + ground.m_index;
  }
  // Bullet numbers a heightfield's triangles by part 2 column + (0 or 1)
  // and index row, in its tile; with flipQuadEdges part 2c is (p00, p10,
  // p11), WTC's triangle 1, and part 2c + 1 is (p00, p11, p01), WTC's
  // triangle 0.
  const Terrain::CompactField field = terrain_.compactField(k);
  const auto* tile = dynamic_cast<const detail::FieldTile*>(parent->getCollisionShape());
  if (tile == nullptr) return -1;
  const int column = tile->col0() + ground.m_partId / 2, row = tile->row0() + ground.m_index;
  return field.first + 2 * (row * (field.field->cols - 1) + column) + (ground.m_partId % 2 == 0 ? 1 : 0);
}

}  // namespace wtc::bullet
