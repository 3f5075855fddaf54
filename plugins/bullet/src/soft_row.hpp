#pragma once
// The tread's soft row (implicit mode, internal to wtc::bullet), shared by
// WTC's multibody rows (wheel_friction_constraint.cpp) and Bullet's own
// friction rows of a rigid wheel (rigid_tread_rows.cpp).
//
// Both of Bullet's solvers update a row by Gauss-Seidel,
//   lambda += rhs - cfm lambda - D' dV,
// D' the row's jacDiagABInv, dV the velocity change along the row since the
// rows were made. A row whose impulse is lambda = h K (v - V+) is the soft
// row of Box2D and of Bullet's own contacts:
//   D' = 1 / (1/D + 1/(h K)),  rhs = D' (v - V),  cfm = D' / (h K),
// D the row's effective mass, V the velocity along the row when it was made.
// Its fixed point (rhs = cfm lambda + D' (V+ - V)) is lambda = h K (v - V+),
// and each update contracts (cfm < 1) at any step.
namespace wtc::bullet {

struct SoftRow {
  double jac_diag_inv;  // D' (kg)
  double rhs;           // D' (v - V) (N s)
  double cfm;           // D' / (h K) (dimensionless)
};

/// The soft row of a row of effective mass `jac_diag_inv` (D, kg) whose
/// velocity error is `velocity_error` (v - V, m/s), for `compliance`
/// 1 / (h K) (1/kg; 0 leaves the row rigid).
inline SoftRow softRow(double jac_diag_inv, double velocity_error, double compliance) {
  const double soft = 1.0 / (1.0 / jac_diag_inv + compliance);
  return {soft, velocity_error * soft, compliance * soft};
}

}  // namespace wtc::bullet
