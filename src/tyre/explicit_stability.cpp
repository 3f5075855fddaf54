#include "wtc/tyre/explicit_stability.hpp"

#include <cmath>

#include "wtc/base/error.hpp"

namespace wtc {
namespace {

double dampingRatio(double c, double b, double m) { return b / (2.0 * std::sqrt(c * m)); }
double stepLimit(double zeta) { return 2.0 * (std::sqrt(1.0 + zeta * zeta) - zeta); }

}  // namespace

SpringStability explicitSpringStability(double c, double b, double m, double h) {
  SpringStability s;
  s.damping_ratio = dampingRatio(c, b, m);
  s.limit = stepLimit(s.damping_ratio);
  s.step_number = h * std::sqrt(c / m);
  s.stiffness = c;
  s.damping = b;
  s.mass = m;
  s.step_seconds = h;
  return s;
}

std::string describe(const SpringStability& s) {
  const double c = s.stiffness, b = s.damping, m = s.mass, h = s.step_seconds;
  return std::string(s.soil ? "soil spring" : "tyre spring") + " c = " + formatNumber(c) +
         " N/m, b = " + formatNumber(b) + " N s/m on m = " + formatNumber(m) + " kg at h = " + formatNumber(h) +
         " s: h sqrt(c/m) = " + formatNumber(s.step_number) + (s.stable() ? " < " : " >= ") + "limit " +
         formatNumber(s.limit) + " (damping ratio " + formatNumber(s.damping_ratio) + "); the largest stable step is " +
         formatNumber(largestStableStep(c, b, m)) + " s";
}

double largestStableStep(double c, double b, double m, double fraction) {
  return fraction * stepLimit(dampingRatio(c, b, m)) / std::sqrt(c / m);
}

}  // namespace wtc
