#include "wtc/sim/drawbar.hpp"

#include <cmath>

#include "wtc/base/constants.hpp"
#include "wtc/base/error.hpp"
#include "wtc/sim/sim_constants.hpp"

namespace wtc::sim {
namespace {

// Below this horizontal length the vehicle's x axis has no heading
// (dimensionless, of a unit vector): it points straight up or down.
constexpr double kMinHeadingLength = 1e-6;

}  // namespace

void validate(const Drawbar& d, const vehicle::VehicleDescription& vehicle, const std::string& where) {
  if (d.body < 0 || d.body >= static_cast<int>(vehicle.bodies.size())) {
    throw InvalidInputError(where + ": body " + std::to_string(d.body) + " is not a body of vehicle '" + vehicle.name +
                            "'");
  }
  if (!d.point_V.allFinite() || d.point_V.norm() > kMaxLengthM) {
    throw InvalidInputError(where + ": point must be finite and within " + formatNumber(kMaxLengthM) +
                            " m of the vehicle's origin");
  }
  if (d.force_N) {
    if (!std::isfinite(*d.force_N)) throw InvalidInputError(where + ": force must be finite (N)");
    return;
  }
  if (!std::isfinite(d.speed_mps) || std::abs(d.speed_mps) > kDivergedSpeedMps) {
    throw InvalidInputError(where + ": speed = " + formatNumber(d.speed_mps) + " m/s must be finite and at most " +
                            formatNumber(kDivergedSpeedMps) + " m/s");
  }
  if (!(d.stiffness_Npm > 0.0) || !std::isfinite(d.stiffness_Npm)) {
    throw InvalidInputError(where + ": stiffness = " + formatNumber(d.stiffness_Npm) +
                            " must be finite and > 0 (N/m) for a moving anchor");
  }
  if (!(d.damping_Nspm >= 0.0) || !std::isfinite(d.damping_Nspm)) {
    throw InvalidInputError(where + ": damping = " + formatNumber(d.damping_Nspm) + " must be finite and >= 0 (N s/m)");
  }
}

DrawbarRig::DrawbarRig(const Drawbar& drawbar, const vehicle::VehicleDescription& vehicle,
                       const vehicle::BodyKinematics& start, const std::string& where)
    : drawbar_(drawbar) {
  validate(drawbar, vehicle, where);
  const vehicle::Body& b = vehicle.bodies[drawbar.body];
  point_B_ = b.pose.inverse() * drawbar.point_V;
  // The vehicle frame's x axis in the world: R_WV = R_WB R_VB^T.
  const Eigen::Vector3d x_W = start.pose.linear() * b.pose.linear().transpose() * Eigen::Vector3d::UnitX();
  const Eigen::Vector3d horizontal(x_W.x(), x_W.y(), 0.0);
  if (horizontal.norm() < kMinHeadingLength) {
    throw InvalidInputError(where +
                            ": the vehicle's x axis is vertical at the start: no horizontal direction to pull along");
  }
  direction_W_ = horizontal.normalized();
  start_along_m_ = direction_W_.dot(start.pose * point_B_);
}

DrawbarForce DrawbarRig::force(const vehicle::BodyKinematics& body, double time) const {
  DrawbarForce f;
  f.point_W = body.pose * point_B_;
  const Eigen::Vector3d v_P = body.linear_velocity + body.angular_velocity.cross(f.point_W - body.pose.translation());
  f.point_speed_mps = direction_W_.dot(v_P);
  if (drawbar_.force_N) {
    f.pull_N = *drawbar_.force_N;
  } else {
    f.extension_m = direction_W_.dot(f.point_W) - start_along_m_ - drawbar_.speed_mps * time;
    f.pull_N =
        drawbar_.stiffness_Npm * f.extension_m + drawbar_.damping_Nspm * (f.point_speed_mps - drawbar_.speed_mps);
  }
  f.force_W = -f.pull_N * direction_W_;
  return f;
}

}  // namespace wtc::sim
