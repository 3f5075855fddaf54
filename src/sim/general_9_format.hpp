#pragma once
// A double as printf's "%.9g" writes it (std::to_chars(..., general, 9) is
// specified to give the same bytes), for the recorder's CSV series, without
// std::to_chars's arbitrary-precision machinery where it is not needed.
//
// Design: a finite |x| = m 2^E (m the 53-bit integer significand) whose
// decimal exponent e = floor(log10 |x|) lies in [-19, 8] (1e-19 <= |x| <
// 1e9, the magnitudes of the series) is scaled to y = |x| 10^(8-e) =
// m 5^k 2^(E+k), k = 8 - e in [0, 27], in integers: m 5^k < 2^53 2^63 fits
// in 128 bits and is exact, and y is that product shifted right, so floor(y)
// and whether the bits shifted out are below, at or above one half are
// exact too. The 9 digits are round(y): nothing is approximated, so no
// margin is needed (e comes from the binary exponent and a table of
// doubles near 10^j, and floor(y) in [10^8, 10^9) checks it exactly). The
// digits are split in a register and stored as words. What this path
// leaves to std::to_chars: |x| < 1e-19 and |x| >= 1e9, subnormals,
// infinities, NaN, and exact ties at the 9th digit (printf rounds them to
// even; they are rare enough not to repeat that here).
// Layout (C17 7.21.6.1, %g with precision P = 9): X the exponent of the
// rounded value; fixed notation with P-1-X decimals when -4 <= X < P,
// otherwise d.dddddddde±XX (at least two exponent digits); trailing zeros
// and a trailing point removed; '-' for every negative, -0 included.

namespace wtc::sim {

/// Room formatGeneral9 needs: the longest "%.9g" ("-1.23456789e-308") and
/// the fixed-size copies the layout makes past the end of its text.
inline constexpr int kGeneral9Chars = 24;

/// Writes `value` as "%.9g" to `out` and returns the end of the text (no
/// terminating NUL). Any double, NaN and inf included. out[0,
/// kGeneral9Chars) must be writable; bytes past the returned end are
/// scratch.
char* formatGeneral9(double value, char* out);

}  // namespace wtc::sim
