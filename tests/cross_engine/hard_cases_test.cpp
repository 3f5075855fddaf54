// Open hard cases of the tyre model in both engines (issue 11), each
// against an answer derived elsewhere. Disabled while open: they fail
// today, and say by how much when run:
//   build/tests/cross_engine/wtc_cross_engine_tests --gtest_also_run_disabled_tests --gtest_filter='HardCases*'
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "engine_sim.hpp"
#include "wheel_sim.hpp"

namespace wtc::testing {
namespace {

constexpr double kRadius = 0.19;  // r_f of the robot's wheel (m)

// A free wheel rolling slowly on flat ground must come to rest: rolling
// resistance alone decelerates it at f_r g r_0 / (r_f (1 + I / (m r_f^2)))
// (0.018 x 9.81 / 1.5 = 0.12 m/s^2 for a disc: 5 cm/s gone in 0.45 s).
// Its tread spring is capped for the wheel's mass, but in the rolling
// direction the contact moves only 1 / (1/m + r^2/I) (m/3 for a disc): in
// force mode the velocity changes sign at nearly every step and never
// settles (measured at 2 ms, 3.7 kg: 1272 sign changes in 3 s, 1.7 mm/s
// left). Both engines, force and constraint mode, 0.4 to 2 ms, 3.7 and 21 kg.
TEST(HardCasesTest, DISABLED_FreeWheelRollingSlowlyComesToRest) {
  constexpr double kStartMps = 0.05, kSeconds = 3.0, kRestMps = 1e-3, kNoiseMps = 1e-5;
  const Terrain ground = flatGround();
  for (const Engine engine : {Engine::kBullet, Engine::kOde}) {
    for (const ContactMode mode : {ContactMode::kForce, ContactMode::kConstraint}) {
      for (const double mass : {3.7, 21.0}) {
        for (const double h : {4e-4, 1e-3, 2e-3}) {
          const double deflection = mass * kGravityMps2 / 1e5;
          auto sim = makeEngineSim(engine, mode, ground, mass, {0, 0, kRadius - deflection}, Hold::kUpright);
          sim->setMotion({kStartMps, 0, 0}, kStartMps / (kRadius - deflection));
          int sign_changes = 0;
          double last = kStartMps, tail_max = 0.0;
          const long steps = std::lround(kSeconds / h);
          for (long k = 0; k < steps; ++k) {
            sim->step(h);
            const double v = sim->velocity().x();
            if (std::abs(v) > kNoiseMps) {  // a sign change of a speed that is really there
              if (v * last < 0.0) ++sign_changes;
              last = v;
            }
            if (k > steps / 2) tail_max = std::max(tail_max, std::abs(v));
          }
          const std::string label = engineName(engine) + (mode == ContactMode::kForce ? " force" : " constraint") +
                                    ", " + std::to_string(mass) + " kg, h = " + std::to_string(h);
          EXPECT_LT(tail_max, kRestMps) << label;
          EXPECT_LT(sign_changes, 10) << label;
        }
      }
    }
  }
}

}  // namespace
}  // namespace wtc::testing
