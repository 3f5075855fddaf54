#include "field_body_algorithm.hpp"

#include <algorithm>
#include <cmath>
#include <new>
#include <utility>

#include <BulletCollision/CollisionShapes/btTriangleShape.h>

#include "field_tile.hpp"

namespace wtc::bullet::detail {
namespace {

// Margin of the body's box test (m): far above the rounding of the
// transforms and of GJK's answer near the threshold, far below a cell.
constexpr btScalar kBoxTestSlackM = 1e-6;
// Margin of the rows' clip before the cells' own box test (m): far above
// the rounding of a cell's interval on an axis, which the cell test then
// decides exactly.
constexpr btScalar kRowClipSlackM = 1e-6;

// Each triangle of a tile that Bullet's box test lets by: the body's own box,
// then Bullet's convex-triangle collision as btConvexTriangleCallback runs it
// (its plane test, then the dispatcher's algorithm for the pair).
class TriangleCallback final : public btTriangleCallback {
 public:
  TriangleCallback(const btCollisionObjectWrapper* convex, const btCollisionObjectWrapper* tile,
                   btDispatcher* dispatcher, btPersistentManifold* manifold, const btDispatcherInfo& dispatch_info,
                   btManifoldResult* result)
      : convex_(convex),
        tile_(tile),
        dispatcher_(dispatcher),
        manifold_(manifold),
        dispatch_info_(dispatch_info),
        result_(result),
        threshold_(manifold->getContactBreakingThreshold() + result->m_closestPointDistanceThreshold),
        margin_(tile->getCollisionShape()->getMargin()) {
    const auto* shape = static_cast<const btConvexShape*>(convex->getCollisionShape());
    // The body's box in the tile's frame, grown by the triangles' margin and
    // the closest-point distance (btConvexTriangleCallback::setTimeStepAndCounters).
    const btTransform body_in_tile = tile->getWorldTransform().inverse() * convex->getWorldTransform();
    shape->getAabb(body_in_tile, aabb_min_, aabb_max_);
    const btScalar extra = margin_ + result->m_closestPointDistanceThreshold;
    aabb_min_ -= btVector3(extra, extra, extra);
    aabb_max_ += btVector3(extra, extra, extra);
    // The body's own box in its frame, grown by the farthest a contact may
    // lie off it.
    shape->getAabb(btTransform::getIdentity(), box_min_, box_max_);
    const btScalar reach = threshold_ + margin_ + kBoxTestSlackM;
    box_min_ -= btVector3(reach, reach, reach);
    box_max_ += btVector3(reach, reach, reach);
    tile_in_body_ = body_in_tile.inverse();
    world_to_body_ = convex->getWorldTransform().getBasis().inverse();
  }

  const btVector3& aabbMin() const { return aabb_min_; }
  const btVector3& aabbMax() const { return aabb_max_; }

  // FieldTile::walkTriangles's row filter: the cells of a row whose box
  // (x0 + i step .. x0 + (i + 1) step, y0 .. y1, z0 .. z1, the tile's frame)
  // meets the body's own box on each of the body's axes, with a cell more
  // each way than computed. A cell's corners lie in its box, so cellNear
  // passes no cell left out here. On axis k a cell's box spans m_k +- e_k,
  // its centre m_k = A_k + B_k i linear in i.
  void narrowRow(btScalar x0, btScalar step, btScalar y0, btScalar y1, btScalar z0, btScalar z1, int& from,
                 int& to) const {
    const btMatrix3x3& basis = tile_in_body_.getBasis();
    const btScalar xc = x0 + 0.5 * step, yc = 0.5 * (y0 + y1), zc = 0.5 * (z0 + z1);
    for (int k = 0; k < 3 && from < to; ++k) {
      const btVector3& axis = basis[k];
      const btScalar a = axis.dot(btVector3(xc, yc, zc)) + tile_in_body_.getOrigin()[k], b = axis[0] * step;
      const btScalar e = 0.5 * (btFabs(axis[0]) * step + btFabs(axis[1]) * (y1 - y0) + btFabs(axis[2]) * (z1 - z0));
      const btScalar lo = box_min_[k] - e - kRowClipSlackM, hi = box_max_[k] + e + kRowClipSlackM;
      // A cell's width of the row's length this axis hardly turns: the
      // cells all pass or all fail it.
      if (btFabs(b) * (to - from) < kRowClipSlackM) {
        const btScalar at = a + b * from;
        if (at < lo || at > hi) from = to;
        continue;
      }
      btScalar first = (lo - a) / b, last = (hi - a) / b;
      if (b < 0.0) std::swap(first, last);
      if (!std::isfinite(first) || !std::isfinite(last)) continue;  // a body off the scale: no clip
      if (first > to || last < from) {
        from = to;
        continue;
      }
      // Within a cell of the row's ends before the cast (a far body's are
      // far beyond an int).
      first = std::max(first, static_cast<btScalar>(from - 1)), last = std::min(last, static_cast<btScalar>(to + 1));
      from = std::max(from, static_cast<int>(std::floor(first)) - 1);
      to = std::min(to, static_cast<int>(std::ceil(last)) + 2);
    }
  }

