#pragma once
// Stability of an explicit spring-damper (the tyre's normal force in force
// mode). An engine's semi-implicit Euler step on m x'' = -c x - b x' has the
// amplification matrix, with a = h w, w = sqrt(c/m), zeta = b / (2 sqrt(c m)),
//   [[1 - a^2, a (1 - 2 zeta a)], [-a, 1 - 2 zeta a]],
// trace 2 - a^2 - 2 zeta a and determinant 1 - 2 zeta a. Jury's conditions
// give stability iff
//   a < 2 (sqrt(1 + zeta^2) - zeta)   (and a < 1/zeta, which is weaker):
// 2 without damping, 1.49 at zeta = 0.3 (spec section 6: "< ~2, less with
// damping"). Non-fatal: a step over the limit is reported, not refused.
#include <string>

namespace wtc {

struct SpringStability {
  double step_number = 0.0;    ///< h sqrt(c/m) (dimensionless).
  double limit = 2.0;          ///< 2 (sqrt(1 + zeta^2) - zeta) (dimensionless).
  double damping_ratio = 0.0;  ///< zeta = b / (2 sqrt(c m)) (dimensionless).
  double stiffness = 0.0;      ///< c the step saw (N/m): a wheel's contacts add theirs (a V-valley doubles it).
  double damping = 0.0;        ///< b the step saw (N s/m), summed likewise.
  double mass = 0.0;           ///< m (kg).
  double step_seconds = 0.0;   ///< h (s).
  bool soil = false;           ///< The spring is soft soil's (soft_soil effect), not the tyre's.
  bool stable() const { return step_number < limit; }
};

/// The report in words, with the stiffness, damping, mass and step it holds
/// and the largest stable step: "tyre spring c = 1e5 N/m, b = 900 N s/m on
/// m = 3.7 kg at h = 0.002 s: h sqrt(c/m) = 0.33 < limit 1.49 (damping
/// ratio 0.74); the largest stable step is 0.0031 s".
std::string describe(const SpringStability& stability);

/// The explicit stability of spring c (N/m), damper b (N s/m) on mass m (kg)
/// at step h (s). Preconditions: c, m, h > 0, b >= 0.
SpringStability explicitSpringStability(double stiffness, double damping, double mass, double step_seconds);

/// The largest step that keeps h sqrt(c/m) below `fraction` of the limit.
double largestStableStep(double stiffness, double damping, double mass, double fraction = 1.0);

}  // namespace wtc
