#include "wtc/sim/tilt_table.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <numbers>

#include "wtc/base/constants.hpp"

namespace wtc::sim {

double TiltTable::angleRad(double t) const {
  return std::max(0.0, t - start_s) * rate_deg_s * std::numbers::pi / 180.0;
}

Eigen::Vector3d TiltTable::gravity(double t) const {
  const Eigen::Vector3d about = axis == 0 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return Eigen::AngleAxisd(-angleRad(t), about) * Eigen::Vector3d(0.0, 0.0, -kGravityMps2);
}

}  // namespace wtc::sim
