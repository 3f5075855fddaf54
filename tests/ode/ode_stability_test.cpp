// The largest stable step of each contact mode in ODE for a stiff tyre,
// measured by bisection and compared with the core's explicit limit.
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "ode_fixture.hpp"
#include "wtc/tyre/explicit_stability.hpp"

namespace wtc {
namespace ode_stability_test {

using testing::kGravityMps2;
using testing::OdeWorld;

constexpr double kRadius = 0.19;                            // r_f (m)
constexpr double kStiffTyre = 1e6;                          // c (N/m): ten times the robot's tyre
constexpr double kWheelMass = 3.7;                          // (kg)
constexpr double kDamping = 900.0;                          // b (N s/m), the default tyre
constexpr double kDropM = 0.001;                            // released this far above its rest height (m)
constexpr double kRunSeconds = 2.0;                         // (s)
constexpr double kSettleTolerance = 0.01;                   // "settled": within 1 % of m g / c
constexpr double kShortestStep = 1e-4, kLongestStep = 0.1;  // bisection bounds (s)
constexpr double kBisectionRatio = 1.01;                    // stop when high / low is below this
constexpr double kPredictionTolerance = 0.1;                // measured vs analytic force-mode limit
constexpr double kSolvedModeMargin = 10.0;  // constraint and implicit mode must be stable at this x the force limit

// The stiff tyre on the 3.7 kg wheel (rotation locked), released 1 mm above
// its rest height, run 2 s at step h: stable if it ends within 1 % of m g / c.
bool settlesAtStep(ContactMode mode, double h) {
  const Terrain ground = testing::flatGround();
  OdeWorld w(ground, mode);
  const double rest = kWheelMass * kGravityMps2 / kStiffTyre;
  const testing::OdeWheel wheel = w.addWheelBody(kWheelMass, {0, 0, kRadius - rest + kDropM});
  testing::lockRotation(w, wheel.body);
  TyreParameters tyre;
  tyre.radial_stiffness = kStiffTyre;
  testing::addWheel(w, wheel, EffectSet::full(), tyre);
  for (long k = 0; k < std::lround(kRunSeconds / h); ++k) w.step(h);
  const double deflection = kRadius - testing::position(wheel.body).z();
  return std::isfinite(deflection) && std::abs(deflection - rest) < kSettleTolerance * rest;
}

// The largest step at which settlesAtStep holds, by bisection on log h in
// [0.1 ms, 0.1 s] (or the upper bound itself).
double largestSettlingStep(ContactMode mode) {
  double low = kShortestStep, high = kLongestStep;
  if (settlesAtStep(mode, high)) return high;
  while (high / low > kBisectionRatio) {
    const double h = std::sqrt(low * high);
    (settlesAtStep(mode, h) ? low : high) = h;
  }
  return low;
}

// Case: force mode is the explicit spring: its measured limit is the core's,
// 2 (sqrt(1 + zeta^2) - zeta) / sqrt(c/m) = 3.05 ms (zeta = 0.23).
// Constraint and implicit mode hand the spring to ODE's implicit solver
// (implicit mode the tread as well): stable at 10 x that step.
TEST(OdeStabilityTest, LargestStableStepOfEachModeForAStiffTyre) {
  const double predicted = largestStableStep(kStiffTyre, kDamping, kWheelMass);
  const double force = largestSettlingStep(ContactMode::kForce);
  RecordProperty("force_mode_largest_step_ms", std::to_string(force * 1e3));
  RecordProperty("analytic_force_mode_step_ms", std::to_string(predicted * 1e3));
  std::printf("ODE, stiff tyre c = 1e6 N/m on 3.7 kg: largest stable step, force mode %.3g ms (analytic %.3g ms)\n",
              force * 1e3, predicted * 1e3);
  EXPECT_NEAR(force, predicted, kPredictionTolerance * predicted);
  for (const ContactMode mode : {ContactMode::kConstraint, ContactMode::kImplicit}) {
    const std::string name(contactModeName(mode));
    const double largest = largestSettlingStep(mode);
    RecordProperty(name + "_mode_largest_step_ms", std::to_string(largest * 1e3));
    std::printf("  %s mode %.3g ms%s\n", name.c_str(), largest * 1e3,
                largest == kLongestStep ? " (the upper bound)" : "");
    EXPECT_TRUE(settlesAtStep(mode, kSolvedModeMargin * predicted)) << name;
    EXPECT_GE(largest, kSolvedModeMargin * predicted) << name;
  }
}

}  // namespace ode_stability_test
}  // namespace wtc
