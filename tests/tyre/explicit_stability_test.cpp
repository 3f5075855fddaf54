// The explicit spring-damper stability limit against the integrator it
// describes: just below the limit a disturbance stays bounded (|x| <= 5 for
// an undamped spring at 0.98 of the limit), just above it grows.
#include "wtc/tyre/explicit_stability.hpp"

#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace wtc {
namespace {

constexpr double kTolerance = 1e-12;

// Largest |x| over 5000 semi-implicit Euler steps from x = 1 (infinity once
// it overflows).
double largestAmplitude(double c, double b, double m, double h) {
  double x = 1.0, v = 0.0, largest = 0.0;
  for (int k = 0; k < 5000 && std::isfinite(x); ++k) {
    v += h * (-c * x - b * v) / m;
    x += h * v;
    largest = std::isfinite(x) ? std::max(largest, std::abs(x)) : INFINITY;
  }
  return largest;
}

TEST(ExplicitStabilityTest, LimitIsTwoUndampedAndLessWithDamping) {
  EXPECT_NEAR(explicitSpringStability(1e5, 0.0, 3.7, 1e-3).limit, 2.0, kTolerance);
  // zeta = 0.3: 2 (sqrt(1.09) - 0.3) = 1.48806...
  const double c = 1e5, m = 21.0, b = 0.3 * 2.0 * std::sqrt(c * m);
  const SpringStability s = explicitSpringStability(c, b, m, 1e-3);
  EXPECT_NEAR(s.damping_ratio, 0.3, kTolerance);
  EXPECT_NEAR(s.limit, 2.0 * (std::sqrt(1.09) - 0.3), kTolerance);
  EXPECT_NEAR(s.step_number, 1e-3 * std::sqrt(c / m), kTolerance);
}

TEST(ExplicitStabilityTest, SeparatesDecayFromGrowthInTheIntegrator) {
  const double c = 1e5, m = 3.7;
  for (const double b : {0.0, 100.0, 900.0}) {
    const double h_max = largestStableStep(c, b, m);
    EXPECT_TRUE(explicitSpringStability(c, b, m, 0.99 * h_max).stable());
    EXPECT_FALSE(explicitSpringStability(c, b, m, 1.01 * h_max).stable());
    EXPECT_LT(largestAmplitude(c, b, m, 0.98 * h_max), 10.0) << "b = " << b;
    EXPECT_GT(largestAmplitude(c, b, m, 1.02 * h_max), 1e3) << "b = " << b;
  }
}

TEST(ExplicitStabilityTest, ReportNamesTheNumbers) {
  const SpringStability s = explicitSpringStability(1e7, 900.0, 3.7, 2e-3);
  EXPECT_FALSE(s.stable());
  const std::string text = describe(s);
  EXPECT_THAT(text, ::testing::HasSubstr("c = 1e+07 N/m"));
  EXPECT_THAT(text, ::testing::HasSubstr("h = 0.002 s"));
  EXPECT_THAT(text, ::testing::HasSubstr(">= limit"));
}

}  // namespace
}  // namespace wtc
