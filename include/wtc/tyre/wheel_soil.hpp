#pragma once
// The stresses of soft soil on a rigid wheel, integrated over the contact
// arc (docs/soft-soil.md), after Wong & Reece (1967) and Ishigami, Miwa,
// Nagatani & Yoshida (2007, J. Field Robotics 24(3)). Angles from the
// downward vertical, positive toward the wheel's travel: the rim meets the
// soil at the entry angle theta_1 = acos(1 - z / r) and leaves it at the
// exit angle theta_2 = -acos(1 - lambda z / r) (0 unless the soil rebounds).
//
//   sigma(theta) = (k_c / b + k_phi) r^n (cos theta - cos theta_1)^n          theta_m <= theta <= theta_1
//   sigma(theta) = (k_c / b + k_phi) r^n (cos theta* - cos theta_1)^n,
//       theta* = theta_1 - (theta - theta_2) / (theta_m - theta_2) (theta_1 - theta_m)   below theta_m
//   theta_m = (a_0 + a_1 i) theta_1
//   j(theta)   = r [p (theta_1 - theta) - q (sin theta_1 - sin theta)]     (shear displacement)
//   j_y(theta) = r q (theta_1 - theta) tan beta                             (side slip)
//   tau = sign(j) (c + sigma tan phi) (1 - exp(-|j| / K))
// with p = 1, q = 1 - i when driving (Ishigami's j) and p = 1 + i, q = 1
// when braking (the same slip over the time the ground takes to pass).
// On the wheel (b the width):
//   W  = r b int (sigma cos theta + tau sin theta) d theta      up
//   DP = r b int (tau cos theta - sigma sin theta) d theta      forward
//   T  = r^2 b int tau d theta                                  resisting the spin
//   F_y = -(r b int tau_y d theta + F_u)                        against the side slip
// F_u the bulldozing of the wheel's leading side (Ishigami et al. 2007, after
// Bekker's passive earth pressure), with h(theta) = r (cos theta - cos theta_1):
//   F_u = int R_b(h) (r - h cos theta) d theta,  R_b = D_1 c h + D_2 rho g h^2,
//   D_1 = cot X_c + tan(X_c + phi),  D_2 = (cot X_c + cot^2 X_c / cot phi) / 2,  X_c = 45 deg - phi / 2.
//
// Ground that remembers (issue 55): a point the soil has been loaded at
// keeps its plastic sinkage z_p (below the fresh surface) and the largest
// stress sigma_m it carried. At a depth Z below the fresh surface it answers
// along Wong's unloading-reloading line up to the virgin curve:
//   sigma = min(k_u (Z - z_p), max(sigma_m, k Z^n))   for Z > z_p, else 0,
// k = k_c / b + k_phi, k_u the soil's unloading stiffness; a fresh point
// answers k Z^n. The rim then enters the soil where it meets the remembered
// surface, Z(theta_1) = z_p, and the angles above follow from that entry.
//
// A ball (a ball caster: a wheel whose tread is a whole sphere) is a stack
// of discs across its rolling axle (strip theory): the slice y off the
// centre line has radius rho = sqrt(r^2 - y^2) and sinkage z - (r - rho),
// and carries the rim's stresses above per unit width, with Bekker's b the
// patch's width 2 a, a = sqrt(z (2 r - z)) (its smaller dimension: a round
// patch). The slices' stresses act in their planes (the sphere's normal
// leans y / r along the axle; on a symmetric patch that part cancels) and
// the ball's spin about the surface normal meets no resistance.
//   W = int_{-a}^{a} W_rim(rho(y), z - r + rho(y)) / b dy, and so DP, T, F_y.
// Small sinkage, at rest: W -> 2 pi r k z^(n + 1) / (n + 1), the pressure
// k Z^n over the paraboloid Z = z - (x^2 + y^2) / 2 r (docs/soft-soil.md).
#include "wtc/terrain/soil.hpp"