  // Whether a cell whose corners (the tile's frame) are `corners` may hold a
  // triangle that the body's own box lets by: beyond the box on one of its
  // axes, each of the cell's triangles is too (processTriangle's test, on
  // the same transformed corners).
  bool cellNear(const btVector3* corners) const {
    btVector3 low = tile_in_body_ * corners[0], high = low;
    for (int i = 1; i < 4; ++i) {
      const btVector3 p = tile_in_body_ * corners[i];
      low.setMin(p), high.setMax(p);
    }
    for (int k = 0; k < 3; ++k) {
      if (low[k] > box_max_[k] || high[k] < box_min_[k]) return false;
    }
    return true;
  }

  void processTriangle(btVector3* triangle, int part, int index) override {
    if (!TestTriangleAgainstAabb2(triangle, aabb_min_, aabb_max_)) return;
    // The body's own box, in its frame.
    const btVector3 a = tile_in_body_ * triangle[0], b = tile_in_body_ * triangle[1], c = tile_in_body_ * triangle[2];
    for (int k = 0; k < 3; ++k) {
      if (btMin(a[k], btMin(b[k], c[k])) > box_max_[k] || btMax(a[k], btMax(b[k], c[k])) < box_min_[k]) return;
    }
    const auto* shape = static_cast<const btConvexShape*>(convex_->getCollisionShape());
    const btTransform& body = convex_->getWorldTransform();
    const btVector3 v0 = tile_->getWorldTransform() * triangle[0], v1 = tile_->getWorldTransform() * triangle[1],
                    v2 = tile_->getWorldTransform() * triangle[2];
    // Bullet's plane test, both sides (btConvexTriangleCallback's early out).
    btVector3 normal = (v1 - v0).cross(v2 - v0);
    normal.normalize();
    for (int side = 0; side < 2; ++side, normal = -normal) {
      const btVector3 deepest = body * shape->localGetSupportingVertex(world_to_body_ * normal);
      if (normal.dot(v0) - normal.dot(deepest) > threshold_) return;
    }
    btTriangleShape piece(triangle[0], triangle[1], triangle[2]);
    piece.setMargin(margin_);
    const btCollisionObjectWrapper piece_wrap(tile_, &piece, tile_->getCollisionObject(), tile_->getWorldTransform(),
                                              part, index);
    btCollisionAlgorithm* algorithm =
        result_->m_closestPointDistanceThreshold > 0
            ? dispatcher_->findAlgorithm(convex_, &piece_wrap, nullptr, BT_CLOSEST_POINT_ALGORITHMS)
            : dispatcher_->findAlgorithm(convex_, &piece_wrap, manifold_, BT_CONTACT_POINT_ALGORITHMS);
    const bool tile_first = result_->getBody0Internal() == tile_->getCollisionObject();
    const btCollisionObjectWrapper* kept = tile_first ? result_->getBody0Wrap() : result_->getBody1Wrap();
    if (tile_first) {
      result_->setBody0Wrap(&piece_wrap);
      result_->setShapeIdentifiersA(part, index);
    } else {
      result_->setBody1Wrap(&piece_wrap);
      result_->setShapeIdentifiersB(part, index);
    }
    algorithm->processCollision(convex_, &piece_wrap, dispatch_info_, result_);
    if (tile_first) {
      result_->setBody0Wrap(kept);
    } else {
      result_->setBody1Wrap(kept);
    }
    algorithm->~btCollisionAlgorithm();
    dispatcher_->freeCollisionAlgorithm(algorithm);
  }

