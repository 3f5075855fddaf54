#include "wtc/tyre/traction_law.hpp"

#include <cmath>
#include <string>

#include "exp_minus_one.hpp"
#include "wtc/base/error.hpp"
#include "wtc/base/tolerances.hpp"

namespace wtc {

// With em = expm1(-s/s1): 1 - q = -em exactly to roundoff for small s, and
// q = 1 + em, which only feeds 1 + s2 q (absolute accuracy suffices).
double tractionCoefficient(const Material& m, double slip_ratio) {
  const double em = detail::expMinusOne(slip_ratio / m.s1);
  return m.mu_max * (-em) * (1.0 + m.s2 * (1.0 + em));
}

double tractionSecant(const Material& m, double slip_ratio) {
  const double x = slip_ratio / m.s1;
  const double em = detail::expMinusOne(x);
  return m.mu_max / m.s1 * detail::oneMinusExpOverX(x, em) * (1.0 + m.s2 * (1.0 + em));
}

double tractionInitialSlope(const Material& m) { return m.mu_max * (1.0 + m.s2) / m.s1; }

// d/ds of mu_max (1 - q) (1 + s2 q), dq/ds = -q / s1:
// mu_max (q / s1) (1 - s2 + 2 s2 q).
double tractionSlope(const Material& m, double slip_ratio) {
  const double q = std::exp(-slip_ratio / m.s1);
  return m.mu_max * q / m.s1 * (1.0 - m.s2 + 2.0 * m.s2 * q);
}

double tractionPeak(const Material& m) {
  return m.s2 <= 1.0 ? m.mu_max : m.mu_max * (1.0 + m.s2) * (1.0 + m.s2) / (4.0 * m.s2);
}

double tractionSaturationSlip(const Material& m) {
  // |mu - mu_max| = mu_max q |s2 - 1 - s2 q| <= mu_max q (1 + s2), q = e^(-s/s1).
  return m.s1 * std::log((1.0 + m.s2) / tolerance::kTractionSaturation);
}

double adhesionBoostForPeakRatio(double peak_ratio) {
  if (!(peak_ratio > 1.0) || !std::isfinite(peak_ratio)) {
    throw InvalidInputError("wtc::adhesionBoostForPeakRatio: peak_ratio = " + formatNumber(peak_ratio) +
                            " must be finite and > 1 (static over dynamic coefficient)");
  }
  const double half_b = 2.0 * peak_ratio - 1.0;
  return half_b + std::sqrt(half_b * half_b - 1.0);
}

}  // namespace wtc
