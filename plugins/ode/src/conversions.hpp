#pragma once
// Eigen <-> ODE (internal to wtc::ode and wtc::ode_sim): Debian's ODE is
// built with dDOUBLE, so every conversion is exact.
#include <ode/ode.h>
#include <Eigen/Core>

namespace wtc::ode {

inline Eigen::Vector3d toEigen(const dReal* v) { return {v[0], v[1], v[2]}; }

// ODE's dMatrix3 is row-major with a stride of 4.
inline void toOde(const Eigen::Matrix3d& r, dMatrix3 m) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m[4 * i + j] = r(i, j);
    m[4 * i + 3] = 0.0;
  }
}
inline Eigen::Matrix3d rotationFromOde(const dReal* m) {
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) r(i, j) = m[4 * i + j];
  }
  return r;
}

}  // namespace wtc::ode
