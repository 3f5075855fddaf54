#include "wtc/bullet/terrain_object.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <optional>

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

// Piece ids with neighbours next to each other: Morton order of the
// centres of their boxes on a 2^16 grid over the terrain's box.
std::vector<PieceId> spatialOrder(const Terrain& terrain) {
  const auto count = static_cast<PieceId>(terrain.pieceCount());
  std::vector<Eigen::Vector3d> centres(count);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (PieceId id = 0; id < count; ++id) {
    const Aabb box = terrain.pieceBounds(id);
    centres[id] = 0.5 * (box.min + box.max);
    lo = lo.cwiseMin(centres[id]);
    hi = hi.cwiseMax(centres[id]);
  }
  const Eigen::Vector3d scale = (65535.0 / (hi - lo).cwiseMax(1e-9).array()).matrix();
  std::vector<std::uint32_t> code(count);
  for (PieceId id = 0; id < count; ++id) {
    const Eigen::Vector3d q = (centres[id] - lo).cwiseProduct(scale);
    code[id] = interleave(static_cast<std::uint32_t>(q.x()), static_cast<std::uint32_t>(q.y()));
  }
  std::vector<PieceId> order(count);
  std::iota(order.begin(), order.end(), PieceId{0});
  std::stable_sort(order.begin(), order.end(), [&](PieceId a, PieceId b) { return code[a] < code[b]; });
  return order;
}

}  // namespace

TerrainObject::TerrainObject(const Terrain& terrain) : terrain_(terrain) {
  const auto count = static_cast<PieceId>(terrain.pieceCount());
  hulls_.reserve(count);
  std::vector<btTransform> origins;  // each hull's child transform: its piece's local origin
  origins.reserve(count);
  std::optional<ConvexPolyhedron> scratch;  // a compact field's piece, formed here
  for (PieceId id = 0; id < count; ++id) {
    const ConvexPolyhedron& piece = terrain.piece(id, scratch);
    // Vertices relative to the piece's local origin keep their digits far
    // from the world origin; the child transform puts them back.
    auto hull = std::make_unique<btConvexHullShape>();
    for (int v = 0; v < piece.vertexCount(); ++v) {
      const Eigen::Vector3d p = piece.vertexLocal(v);
      hull->addPoint(btVector3(p.x(), p.y(), p.z()), false);
    }
    hull->recalcLocalAabb();
    hull->setMargin(kTerrainMarginM);
    hull->setUserIndex(id);
    hulls_.push_back(std::move(hull));
    const Eigen::Vector3d& o = piece.origin();
    origins.emplace_back(btQuaternion::getIdentity(), btVector3(o.x(), o.y(), o.z()));
  }
  if (count <= kPiecesPerGroup) {
    compound_ = std::make_unique<btCompoundShape>(true, count);
    for (PieceId id = 0; id < count; ++id) compound_->addChildShape(origins[id], hulls_[id].get());
  } else {
    const std::vector<PieceId> order = spatialOrder(terrain);
    const int group_count = static_cast<int>((order.size() + kPiecesPerGroup - 1) / kPiecesPerGroup);
    compound_ = std::make_unique<btCompoundShape>(true, group_count);
    for (std::size_t first = 0; first < order.size(); first += kPiecesPerGroup) {
      const std::size_t end = std::min(order.size(), first + kPiecesPerGroup);
      auto group = std::make_unique<btCompoundShape>(true, static_cast<int>(end - first));
      for (std::size_t k = first; k < end; ++k) group->addChildShape(origins[order[k]], hulls_[order[k]].get());
      compound_->addChildShape(btTransform::getIdentity(), group.get());
      groups_.push_back(std::move(group));
    }
  }
  object_.setCollisionShape(compound_.get());
  object_.setCollisionFlags(object_.getCollisionFlags() | btCollisionObject::CF_STATIC_OBJECT);
}

}  // namespace wtc::bullet
