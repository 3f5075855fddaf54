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

}  // namespace wtc::mujoco
