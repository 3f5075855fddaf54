// The traction law mu(s) of the wheel-terrain model, section 4, against its
// stated properties, and the static/dynamic mapping of the vehicles spec.
#include "wtc/tyre/traction_law.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "wtc/base/error.hpp"
#include "wtc/base/tolerances.hpp"

namespace wtc {
namespace traction_law_test {

constexpr double kTolerance = 1e-12;

Material material(double mu_max, double s1, double s2) {
  Material m;
  m.mu_max = mu_max;
  m.s1 = s1;
  m.s2 = s2;
  return m;
}

TEST(TractionLawTest, IsZeroAtZeroSlipAndTendsToMuMax) {
  for (const double s2 : {0.0, 0.3, 4.44}) {
    const Material m = material(0.8, 0.1, s2);
    EXPECT_EQ(tractionCoefficient(m, 0.0), 0.0);
    EXPECT_NEAR(tractionCoefficient(m, 10.0), 0.8, kTolerance);
    EXPECT_NEAR(tractionCoefficient(m, 1e6), 0.8, kTolerance);
  }
}

TEST(TractionLawTest, InitialSlopeIsMuMaxTimesOnePlusS2OverS1) {
  for (const double s2 : {0.0, 0.3, 4.44}) {
    const Material m = material(0.8, 0.1, s2);
    const double slope = 0.8 * (1.0 + s2) / 0.1;
    EXPECT_NEAR(tractionInitialSlope(m), slope, kTolerance);
    // Central difference of mu about 0 continued oddly: mu(h)/h -> slope.
    EXPECT_NEAR(tractionCoefficient(m, 1e-7) / 1e-7, slope, 1e-5 * slope);
  }
}

TEST(TractionLawTest, SecantIsMuOverSAndContinuousAtZero) {
  const Material m = material(0.8, 0.1, 0.3);
  EXPECT_NEAR(tractionSecant(m, 0.0), tractionInitialSlope(m), kTolerance);
  for (const double s : {1e-12, 1e-9, 1e-8, 1.1e-8, 1e-6, 1e-3, 0.05, 0.5, 5.0}) {
    EXPECT_NEAR(tractionSecant(m, s) * s, tractionCoefficient(m, s), 1e-14) << "s = " << s;
  }
  // No jump where the secant switches to its series.
  const double x = 1e-8 * m.s1;
  EXPECT_NEAR(tractionSecant(m, x * (1 - 1e-9)), tractionSecant(m, x * (1 + 1e-9)), 1e-12);
}

TEST(TractionLawTest, IncreasesMonotonicallyWithoutAPeakWhenS2AtMostOne) {
  for (const double s2 : {0.0, 0.3, 1.0}) {
    const Material m = material(0.8, 0.1, s2);
    double previous = 0.0;
    for (double s = 1e-4; s < 3.0; s *= 1.05) {
      const double mu = tractionCoefficient(m, s);
      // Strictly rising until mu_max is reached in double (s ~ 20 s1),
      // then flat to within an ulp.
      if (s < 1.0) {
        EXPECT_GT(mu, previous) << "s2 = " << s2 << ", s = " << s;
      }
      EXPECT_GE(mu, previous - 1e-15) << "s2 = " << s2 << ", s = " << s;
      EXPECT_LE(mu, 0.8 * (1 + 1e-15));
      previous = mu;
    }
    EXPECT_EQ(tractionPeak(m), 0.8);
  }
}

TEST(TractionLawTest, PeakAboveMuMaxWhenS2AboveOne) {
  const Material m = material(0.45, 0.1, 4.44);
  const double peak = 0.45 * (1 + 4.44) * (1 + 4.44) / (4 * 4.44);
  EXPECT_NEAR(tractionPeak(m), peak, kTolerance);
  // The maximum over a fine grid: reached at q* = (s2 - 1) / (2 s2).
  const double s_star = -0.1 * std::log((4.44 - 1) / (2 * 4.44));
  EXPECT_NEAR(tractionCoefficient(m, s_star), peak, kTolerance);
  double highest = 0.0;
  for (double s = 0.0; s < 2.0; s += 1e-4) highest = std::max(highest, tractionCoefficient(m, s));
  EXPECT_LE(highest, peak + kTolerance);
  EXPECT_NEAR(highest, peak, 1e-7);
}

TEST(TractionLawTest, StaticDynamicPairsOfTheVehiclesSpecMapToS2) {
  // Case: 0.45/0.75, 0.30/0.50, 0.21/0.35 all have ratio 5/3 -> s2 = 4.44.
  const double s2 = adhesionBoostForPeakRatio(5.0 / 3.0);
  EXPECT_NEAR(s2, 4.44, 5e-3);
  for (const auto& [dynamic, stat] : {std::pair{0.45, 0.75}, std::pair{0.30, 0.50}, std::pair{0.21, 0.35}}) {
    const Material m = material(dynamic, 0.1, s2);
    EXPECT_NEAR(tractionPeak(m), stat, 1e-12) << dynamic << "/" << stat;
    EXPECT_NEAR(tractionCoefficient(m, 100.0), dynamic, 1e-12);
  }
  // Case: ratio 1 or below has no s2 >= 0 (a peak needs s2 > 1).
  EXPECT_THROW(adhesionBoostForPeakRatio(1.0), InvalidInputError);
  EXPECT_THROW(adhesionBoostForPeakRatio(std::nan("")), InvalidInputError);
}

TEST(TractionLawTest, SaturationSlipBoundsTheDistanceToMuMax) {
  for (const double s2 : {0.0, 0.3, 4.44}) {
    const Material m = material(0.8, 0.1, s2);
    const double s_sat = tractionSaturationSlip(m);
    for (double s = s_sat; s < 20.0 * s_sat; s *= 1.01) {
      EXPECT_LE(std::abs(tractionCoefficient(m, s) - 0.8), tolerance::kTractionSaturation * 0.8 * (1 + 1e-12))
          << "s2 = " << s2 << ", s = " << s;
    }
  }
}

}  // namespace traction_law_test
}  // namespace wtc
