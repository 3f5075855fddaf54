#pragma once
// The description of one wheel for the tyre model: its geometry, the tyre's
// own parameters, and the inertia its contacts accelerate. Immutable during
// a run; shared by every step. Values and their sources: docs/tyre-model.md.
#include "wtc/contact/wheel_contact.hpp"

namespace wtc {

/// Tyre parameters. The source gives none of c, b, s1, s2, eps; the defaults
/// are the project's choice for the 126 kg six-wheel robot (spec section 5):
/// c = 1e5 N/m is 2 mm of static deflection under 21 kg, b = 900 N s/m a
/// damping ratio of about 0.3.
struct TyreParameters {
  double radial_stiffness = 1e5;       ///< c (N/m), > 0.
  double radial_damping = 900.0;       ///< b (N s/m), >= 0.
  double rolling_radius_ratio = 0.97;  ///< r_0 / r_f (dimensionless, in (0, 1]); spec: 0.97.
  double slip_speed_floor = 1e-3;      ///< eps in the reported s = |V_s| / max(V_t, eps) (m/s), > 0.

  // Low speed (docs/tyre-model.md, "Standstill"). The slip law acts through
  // a tread deflection u with relaxation length sigma = mu'(0) R_z / k_t:
  // its steady state is the spec's law, and at standstill it is a spring
  // that holds a parked vehicle without creep.
  double tangential_stiffness = 1e5;      ///< k_t of the tread (N/m), > 0; a brush tyre's is close to c.
  double standstill_damping_ratio = 1.0;  ///< zeta_t of the tread spring at V_t = 0 (dimensionless, >= 0).
  double standstill_speed = 0.1;          ///< Transport speed where that damping has faded out (m/s), > 0.
  double stability_fraction = 0.4;        ///< kappa: h sqrt(k_t/m) and the rolling-resistance ramp gain
                                          ///< h k / I are held below this (dimensionless, in (0, 1]).
  double spin_floor = 1e-3;               ///< Smallest width of the sign(omega) ramp (rad/s), > 0.
};

/// What the contact forces accelerate: the stability bounds of the explicit
/// tyre springs use these. The safe value is the smallest mass a contact
/// can move alone: the wheel body's own (3.7 kg, 0.067 kg m^2 for the robot).
struct WheelInertia {
  double effective_mass = 3.7;    ///< m (kg), > 0.
  double axial_inertia = 0.0668;  ///< I about the axle (kg m^2), > 0; 0.5 m r_f^2 for a disc.
  /// Whether a drive or a brake holds the wheel's spin to its carrier (an
  /// engine's velocity motor). Along the ground a held wheel's contact moves
  /// at least m; a free wheel's moves 1 / (1/m + r_f^2 / I), m/3 for a disc,
  /// and the tread is capped for that (docs/tyre-model.md, "Stability").
  bool spin_held = false;
};

/// Where an engine adapter takes a wheel's WheelInertia from.
enum class InertiaSource {
  kBody,         ///< The body's mass and moment about the axle (the engine knows them); spin_held as given.
  kDescription,  ///< WheelDescription::inertia as given (for contacts that move more than the wheel body).
};

/// The inertia of a wheel that is its own body: its mass (kg) and the moment
/// a^T I a about the axle (I in the body frame (kg m^2), a = axle_local
/// normalized), with `spin_held` as given. Throws InvalidInputError naming
/// `where` unless both are finite and > 0 (a static body has no mass).
WheelInertia bodyInertia(double mass, const Eigen::Matrix3d& inertia_local, const Eigen::Vector3d& axle_local,
                         bool spin_held, const char* where);

struct WheelDescription {
  WheelGeometry geometry;
  TyreParameters tyre;
  WheelInertia inertia;
};

/// Throws InvalidInputError naming the field, its value and `where`.
/// Allocates nothing unless it throws (the tyre model checks every step).
void validate(const TyreParameters& tyre, const char* where);
void validate(const WheelInertia& inertia, const char* where);
void validate(const WheelDescription& wheel, const char* where);

/// What an engine adapter registers: `given`, its inertia read from the
/// wheel body (bodyInertia, keeping given.inertia.spin_held) when `source`
/// is kBody, then validated. Throws InvalidInputError naming `where`.
WheelDescription mountedDescription(WheelDescription given, InertiaSource source, double body_mass,
                                    const Eigen::Matrix3d& body_inertia_local, const Eigen::Vector3d& axle_local,
                                    const char* where);

/// How an adapter mounts a wheel on its body: the axle direction and the
/// wheel centre in the body frame. Throws InvalidInputError unless the axle
/// is finite and non-zero and the centre finite.
void validateMounting(const Eigen::Vector3d& axle_local, const Eigen::Vector3d& centre_local, const char* where);

}  // namespace wtc
