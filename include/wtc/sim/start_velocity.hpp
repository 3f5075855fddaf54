#pragma once
// A vehicle that starts moving (wtc::sim): the velocity each body has when
// the whole vehicle translates at one velocity with its wheels rolling,
// for the rigs that start at speed (coast-down, a locked-wheel stop:
// docs/mobility-bounds.md, "Test rigs"; a scene's `vehicle.velocity`).
//
// Every body translates at v (world); no body turns but the wheels, each
// spinning about its axle at the rate that rolls it without slip on a
// ground normal to the vehicle's z axis n:
//
//   w_wheel = ((n x v) . a) a / r_f,
//
// a the wheel's axle (world), r_f its free radius (the lever of the slip
// ratio, docs/tyre-model.md): the contact point, at -r_f n from the centre,
// then moves at v + w x (-r_f n) = v - (v - (v . a) a) = (v . a) a, nothing
// along the ground in the wheel's plane.
#include <vector>

#include <Eigen/Geometry>

#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::sim {

struct BodyVelocity {
  Eigen::Vector3d linear{Eigen::Vector3d::Zero()};   ///< The centre of mass's velocity (world, m/s).
  Eigen::Vector3d angular{Eigen::Vector3d::Zero()};  ///< The body's angular velocity (world, rad/s).
};

/// Per body of `vehicle` placed at `placement` (the vehicle frame V in the
/// world), moving at `velocity_V` (m/s, in V): each body's velocity as
/// above. Throws InvalidInputError for a velocity that is not finite or is
/// beyond kDivergedSpeedMps (a run would stop at once).
std::vector<BodyVelocity> startVelocities(const vehicle::VehicleDescription& vehicle,
                                          const Eigen::Isometry3d& placement, const Eigen::Vector3d& velocity_V);

}  // namespace wtc::sim