namespace wtc {

/// What the ground remembers at a point.
struct SoilMemory {
  double plastic_sinkage = 0.0;  ///< z_p, the surface below the fresh one (m); < 0 where raised.
  double max_pressure = 0.0;     ///< sigma_m, the largest normal stress it carried (Pa).
  bool fresh = true;             ///< Never loaded: the virgin curve from the fresh surface.
};

/// The ground's memory along a wheel's travel, at `ahead` (m) from below the
/// rim's lowest point (negative behind it).
class SoilMemoryProfile {
 public:
  virtual ~SoilMemoryProfile() = default;
  virtual SoilMemory at(double ahead) const = 0;
  /// The memory `aside` (m) off that line along the axle laid on the
  /// surface (a ball's slices read beside its centre line). By default the
  /// line's own: a profile that knows one line.
  virtual SoilMemory beside(double ahead, double aside) const {
    static_cast<void>(aside);
    return at(ahead);
  }
};

/// Wong's repetitive loading at depth Z below the fresh surface (m), for a
/// wheel of width b (m): the stress the box above states (Pa).
double reloadStress(const Soil& soil, double width, const SoilMemory& memory, double depth);

/// What a point remembers once the rim has pressed it to depth Z below the
/// fresh surface (m): the foot of the unloading line it is on and the stress
/// it carried,
///   z_p' = max(z_p, Z - sigma / k_u),   sigma_m' = max(sigma_m, sigma),
/// sigma = reloadStress(soil, width, before, Z). Where sigma is 0 (the rim
/// above the remembered surface) nothing changes. Idempotent: a wheel at
/// rest presses the same nodes every step and they stay as they are.
SoilMemory pressedSoil(const Soil& soil, double width, const SoilMemory& before, double depth);

/// A wheel's state against a flat soil surface, in its travel frame.
struct WheelSoilState {
  double radius = 0.0;      ///< r (m, > 0).
  double width = 0.0;       ///< b (m, > 0).
  double sinkage = 0.0;     ///< z, the rim's lowest point below the surface (m, [0, r]).
  double slip = 0.0;        ///< i in [-1, 1]: 1 - v / (r omega) driving, r omega / v - 1 braking.
  double slip_angle = 0.0;  ///< beta = atan(v_y / v_x) (rad, (-pi/2, pi/2)); > 0 sliding toward +axle.
  /// How far the contact is made symmetric, in [0, 1]: 0 the rolling
  /// wheel's arc (theta_2, theta_m as above), 1 a wheel at rest in its own
  /// hollow (theta_2 = -theta_1, theta_m = 0, no compaction resistance,
  /// and no shear: j and j_y scale with 1 - symmetry).
  double symmetry = 0.0;
  /// The ground's memory under the wheel, or none (a fresh surface). With
  /// one, `sinkage` is measured below the fresh surface and may exceed r
  /// in a rut.
  const SoilMemoryProfile* memory = nullptr;
};

/// What the soil does to the wheel.
struct WheelSoilForces {
  double normal = 0.0;            ///< W (N), along the surface normal.
  double drawbar_pull = 0.0;      ///< DP (N), along the travel.
  double torque = 0.0;            ///< T (N m), resisting the spin (the drive supplies it).
  double lateral = 0.0;           ///< F_y (N), along the axle: shear and bulldozing.
  double bulldozing = 0.0;        ///< F_u (N, >= 0), its bulldozing part's size.
  double entry_angle = 0.0;       ///< theta_1 (rad).
  double exit_angle = 0.0;        ///< theta_2 (rad, <= 0).
  double max_stress_angle = 0.0;  ///< theta_m (rad).
  double peak_stress = 0.0;       ///< sigma at theta_m (Pa): what the soil there has carried.
  /// The patch the soil touches (m^2): b r (sin theta_1 - sin theta_2) under
  /// a wheel, the slices' sum under a ball.
  double patch_area = 0.0;
};

/// The stresses integrated over the arc (Gauss-Legendre on [theta_2, theta_m]
/// and [theta_m, theta_1], where sigma is smooth). Preconditions: a
/// validated soil, the state in its stated ranges (TyreModel checks both).
WheelSoilForces wheelSoilForces(const Soil& soil, const WheelSoilState& state);

/// A ball's state against a flat soil surface, in its travel frame: t the
/// way its centre and its lowest point move over the surface together, the
/// axle a = n x t it rolls about (n the surface's normal).
struct SphereSoilState {
  double radius = 0.0;           ///< r (m, > 0).
  double sinkage = 0.0;          ///< z, its lowest point below the surface (m; below the fresh one with a memory).
  double travel_speed = 0.0;     ///< v = V . t (m/s).
  double rim_speed = 0.0;        ///< r omega . a (m/s): a slice of radius rho slips at soilSlip(v, rim rho / r).
  double side_slip_speed = 0.0;  ///< The lowest point's speed along a (m/s): beta = atan2(it, max(v, floor)).
  double speed_floor = 0.0;      ///< soilSlip's floor (m/s, > 0).
  double symmetry = 0.0;         ///< As WheelSoilState::symmetry.
  const SoilMemoryProfile* memory = nullptr;  ///< As WheelSoilState::memory, read beside the line per slice.
};

/// The slices' stresses summed (Gauss-Legendre across the patch, each slice
/// as wheelSoilForces without bulldozing); the angles and peak stress are
/// the centre line's, and the bulldozing that of its side, whose section is
/// the same circle of radius r a wheel's side has. Preconditions as
/// wheelSoilForces'.
WheelSoilForces sphereSoilForces(const Soil& soil, const SphereSoilState& state);

/// The steady state of a wheel carrying `load` (N) at slip `slip` and slip
/// angle `slip_angle`: the sinkage where W = load (bisection; W grows with
/// z) and the forces there. Throws InvalidInputError if the load is not
/// finite and > 0, or the soil cannot carry it before the axle sinks in
/// (naming the load and the most the soil carries).
struct SoilSteadyState {
  double sinkage = 0.0;  ///< z (m).
  WheelSoilForces forces;
};
SoilSteadyState steadyWheelOnSoil(const Soil& soil, double radius, double width, double load, double slip,
                                  double slip_angle = 0.0, const SoilMemoryProfile* memory = nullptr);

/// Terramechanics' slip from the travel speed v and the rim speed r omega
/// (both along the travel): (r omega - v) / max(|r omega|, |v|, floor),
/// clamped to [-1, 1]: 1 - v / (r omega) driving, r omega / v - 1 braking,
/// fading to 0 below `floor` (m/s) where neither is defined.
double soilSlip(double travel_speed, double rim_speed, double floor);

}  // namespace wtc
