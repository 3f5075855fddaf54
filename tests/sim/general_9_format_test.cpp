// sim::formatGeneral9 (the recorder's numbers) writes exactly the bytes of
// std::to_chars(..., general, 9), i.e. printf's %.9g: over random bit
// patterns, the magnitudes the series hold, every power of ten and its
// neighbours, exact and near ties at the 9th digit, and the special values.
#include "sim/general_9_format.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <limits>
#include <random>
#include <string>
#include <string_view>

namespace wtc::sim {
namespace {

constexpr int kRandomCases = 8'000'000;  // per random test
constexpr int kNeighbourUlps = 3;        // neighbours each side of a chosen value
constexpr int kMismatchesShown = 5;

// Compares formatGeneral9 with std::to_chars on many values, counting the
// mismatches and naming the first few (a flood of failures helps no one).
class Comparison {
 public:
  void check(double value) {
    char expected[kGeneral9Chars];
    char actual[kGeneral9Chars];
    const std::string_view want(
        expected, std::to_chars(expected, expected + kGeneral9Chars, value, std::chars_format::general, 9).ptr);
    const std::string_view got(actual, formatGeneral9(value, actual));
    ++checked_;
    if (want == got) return;
    if (++mismatches_ <= kMismatchesShown) {
      char bits[64];
      std::snprintf(bits, sizeof bits, "%a", value);
      report_ += "\n  " + std::string(bits) + ": to_chars \"" + std::string(want) + "\", formatGeneral9 \"" +
                 std::string(got) + "\"";
    }
  }
  void checkWithNeighbours(double value) {
    double below = value;
    double above = value;
    check(value);
    for (int i = 0; i < kNeighbourUlps; ++i) {
      below = std::nextafter(below, -std::numeric_limits<double>::infinity());
      above = std::nextafter(above, std::numeric_limits<double>::infinity());
      check(below);
      check(above);
    }
  }
  int checked() const { return checked_; }
  ::testing::AssertionResult allMatched() const {
    if (mismatches_ == 0) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << mismatches_ << " of " << checked_ << " values differ:" << report_;
  }

 private:
  int checked_ = 0;
  int mismatches_ = 0;
  std::string report_;
};

double parse(const std::string& text) { return std::strtod(text.c_str(), nullptr); }  // the nearest double

TEST(General9FormatTest, RandomBitPatternsMatchToChars) {
  std::mt19937_64 random(20261126);
  Comparison c;
  for (int i = 0; i < kRandomCases; ++i) c.check(std::bit_cast<double>(random()));
  EXPECT_TRUE(c.allMatched());
}

TEST(General9FormatTest, MagnitudesOfTheSeriesMatchToChars) {
  // Log-uniform over 1e-12..1e6, both signs: positions, velocities,
  // quaternions, forces and slips as the recorder writes them.
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> decade(-12.0, 6.0);
  Comparison c;
  for (int i = 0; i < kRandomCases; ++i) {
    const double magnitude = std::pow(10.0, decade(random));
    c.check(i % 2 == 0 ? magnitude : -magnitude);
  }
  // Times and round values: few digits, exact multiples of the steps.
  for (int i = 0; i < 100'000; ++i) {
    c.check(i * 0.005);
    c.check(i * 1e-3);
    c.check(i * 0.25);
  }
  EXPECT_TRUE(c.allMatched());
}

TEST(General9FormatTest, PowersOfTenAndTheirNeighboursMatchToChars) {
  Comparison c;
  for (int p = -320; p <= 308; ++p) {
    c.checkWithNeighbours(parse("1e" + std::to_string(p)));
    // Where rounding carries into the next power: 9.999999995e(p-1).
    c.checkWithNeighbours(parse("9.999999995e" + std::to_string(p - 1)));
    c.checkWithNeighbours(-parse("1e" + std::to_string(p)));
  }
  EXPECT_TRUE(c.allMatched());
}

TEST(General9FormatTest, TiesAtTheNinthDigitMatchToChars) {
  Comparison c;
  // Exact ties: ten significant digits ending in 5, exactly representable.
  // D 10^q for q >= 0 (D 10^q < 2^53), and D / 10^j = (D / 5^j) 2^-j when
  // 5^j divides D.
  const std::uint64_t ties[] = {1000000005, 1234567895, 9999999995, 1000000015, 5000000005, 2147483645};
  for (const std::uint64_t d : ties) {
    for (int q = 0; q <= 5; ++q) c.checkWithNeighbours(static_cast<double>(d) * std::pow(10.0, q));
  }
  // D / 10^j with 5^j dividing D: D = c 5^j, c odd, is c 2^-j.
  std::mt19937_64 random(3);
  std::uint64_t powerOf5 = 5;
  for (int j = 1; powerOf5 < 10'000'000'000; ++j, powerOf5 *= 5) {
    std::uniform_int_distribution<std::uint64_t> odd((1'000'000'000 / powerOf5 + 1) / 2,
                                                     (9'999'999'999 / powerOf5 - 1) / 2);
    for (int i = 0; i < 500; ++i) c.checkWithNeighbours(std::ldexp(static_cast<double>(2 * odd(random) + 1), -j));
  }
  // A power of two whose digits are ten ending in 5 (2^-14 = 6.103515625e-5),
  // halves of 9-digit integers (odd and even below, and the carry to 1e9).
  c.checkWithNeighbours(std::ldexp(1.0, -14));
  c.checkWithNeighbours(123456789.5);
  c.checkWithNeighbours(123456788.5);
  c.checkWithNeighbours(999999999.5);
  // Near ties: the nearest double to a tie that is not representable.
  for (int p = -30; p <= 30; ++p) {
    for (const char* digits : {"1.000000005e", "1.234567895e", "9.999999995e", "5.000000005e"}) {
      c.checkWithNeighbours(parse(digits + std::to_string(p)));
    }
  }
  EXPECT_GT(c.checked(), 20'000);
  EXPECT_TRUE(c.allMatched());
}

TEST(General9FormatTest, SpecialValuesMatchToChars) {
  using Limits = std::numeric_limits<double>;
  Comparison c;
  for (const double v : {0.0, -0.0, Limits::denorm_min(), Limits::min(), Limits::max(), Limits::lowest(),
                         Limits::infinity(), -Limits::infinity(), Limits::quiet_NaN(), -Limits::quiet_NaN(),
                         Limits::epsilon(), 1.0, -1.0, 0.1, 1e9, 1e-19, 1e-20}) {
    c.checkWithNeighbours(v);
  }
  std::mt19937_64 random(11);
  for (int i = 0; i < 100'000; ++i) {  // subnormals
    c.check(std::bit_cast<double>(random() >> 12));
    c.check(-std::bit_cast<double>(random() >> 12));
  }
  EXPECT_TRUE(c.allMatched());
  // What the recorder's files hold for them, spelled out.
  char text[kGeneral9Chars];
  EXPECT_EQ(std::string_view(text, formatGeneral9(0.0, text)), "0");
  EXPECT_EQ(std::string_view(text, formatGeneral9(-0.0, text)), "-0");
  EXPECT_EQ(std::string_view(text, formatGeneral9(-1.5e-7, text)), "-1.5e-07");
  EXPECT_EQ(std::string_view(text, formatGeneral9(0.000123456789, text)), "0.000123456789");
  EXPECT_EQ(std::string_view(text, formatGeneral9(999999999.7, text)), "1e+09");
}

}  // namespace
}  // namespace wtc::sim
