#pragma once
// The collision shape of a WTC wheel in Bullet. Plugin::addWheel gives the
// wheel body this shape, wrapping the body's own shape:
//  - against the WTC terrain, the pair is WTC's (the plugin's collision
//    algorithm: modified-GJK contacts, no GJK/EPA);
//  - against anything else, Bullet collides the wrapped original shape as
//    before (a cylinder hitting a chassis stays a cylinder).
// Its type is CUSTOM_CONVEX_SHAPE_TYPE, so no built-in algorithm sees it; its
// AABB covers both the wrapped shape and the sphere of the free radius.
#include <btBulletCollisionCommon.h>

namespace wtc::bullet {

class WheelShape : public btSphereShape {
 public:
  /// `original` (not owned) must outlive this shape; `free_radius` (m) > 0.
  WheelShape(btScalar free_radius, btCollisionShape* original);

  btCollisionShape* original() const { return original_; }
  void getAabb(const btTransform& t, btVector3& aabb_min, btVector3& aabb_max) const override;
  const char* getName() const override { return "WtcWheel"; }

 private:
  btCollisionShape* original_;
};

/// The shape Bullet's algorithms should see for `shape`: the wrapped one for a
/// WheelShape, else `shape` itself.
const btCollisionShape* unwrap(const btCollisionShape* shape);

}  // namespace wtc::bullet
