#pragma once
// Eigen <-> Bullet (internal to wtc::bullet and wtc::bullet_sim): both are
// double here (bullet-float64), so every conversion is exact.
#include <LinearMath/btMatrix3x3.h>
#include <LinearMath/btQuaternion.h>
#include <LinearMath/btTransform.h>
#include <LinearMath/btVector3.h>
#include <Eigen/Geometry>

namespace wtc::bullet {

inline btVector3 toBt(const Eigen::Ref<const Eigen::Vector3d>& v) { return {v.x(), v.y(), v.z()}; }
inline Eigen::Vector3d toEigen(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

inline btQuaternion toBtRotation(const Eigen::Matrix3d& r) {
  const Eigen::Quaterniond q(r);
  return {q.x(), q.y(), q.z(), q.w()};
}
inline Eigen::Matrix3d toEigen(const btMatrix3x3& m) {
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i) r.row(i) = toEigen(m.getRow(i)).transpose();
  return r;
}
inline btTransform toBtTransform(const Eigen::Isometry3d& t) {
  return btTransform(toBtRotation(Eigen::Matrix3d(t.linear())), toBt(t.translation()));
}

}  // namespace wtc::bullet
