#pragma once
// exp(-x) - 1 for x >= 0, the core of the traction law and of the tread's
// relaxation (internal to wtc). std::expm1 keeps the digits where the
// difference cancels; above x = 1/8 the difference is >= 0.1175, so
// std::exp (about twice as fast in glibc) loses at most 1e-15 relative.
#include <cmath>

namespace wtc::detail {

inline double expMinusOne(double x) { return x < 0.125 ? std::expm1(-x) : std::exp(-x) - 1.0; }

}  // namespace wtc::detail
