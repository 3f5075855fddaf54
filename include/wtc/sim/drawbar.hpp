#pragma once
// A drawbar rig (wtc::sim): a horizontal pull at a point of one body, the
// test rig of drawbar pull against slip (docs/mobility-bounds.md, "Test
// rigs"; a scene's `drawbar`). Design note:
//
// The pull acts along d, the vehicle's x axis at the start projected on the
// horizontal plane, backward: the force on the body at the point P is
// -F d. Either F is given (a constant pull, N), or the rig is an anchor
// moving forward along d at a set speed V from where P starts, tied to P by
// a spring k and damper c along d:
//
//   e = d . (p_P(t) - p_P(0)) - V t,      F = k e + c (d . v_P - V),
//
// so the vehicle settles at the anchor's speed V pulling F against it, and
// imposing V with the wheels' rate imposes the slip. An imposed slip is
// stable on the falling branch of a slip law whose peak is above mu_max,
// where an imposed force is not (more slip, less pull). The rig is outside
// the vehicle: its work, F . v_P per step, enters the energy balance as a
// source (EnergyBalance::step).
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "wtc/vehicle/controller.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::sim {

/// The rig as a scene gives it.
struct Drawbar {
  int body = -1;                                     ///< The body pulled (an index of the vehicle's bodies).
  Eigen::Vector3d point_V{Eigen::Vector3d::Zero()};  ///< P in the vehicle frame at the reference (m).
  std::optional<double> force_N;                     ///< A constant pull F (N); none: the moving anchor.
  double speed_mps = 0.0;                            ///< The anchor's speed V along d (m/s).
  double stiffness_Npm = 0.0;                        ///< k (N/m), > 0 for the anchor.
  double damping_Nspm = 0.0;                         ///< c (N s/m), >= 0.
};

/// The pull of one step.
struct DrawbarForce {
  Eigen::Vector3d force_W{Eigen::Vector3d::Zero()};  ///< On the body at point_W (N, world): -pull d.
  Eigen::Vector3d point_W{Eigen::Vector3d::Zero()};  ///< P now (m, world).
  double pull_N = 0.0;                               ///< F, positive backward (N).
  double extension_m = 0.0;                          ///< e (m; 0 for a constant pull).
  double point_speed_mps = 0.0;                      ///< d . v_P (m/s).
};

/// The rig placed on a vehicle at its start.
class DrawbarRig {
 public:
  /// `start` is the pulled body's state at the start. Throws
  /// InvalidInputError naming `where` for a body the vehicle does not have,
  /// a non-finite or far point, neither or both of a force and an anchor,
  /// k <= 0 or c < 0 for an anchor, and a vehicle whose x axis is vertical
  /// at the start (no horizontal d).
  DrawbarRig(const Drawbar& drawbar, const vehicle::VehicleDescription& vehicle, const vehicle::BodyKinematics& start,
             const std::string& where);

  /// The pull at `time` (s since the start) on the body in state `body`.
  DrawbarForce force(const vehicle::BodyKinematics& body, double time) const;

  int body() const { return drawbar_.body; }
  /// d (world, unit, horizontal).
  const Eigen::Vector3d& direction() const { return direction_W_; }

 private:
  Drawbar drawbar_;
  Eigen::Vector3d point_B_;      // P in the body's frame (m)
  Eigen::Vector3d direction_W_;  // d
  double start_along_m_;         // d . p_P(0)
};

/// Checks `drawbar` alone, as DrawbarRig does (for a reader that wants the
/// error before anything runs).
void validate(const Drawbar& drawbar, const vehicle::VehicleDescription& vehicle, const std::string& where);

}  // namespace wtc::sim
