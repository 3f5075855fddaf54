#include "wtc/bullet/terrain_object.hpp"

namespace wtc::bullet {

TerrainObject::TerrainObject(const Terrain& terrain) : terrain_(terrain) {
  const auto count = static_cast<PieceId>(terrain.pieceCount());
  compound_ = std::make_unique<btCompoundShape>(true, count);
  hulls_.reserve(count);
  for (PieceId id = 0; id < count; ++id) {
    const ConvexPolyhedron& piece = terrain.piece(id);
    // Vertices relative to the piece's local origin keep their digits far
    // from the world origin; the child transform puts them back.
    auto hull = std::make_unique<btConvexHullShape>();
    for (int v = 0; v < piece.vertexCount(); ++v) {
      const Eigen::Vector3d p = piece.vertexLocal(v);
      hull->addPoint(btVector3(p.x(), p.y(), p.z()), false);
    }
    hull->recalcLocalAabb();
    hull->setMargin(kTerrainMarginM);
    const Eigen::Vector3d& o = piece.origin();
    compound_->addChildShape(btTransform(btQuaternion::getIdentity(), btVector3(o.x(), o.y(), o.z())), hull.get());
    hulls_.push_back(std::move(hull));
  }
  object_.setCollisionShape(compound_.get());
  object_.setCollisionFlags(object_.getCollisionFlags() | btCollisionObject::CF_STATIC_OBJECT);
}

}  // namespace wtc::bullet
