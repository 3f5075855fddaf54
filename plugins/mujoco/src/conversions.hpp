#pragma once
// MuJoCo's arrays as Eigen values (internal to wtc::mujoco).
#include <mujoco/mujoco.h>
#include <Eigen/Geometry>

namespace wtc::mujoco {

inline Eigen::Vector3d vec3(const mjtNum* v) { return {v[0], v[1], v[2]}; }
/// A 3 x 3 row-major matrix (mjData::xmat, ximat).
inline Eigen::Matrix3d mat3(const mjtNum* m) {
  Eigen::Matrix3d r;
  r << m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8];
  return r;
}
/// A unit quaternion w, x, y, z (mjModel::body_iquat) as a rotation.
inline Eigen::Matrix3d quatMat(const mjtNum* q) {
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).toRotationMatrix();
}

/// A body's spin and the velocity of its material point at `point` (world
/// axes) from cvel (mj_objectVelocity gives them at the centre of mass).
struct PointVelocity {
  Eigen::Vector3d angular;  ///< rad/s.
  Eigen::Vector3d linear;   ///< m/s, of the point.
};
inline PointVelocity velocityAt(const mjModel& m, const mjData& d, int body, const Eigen::Vector3d& point) {
  mjtNum spin_velocity[6];
  mj_objectVelocity(&m, &d, mjOBJ_BODY, body, spin_velocity, 0);
  const Eigen::Vector3d angular = vec3(spin_velocity);
  return {angular, vec3(spin_velocity + 3) + angular.cross(point - vec3(d.xipos + 3 * body))};
}

}  // namespace wtc::mujoco
