#include "general_9_format.hpp"

#include <array>
#include <bit>
#include <cassert>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace wtc::sim {

namespace {

__extension__ typedef unsigned __int128 Uint128;  // GCC's, exact 64 x 64 -> 128-bit products

constexpr int kPrecision = 9;                          // significant digits
constexpr std::uint64_t kLowest9Digits = 100'000'000;  // 10^8
constexpr std::uint64_t kPast9Digits = 1'000'000'000;  // 10^9
// IEEE 754 binary64 fields.
constexpr int kFractionBits = 52;
constexpr int kExponentBias = 1023;
constexpr int kExponentAllOnes = 0x7ff;
constexpr std::uint64_t kFractionMask = (std::uint64_t{1} << kFractionBits) - 1;
// The largest k with 5^k < 2^64: m 5^k (m < 2^53) then fits in 128 bits.
constexpr int kMaxScale = 27;
// Exponents fixed notation is used for (C17 7.21.6.1: -4 <= X < P).
constexpr int kLowestFixedExponent = -4;

constexpr std::array<std::uint64_t, kMaxScale + 1> kPowersOf5 = [] {
  std::array<std::uint64_t, kMaxScale + 1> p{};
  p[0] = 1;
  for (int k = 1; k <= kMaxScale; ++k) p[k] = p[k - 1] * 5;
  return p;
}();
static_assert(kPowersOf5[kMaxScale] < (std::uint64_t{1} << 63));

// The decimal exponents the exact path covers: scales k = 8 - e in [0, kMaxScale].
constexpr int kLowestExponent = kPrecision - 1 - kMaxScale;  // -19
constexpr int kHighestExponent = kPrecision - 1;             // 8
// 10^j for j in [kLowestExponent, kHighestExponent + 1], each the double
// nearest to it (the compiler rounds the literals): they only choose which
// scale to try, and the scaled value is checked exactly afterwards.
constexpr std::array<double, kHighestExponent - kLowestExponent + 2> kPowersOf10 = {
    1e-19, 1e-18, 1e-17, 1e-16, 1e-15, 1e-14, 1e-13, 1e-12, 1e-11, 1e-10, 1e-9, 1e-8, 1e-7, 1e-6, 1e-5,
    1e-4,  1e-3,  1e-2,  1e-1,  1e0,   1e1,   1e2,   1e3,   1e4,   1e5,   1e6,  1e7,  1e8,  1e9};

// "00" "01" ... "99": two digits a lookup.
constexpr std::array<char, 200> kDigitPairs = [] {
  std::array<char, 200> d{};
  for (int i = 0; i < 100; ++i) {
    d[2 * i] = static_cast<char>('0' + i / 10);
    d[2 * i + 1] = static_cast<char>('0' + i % 10);
  }
  return d;
}();

// floor(e2 log10(2)): 78913 / 2^18 is log10(2) to 8e-7 (Ryu, Adams 2018,
// log10Pow2), equal to it for every binary64 exponent (-1022..1023, checked
// against a 60-digit log10(2)); were it ever off, the exact check below
// would send the value to std::to_chars. C++20 defines >> of a negative int
// as a floor.
int floorLog10Pow2(int e2) { return (e2 * 78913) >> 18; }

char* fallback(double value, char* out) {
  return std::to_chars(out, out + kGeneral9Chars, value, std::chars_format::general, kPrecision).ptr;
}

// n in [10^8, 10^9) as its leading digit and the eight after it, the
// latter as eight ASCII bytes in a word (the first digit in the lowest
// byte, as a little-endian store writes them first), computed in the
// register, SWAR fashion: halves of four digits, then pairs, then digits,
// each lane divided by a multiply and shift (v/100 = (v 10486) >> 20 for
// v < 10^4, v/10 = (v 103) >> 10 for v < 100; Granlund and Montgomery
// 1994). Writing the digits byte by byte and reading them back as a word
// would stall on store forwarding.
struct Digits {
  char lead;
  std::uint64_t tail;  // digits 2..9, ASCII
  int count;           // significant digits once trailing zeros are dropped, >= 1
};

Digits splitDigits(std::uint32_t n) {
  const std::uint32_t lead = n / kLowest9Digits;
  const std::uint32_t rest = n - lead * kLowest9Digits;
  const std::uint32_t high = rest / 10000;
  const std::uint64_t quads = high | (std::uint64_t{rest - high * 10000} << 32);
  const std::uint64_t hundreds = ((quads * 10486) >> 20) & 0x0000007F0000007F;
  const std::uint64_t pairs = hundreds | ((quads - hundreds * 100) << 16);
  const std::uint64_t tens = ((pairs * 103) >> 10) & 0x000F000F000F000F;
  const std::uint64_t digits = tens | ((pairs - tens * 10) << 8);
  // Trailing zero digits are the zero bytes at the top of `digits`.
  const int count = digits == 0 ? 1 : kPrecision - std::countl_zero(digits) / 8;
  return {static_cast<char>('0' + lead), digits | 0x3030303030303030, count};
}

// %g's layout of n 10^(exponent - 8) for exponent in [-19, 9]. Whole words
// are stored and the end moved by what is kept: the writes stay inside
// out[0, kGeneral9Chars) (at most 17 chars: 8 digits, the point, a word).
char* layOut(const Digits& d, int exponent, char* out) {
  if (exponent >= 0 && exponent < kPrecision) {  // ddd[.ddd]
    const int whole = exponent + 1;
    out[0] = d.lead;
    std::memcpy(out + 1, &d.tail, 8);
    if (d.count <= whole) return out + whole;
    out[whole] = '.';
    const std::uint64_t fraction = d.tail >> (8 * exponent);  // exponent <= 7 here
    std::memcpy(out + whole + 1, &fraction, 8);
    return out + d.count + 1;
  }
  if (exponent >= kLowestFixedExponent && exponent < 0) {  // 0.000ddd
    std::memcpy(out, "0.000000", 8);
    out += 1 - exponent;
    out[0] = d.lead;
    std::memcpy(out + 1, &d.tail, 8);
    return out + d.count;
  }
  out[0] = d.lead;  // d[.ddd]e±XX
  out[1] = '.';
  std::memcpy(out + 2, &d.tail, 8);
  out += d.count > 1 ? d.count + 1 : 1;
  const int magnitude = exponent < 0 ? -exponent : exponent;
  out[0] = 'e';
  out[1] = exponent < 0 ? '-' : '+';
  std::memcpy(out + 2, &kDigitPairs[2 * magnitude], 2);
  return out + 4;
}

}  // namespace

