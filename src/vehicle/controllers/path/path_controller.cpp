#include "wtc/vehicle/controllers/path_controller.hpp"

#include <cmath>

#include "wtc/base/error.hpp"

namespace wtc::vehicle {
namespace {

int drivenBody(const VehicleDescription& v, const std::string& name, const std::string& where, const char* what) {
  const int b = v.find(name);
  if (b < 0 || !v.bodies[b].joint.actuator || !v.bodies[b].wheel) {
    throw InvalidInputError(where + ": " + what + " '" + name + "' is not a driven wheel of vehicle '" + v.name + "'");
  }
  return b;
}

}  // namespace

PathController::PathController(const VehicleDescription& v, const PathControllerParams& p, const std::string& where)
    : params_(p) {
  body_ = v.find(p.body);
  if (body_ < 0) throw InvalidInputError(where + ": body '" + p.body + "' is not in vehicle '" + v.name + "'");
  left_ = drivenBody(v, p.left_drive, where, "left_drive");
  right_ = drivenBody(v, p.right_drive, where, "right_drive");
  if (!std::isfinite(p.lead) || p.lead <= 0.0) {
    throw InvalidInputError(where + ": lead " + formatNumber(p.lead) + " m must be > 0 (C ahead of the axle)");
  }
  if (!std::isfinite(p.gain_x) || !std::isfinite(p.gain_y) || p.gain_x < 0.0 || p.gain_y < 0.0) {
    throw InvalidInputError(where + ": gains must be finite and >= 0");
  }
  if (std::isnan(p.end_time) || p.end_time <= 0.0) {
    throw InvalidInputError(where + ": end_time " + formatNumber(p.end_time) + " s must be > 0");
  }
  if (!std::isfinite(p.max_tracking_error) || p.max_tracking_error <= 0.0) {
    throw InvalidInputError(where + ": max_tracking_error must be > 0 m");
  }
  for (int i = 0; i < 6; ++i) {
    if (!std::isfinite(p.x_coefficients[i]) || !std::isfinite(p.y_coefficients[i])) {
      throw InvalidInputError(where + ": path coefficient " + std::to_string(i) + " is not finite");
    }
  }
  const Body& l = v.bodies[left_];
  const Body& r = v.bodies[right_];
  radius_ = l.wheel->geometry.free_radius;
  if (r.wheel->geometry.free_radius != radius_) {
    throw InvalidInputError(where + ": the drive wheels have different radii");
  }
  // The controller steers by the body's own axes (x forward, y left), not
  // the principal axes the engines integrate it in (a URDF tensor with
  // products of inertia turns those).
  own_axes_ = v.bodies[body_].own_axes;
  // Both wheels' centres in the body's own frame; the axle is the line between.
  const Eigen::Isometry3d to_body = ownFrame(v.bodies[body_], v.bodies[body_].pose).inverse();
  const Eigen::Vector3d pl = to_body * l.pose.translation(), pr = to_body * r.pose.translation();
  if (pl.y() <= pr.y() || std::abs(pl.x() - pr.x()) > 1e-9) {
    throw InvalidInputError(where + ": left_drive must be left of right_drive (+y) on one axle across the body");
  }
  axle_mid_local_ = 0.5 * (pl + pr);
  half_track_ = 0.5 * (pl - pr).norm();
}

Eigen::Vector2d PathController::desired(double t) const {
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  double power = 1.0;
  for (int i = 0; i < 6; ++i, power *= t)
    c += power * Eigen::Vector2d(params_.x_coefficients[i], params_.y_coefficients[i]);
  return c;
}

Eigen::Vector2d PathController::desiredVelocity(double t) const {
  Eigen::Vector2d v = Eigen::Vector2d::Zero();
  double power = 1.0;
  for (int i = 1; i < 6; ++i, power *= t)
    v += i * power * Eigen::Vector2d(params_.x_coefficients[i], params_.y_coefficients[i]);
  return v;
}

Eigen::Vector2d PathController::pointC(const Eigen::Isometry3d& pose) const {
  const Eigen::Vector3d c = pose * (own_axes_ * (axle_mid_local_ + params_.lead * Eigen::Vector3d::UnitX()));
  return c.head<2>();
}

void PathController::update(const VehicleState& state, std::span<DriveCommand> commands) {
  const Eigen::Isometry3d& pose = state.bodies[body_].pose;
  const Eigen::Vector3d forward = pose.linear() * own_axes_.col(0);
  const double psi = std::atan2(forward.y(), forward.x());
  const Eigen::Vector2d heading(std::cos(psi), std::sin(psi)), left(-std::sin(psi), std::cos(psi));

  // After the path's end, or once the path is lost, the drive wheels are
  // told to stop (a tug that cannot follow must not chase; holding a point
  // by steering C would turn the tug to and fro against the hitch). The
  // error is then measured to the path's last point.
  const double t = std::min(state.time, params_.end_time);
  const Eigen::Vector2d error = desired(t) - pointC(pose);
  const bool stop = lost_ || state.time >= params_.end_time;
  const Eigen::Vector2d u =
      stop ? Eigen::Vector2d::Zero()
           : Eigen::Vector2d(desiredVelocity(t) + Eigen::Vector2d(params_.gain_x, params_.gain_y).cwiseProduct(error));
  const double speed = u.dot(heading);
  const double yaw_rate = u.dot(left) / params_.lead;
  commands[right_] = {.mode = DriveMode::kVelocity, .value = (speed + yaw_rate * half_track_) / radius_};
  commands[left_] = {.mode = DriveMode::kVelocity, .value = (speed - yaw_rate * half_track_) / radius_};

  last_error_ = error.norm();
  max_error_ = std::max(max_error_, last_error_);
  sum_sq_error_ += last_error_ * last_error_;
  ++samples_;
  if (!lost_ && last_error_ > params_.max_tracking_error) {
    lost_ = true;
    lost_time_ = state.time;
  }
}

void PathController::summarize(std::map<std::string, double>& fields) const {
  fields["max_tracking_error_m"] = max_error_;
  fields["rms_tracking_error_m"] = samples_ > 0 ? std::sqrt(sum_sq_error_ / static_cast<double>(samples_)) : 0.0;
  fields["final_tracking_error_m"] = last_error_;
}

std::string PathController::failure() const {
  if (!lost_) return {};
  return "path lost at t = " + formatNumber(lost_time_) + " s: the tracking error passed " +
         formatNumber(params_.max_tracking_error) + " m";
}

}  // namespace wtc::vehicle
