#include "wtc/sim/start_velocity.hpp"

#include "wtc/base/error.hpp"
#include "wtc/sim/sim_constants.hpp"

namespace wtc::sim {

std::vector<BodyVelocity> startVelocities(const vehicle::VehicleDescription& vehicle,
                                          const Eigen::Isometry3d& placement, const Eigen::Vector3d& velocity_V) {
  if (!velocity_V.allFinite() || velocity_V.norm() > kDivergedSpeedMps) {
    throw InvalidInputError("wtc::sim::startVelocities: velocity (" + formatNumber(velocity_V.x()) + ", " +
                            formatNumber(velocity_V.y()) + ", " + formatNumber(velocity_V.z()) +
                            ") m/s must be finite and at most " + formatNumber(kDivergedSpeedMps) + " m/s");
  }
  const Eigen::Matrix3d R_WV = placement.linear();
  const Eigen::Vector3d v_W = R_WV * velocity_V;
  const Eigen::Vector3d n_W = R_WV.col(2);
  std::vector<BodyVelocity> velocities(vehicle.bodies.size());
  for (std::size_t i = 0; i < vehicle.bodies.size(); ++i) {
    const vehicle::Body& b = vehicle.bodies[i];
    velocities[i].linear = v_W;
    if (!b.wheel) continue;
    const Eigen::Vector3d a_W = (R_WV * b.pose.linear() * b.wheel->axle).normalized();
    velocities[i].angular = n_W.cross(v_W).dot(a_W) / b.wheel->geometry.free_radius * a_W;
  }
  return velocities;
}

}  // namespace wtc::sim
