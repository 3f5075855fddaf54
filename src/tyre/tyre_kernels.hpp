#pragma once
// The per-contact force kernels of the tyre model, one compiled per
// combination of force effects (internal to wtc; see tyre_model.hpp).
#include <array>
#include <span>

#include <Eigen/Core>

#include "wtc/terrain/material.hpp"
#include "wtc/tyre/tyre_model.hpp"

namespace wtc::detail {

/// Everything a kernel reads, prepared once per wheel step.
struct KernelInputs {
  std::span<const Material> materials;
  const WheelMotion* motion = nullptr;
  Eigen::Vector3d axle{Eigen::Vector3d::UnitY()};  ///< a, unit.
  double free_radius = 0.0;                        ///< r_f (m).
  double rolling_radius = 0.0;                     ///< r_0 (m).
  double stiffness = 0.0;                          ///< c (N/m).
  double damping = 0.0;                            ///< b (N s/m).
  double step = 0.0;                               ///< h (s).
  double transport_speed = 0.0;                    ///< V_t = |V_O| (m/s).
  double slip_speed_floor = 0.0;                   ///< eps (m/s).
  double sticking = 0.0;                           ///< (1 - V_t / eps)+: 1 at rest, 0 from V_t = eps.
  /// The engine solves the tread (implicit mode): the kernel also makes
  /// the tread's rows (ContactForce::tread_rows).
  bool implicit_tread = false;
  /// The tread's spring along its two axes, the rolling direction and the
  /// axle's (index kRolling, kLateral): each capped for the mass its
  /// contact moves that way (tyre_model.hpp).
  std::array<double, 2> tread_stiffness{};     ///< k_t (N/m).
  std::array<double, 2> tread_damping_time{};  ///< tau (s), faded with V_t.
  double spin_ramp_gain = 0.0;                 ///< h / (kappa I) (s / (kg m^2)): ramp width per N m.
  double spin_floor = 0.0;                     ///< Smallest ramp width (rad/s).
  double travel_ramp_gain = 0.0;               ///< h / (kappa m) (s/kg): soft soil's rest ramp per N of pull.
};

/// A force kernel: the forces of `contacts` into `out`, the tread's next state into `tread_out`.
using Kernel = void (*)(const KernelInputs&, std::span<const WheelContact> contacts,
                        std::span<const TreadState> tread_in, std::vector<TreadState>& tread_out, ContactForce* out);

/// The tread axes: along the ground under the rolling wheel, and along the axle.
inline constexpr int kRolling = 0, kLateral = 1;

enum class Traction { kNone, kSlipLaw, kCoulomb };

/// The index of the kernel compiled for this combination of force effects.
int selectKernel(bool damping, Traction traction, bool rolling_resistance);
/// The kernel of an index selectKernel gave.
Kernel kernel(int index);

}  // namespace wtc::detail
