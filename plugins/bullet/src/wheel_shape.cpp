#include "wheel_shape.hpp"

namespace wtc::bullet {

WheelShape::WheelShape(btScalar free_radius, btCollisionShape* original)
    : btSphereShape(free_radius), original_(original) {
  m_shapeType = CUSTOM_CONVEX_SHAPE_TYPE;
}

void WheelShape::getAabb(const btTransform& t, btVector3& aabb_min, btVector3& aabb_max) const {
  btSphereShape::getAabb(t, aabb_min, aabb_max);
  btVector3 min_original, max_original;
  original_->getAabb(t, min_original, max_original);
  aabb_min.setMin(min_original);
  aabb_max.setMax(max_original);
}

const btCollisionShape* unwrap(const btCollisionShape* shape) {
  if (shape->getShapeType() == CUSTOM_CONVEX_SHAPE_TYPE) {
    if (const auto* wheel = dynamic_cast<const WheelShape*>(shape)) return wheel->original();
  }
  return shape;
}

}  // namespace wtc::bullet
