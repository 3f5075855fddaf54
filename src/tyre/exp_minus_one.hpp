#pragma once
// exp(-x) - 1 and (1 - exp(-x)) / x for x >= 0, the core of the traction
// law and of the tread's relaxation (internal to wtc). std::expm1 keeps the
// digits where the difference cancels; above x = 1/8 the difference is
// >= 0.1175, so std::exp (about twice as fast in glibc) loses at most 1e-15
// relative.
#include <cmath>

namespace wtc::detail {

inline double expMinusOne(double x) { return x < 0.125 ? std::expm1(-x) : std::exp(-x) - 1.0; }

/// Below this x, (1 - e^-x) / x is its series 1 - x/2 (+ x^2/6: below
/// roundoff for x < 1e-8), so there is no 0/0 at x = 0.
inline constexpr double kSeriesLimit = 1e-8;

/// (1 - exp(-x)) / x for x >= 0, given em = expMinusOne(x) (callers need em
/// too, so it is computed once).
inline double oneMinusExpOverX(double x, double em) { return x < kSeriesLimit ? 1.0 - 0.5 * x : -em / x; }

}  // namespace wtc::detail