char* formatGeneral9(double value, char* out) {
  const auto bits = std::bit_cast<std::uint64_t>(value);
  const bool negative = (bits >> 63) != 0;
  const int biased = static_cast<int>((bits >> kFractionBits) & kExponentAllOnes);
  const std::uint64_t fraction = bits & kFractionMask;
  if (biased == 0 && fraction == 0) {  // "0" and "-0", as %g writes them
    if (negative) *out++ = '-';
    *out++ = '0';
    return out;
  }
  if (biased == 0 || biased == kExponentAllOnes) return fallback(value, out);  // subnormal, inf, NaN
  // |value| = m 2^e2b with m in [2^52, 2^53): |value| in [2^e2, 2^(e2+1)).
  const std::uint64_t m = fraction | (std::uint64_t{1} << kFractionBits);
  const int e2 = biased - kExponentBias;
  const int e2b = e2 - kFractionBits;
  // e = floor(log10 |value|) is floor(e2 log10 2) or one more, as log10
  // |value| lies in [e2 log10 2, (e2 + 1) log10 2) and log10 2 < 1; one
  // comparison with 10^(e + 1) decides which.
  int exponent = floorLog10Pow2(e2);
  if (exponent < kLowestExponent - 1 || exponent > kHighestExponent) return fallback(value, out);
  exponent += std::fabs(value) >= kPowersOf10[exponent + 1 - kLowestExponent] ? 1 : 0;
  const int k = kHighestExponent - exponent;
  if (k < 0 || k > kMaxScale) return fallback(value, out);
  // y = |value| 10^k = (m 5^k) 2^(e2b + k), exactly: m 5^k < 2^53 2^63 fits
  // in 128 bits, and as y < 10^10 < 2^52 <= m 5^k the shift is to the right
  // (at least 18 bits; at most 100, as y >= 10^7 and m 5^k < 2^116).
  // Then floor(2y) is the bits above shift - 1, and y's fraction is above,
  // at or below one half as the bits below are.
  const Uint128 product = Uint128{m} * kPowersOf5[k];
  const int shift = -(e2b + k);
  assert(shift >= 18 && shift <= 100);
  const auto halves = static_cast<std::uint64_t>(product >> (shift - 1));  // floor(2y)
  const std::uint64_t whole = halves >> 1;                                 // floor(y)
  const bool half_or_more = (halves & 1) != 0;
  const bool below_half_bit = (product << (129 - shift)) != 0;  // any bit under the half's
  // floor(y) is outside [10^8, 10^9) only for |value| the double nearest
  // 10^(e + 1) when that lies below 10^(e + 1) (the table's rounding); a
  // tie (exactly .5) is printf's to round to even. std::to_chars has both.
  if (whole < kLowest9Digits || whole >= kPast9Digits || (half_or_more && !below_half_bit)) {
    return fallback(value, out);
  }
  // Rounding up from 999999999.5 and above gives 1.00000000e(exponent + 1).
  // Without branches: the rounding bit is random in real data.
  std::uint64_t n = whole + (halves & 1);
  const bool carry = n == kPast9Digits;
  n = carry ? kLowest9Digits : n;
  exponent += carry ? 1 : 0;
  const Digits digits = splitDigits(static_cast<std::uint32_t>(n));
  *out = '-';  // kept or overwritten: no branch on the sign
  out += negative ? 1 : 0;
  return layOut(digits, exponent, out);
}

}  // namespace wtc::sim
