#pragma once
// The towed system's trajectory controller (vehicles spec, section 2; the
// source's law), for any vehicle with a differential drive (wtc::vehicle):
//
// A point C, fixed at `lead` ahead of the drive axle's midpoint A along the
// body's forward axis, follows a path given as polynomials in time,
//   Xc*(t) = sum a_i t^i,   Yc*(t) = sum b_i t^i   (degree <= 5, world).
// Its commanded velocity is the path's plus a proportional correction,
//   u = dC*/dt + diag(Kx, Ky) (C* - C).
// With heading psi, forward speed V of A and yaw rate Omega (no slip
// assumed), dC/dt = V (cos psi, sin psi) + lead Omega (-sin psi, cos psi),
// which is invertible because lead > 0:
//   V = u . (cos psi, sin psi),   Omega = u . (-sin psi, cos psi) / lead.
// The drive wheels are told omega_R,L = (V +- Omega d) / R (d the half
// track, R the wheel radius); their motors hold these within their limits.
//
// The controller watches its own tracking error |C* - C|: once it exceeds
// max_tracking_error the path is lost, the drive wheels are told to stop,
// and the run fails and says so. At end_time the path ends: the drive
// wheels are told to stop there too (polynomials run away outside the time
// they were made for).
#include <array>
#include <limits>
#include <string>

#include "wtc/vehicle/controller.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::vehicle {

struct PathControllerParams {
  std::string body;                        ///< The driven body (the tug).
  std::string left_drive;                  ///< Its left drive wheel (a driven body on the left, +y).
  std::string right_drive;                 ///< Its right drive wheel.
  double lead = 1.0;                       ///< Distance of C ahead of the axle midpoint (m), > 0.
  std::array<double, 6> x_coefficients{};  ///< a_0 .. a_5 (m, m/s, ... m/s^5).
  std::array<double, 6> y_coefficients{};  ///< b_0 .. b_5.
  double gain_x = 1.0;                     ///< Kx (1/s), >= 0.
  double gain_y = 1.0;                     ///< Ky (1/s), >= 0.
  double max_tracking_error = 0.5;         ///< Beyond it the path is lost (m), > 0.
  /// The path's end (s), > 0: from then on the drive wheels stop.
  double end_time = std::numeric_limits<double>::infinity();
};

class PathController final : public Controller {
 public:
  /// Throws InvalidInputError naming `where` and the parameter: unknown or
  /// undriven bodies, wheels of different radii or not on one axle, a
  /// non-positive lead, negative gains, non-finite coefficients.
  PathController(const VehicleDescription& vehicle, const PathControllerParams& params, const std::string& where);

  void update(const VehicleState& state, std::span<DriveCommand> commands) override;
  /// max_tracking_error_m, rms_tracking_error_m, final_tracking_error_m.
  void summarize(std::map<std::string, double>& fields) const override;
  bool failed() const override { return lost_; }
  std::string failure() const override;

  /// The path's point and velocity at time t (world, m and m/s).
  Eigen::Vector2d desired(double t) const;
  Eigen::Vector2d desiredVelocity(double t) const;
  /// Where C is for the body's pose (its centre-of-mass frame, as the
  /// engines give it; world x, y).
  Eigen::Vector2d pointC(const Eigen::Isometry3d& body_pose) const;

 private:
  PathControllerParams params_;
  int body_ = -1, left_ = -1, right_ = -1;
  Eigen::Matrix3d own_axes_{Eigen::Matrix3d::Identity()};    // Body::own_axes: the axes it steers by
  Eigen::Vector3d axle_mid_local_{Eigen::Vector3d::Zero()};  // A in the body's own frame
  double half_track_ = 0.0, radius_ = 0.0;
  double max_error_ = 0.0, sum_sq_error_ = 0.0, last_error_ = 0.0, lost_time_ = 0.0;
  long samples_ = 0;
  bool lost_ = false;
};

}  // namespace wtc::vehicle