 private:
  const btCollisionObjectWrapper* convex_;
  const btCollisionObjectWrapper* tile_;
  btDispatcher* dispatcher_;
  btPersistentManifold* manifold_;
  const btDispatcherInfo& dispatch_info_;
  btManifoldResult* result_;
  btScalar threshold_;  // the deepest a kept contact lies off the body (m): btManifoldResult::addContactPoint's
  btScalar margin_;     // the triangles' (m)
  btVector3 aabb_min_, aabb_max_, box_min_, box_max_;
  btTransform tile_in_body_;
  btMatrix3x3 world_to_body_;  // the body's basis inverted, as Bullet's plane test turns a normal
};

}  // namespace

bool FieldBodyAlgorithm::serves(int shape_type) {
  return shape_type != CUSTOM_CONVEX_SHAPE_TYPE && btBroadphaseProxy::isConvex(shape_type);
}

btCollisionAlgorithm* FieldBodyAlgorithm::CreateFunc::CreateCollisionAlgorithm(
    btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper* body0,
    const btCollisionObjectWrapper* body1) {
  const btCollisionObjectWrapper* tile = m_swapped ? body0 : body1;
  const btCollisionObjectWrapper* convex = m_swapped ? body1 : body0;
  if (dynamic_cast<const FieldTile*>(tile->getCollisionShape()) == nullptr ||
      !convex->getCollisionShape()->isConvex()) {
    return fallback_->CreateCollisionAlgorithm(info, body0, body1);
  }
  void* memory = info.m_dispatcher1->allocateCollisionAlgorithm(sizeof(FieldBodyAlgorithm));
  return new (memory) FieldBodyAlgorithm(info, body0, body1, m_swapped);
}

FieldBodyAlgorithm::FieldBodyAlgorithm(const btCollisionAlgorithmConstructionInfo& info,
                                       const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                                       bool swapped)
    : btActivatingCollisionAlgorithm(info, body0, body1), swapped_(swapped) {
  // As btConvexTriangleCallback: a manifold of (convex, tile), cleared.
  const btCollisionObjectWrapper* convex = swapped ? body1 : body0;
  const btCollisionObjectWrapper* tile = swapped ? body0 : body1;
  manifold_ = m_dispatcher->getNewManifold(convex->getCollisionObject(), tile->getCollisionObject());
  m_dispatcher->clearManifold(manifold_);
}

FieldBodyAlgorithm::~FieldBodyAlgorithm() {
  m_dispatcher->clearManifold(manifold_);
  m_dispatcher->releaseManifold(manifold_);
}

void FieldBodyAlgorithm::processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                                          const btDispatcherInfo& dispatch_info, btManifoldResult* result) {
  const btCollisionObjectWrapper* convex = swapped_ ? body1 : body0;
  const btCollisionObjectWrapper* tile = swapped_ ? body0 : body1;
  result->setPersistentManifold(manifold_);
  TriangleCallback each(convex, tile, m_dispatcher, manifold_, dispatch_info, result);
  manifold_->setBodies(convex->getCollisionObject(), tile->getCollisionObject());
  // The tile's cells under the body's box in the tile's frame, as Bullet
  // walks them, less those beyond the body's own box.
  static_cast<const FieldTile*>(tile->getCollisionShape())->walkTriangles(&each, each.aabbMin(), each.aabbMax(), each);
  result->refreshContactPoints();
}

void FieldBodyAlgorithm::getAllContactManifolds(btManifoldArray& manifolds) { manifolds.push_back(manifold_); }

}  // namespace wtc::bullet::detail
