// The tyre model integrated in time by the semi-implicit Euler loop of
// tests/support/wheel_sim.hpp: static deflection, bounce, the parked vehicle on a slope
// (spec section 6, issue: < 1 cm creep in 10 s, no oscillation, h from
// 0.1 to 2 ms), sliding above the friction limit, spinning in place, and
// the stability report.
#include <cmath>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "wheel_sim.hpp"
#include "wtc/tyre/traction_law.hpp"

namespace wtc {
namespace {

using Eigen::Vector3d;
using testing::downhill;
using testing::kGravityMps2;
using testing::restOnSlab;
using testing::SimWheel;
using testing::slabNormal;
using testing::step;
using testing::tiltedSlab;

constexpr double kDegree = 0.017453292519943295;  // (rad)

// Case: dropped from 1 cm, a damped tyre settles where c Z = m g.
TEST(TyreDynamicsTest, DroppedWheelSettlesAtWeightOverStiffness) {
  const Terrain flat = tiltedSlab(0.0);
  for (const double mass : {3.7, 21.0, 60.0}) {
    SimWheel wheel;
    wheel.mass = mass;
    wheel.center = {0, 0, wheel.description.geometry.free_radius + 0.01};
    const TyreModel model(EffectSet::full());
    for (int k = 0; k < 3000; ++k) step(model, flat, 1e-3, wheel);
    const double deflection = wheel.description.geometry.free_radius - wheel.center.z();
    EXPECT_NEAR(deflection, mass * kGravityMps2 / 1e5, 1e-6 * deflection) << "m = " << mass;
  }
}

// Case: without damping, the bounce keeps its height: symplectic Euler
// neither gains nor loses energy over a cycle. Its apex wanders by the
// travel of about one step at impact (v h, v = sqrt(2 g drop) = 1 m/s:
// 1 mm at 1 ms), with the phase of contact within the step.
TEST(TyreDynamicsTest, UndampedBounceDoesNotGainEnergy) {
  const Terrain flat = tiltedSlab(0.0);
  SimWheel wheel;
  const double drop = 0.05;  // (m)
  wheel.center = {0, 0, wheel.description.geometry.free_radius + drop};
  const TyreModel model(EffectSet::minimal());
  double highest_late = 0.0;
  for (int k = 0; k < 20000; ++k) {  // 20 s, dozens of bounces
    step(model, flat, 1e-3, wheel);
    if (k > 18000) highest_late = std::max(highest_late, wheel.center.z());
  }
  const double top = wheel.description.geometry.free_radius + drop;
  const double one_step_travel = std::sqrt(2 * kGravityMps2 * drop) * 1e-3;  // (m)
  EXPECT_LE(highest_late, top + one_step_travel);
  EXPECT_GE(highest_late, top - 10 * one_step_travel);  // and does not lose it either
}

struct ParkedCase {
  double step_seconds;
  double effective_mass;
};

class ParkedOnSlopeTest : public ::testing::TestWithParam<ParkedCase> {};
constexpr double kStillMps = 1e-5;  // a parked wheel moves slower than this

// Case: a locked wheel carrying a sixth of the robot on 15 deg with
// mu_max = 0.8 holds (the tread's sticking state: it relaxes only as the
// ground moves under it): < 1 um in 10 s after it has settled, where the
// spec's regularized law creeps at s_eq eps (0.41 mm), and no oscillation
// above 10 um/s. Settling takes up to 1.5 s: the tread's damping is
// critical for the wheel's mass but bounded by the explicit stability of
// the lighter mass an unbraked wheel's contact moves (1 / (1/m + r^2/I),
// defect 1), so a braked 21 kg wheel rings at about 8 Hz with a damping
// ratio of 0.15-0.3 at 1-2 ms (45 um of load-up at 2 ms), then holds.
TEST_P(ParkedOnSlopeTest, HoldsWithinAMicrometreForTenSecondsWithoutOscillating) {
  const double slope = 15 * kDegree, h = GetParam().step_seconds;
  const Terrain incline = tiltedSlab(slope);
  SimWheel wheel;
  wheel.description.inertia.effective_mass = GetParam().effective_mass;
  wheel.locked = true;
  restOnSlab(wheel, slope);
  const TyreModel model(EffectSet::full());
  const int settle = static_cast<int>(std::lround(2.0 / h)), steps = static_cast<int>(std::lround(10.0 / h));
  for (int k = 0; k < settle; ++k) step(model, incline, h, wheel);
  const Vector3d start = wheel.center;
  int reversals = 0;
  double previous = 0.0, fastest = 0.0;
  for (int k = 0; k < steps; ++k) {
    step(model, incline, h, wheel);
    const double v = wheel.velocity.dot(downhill(slope));
    if (std::abs(v) > kStillMps) {
      if (v * previous < 0.0) ++reversals;
      previous = v;
    }
    fastest = std::max(fastest, std::abs(v));
  }
  const double creep = (wheel.center - start).dot(downhill(slope));
  EXPECT_LT(std::abs(creep), 1e-6);
  EXPECT_EQ(reversals, 0);
  EXPECT_LT(fastest, kStillMps);
  EXPECT_EQ(wheel.state.unstableSteps(), 0u);
}

INSTANTIATE_TEST_SUITE_P(StepsAndMasses, ParkedOnSlopeTest,
                         ::testing::Values(ParkedCase{1e-4, 3.7}, ParkedCase{5e-4, 3.7}, ParkedCase{1e-3, 3.7},
                                           ParkedCase{2e-3, 3.7}, ParkedCase{2e-3, 21.0}, ParkedCase{1e-4, 21.0}));

// Case (issue 11, defect 1): a free wheel rolling slowly comes to rest,
// stopped by rolling resistance alone. Rolling without slip,
// (M + I / r_f^2) dv/dt = -f_r R_z r_0 / r_f: it slows from 5 to 2 cm/s in
// 0.03 m/s / that (0.19 s for the robot's wheel under 21 kg); below, the
// moment's sign ramp (its width keeps the gain below kappa I / h) lets it
// settle in a few tenths of a second more. The tread's caps must hold for
// the mass its contact moves along the ground, 1 / (1/M + r_f^2 / I)
// (1.7 kg here): capped for M, the speed changed sign at every step and
// never settled (21 kg at 2 ms: 27 mm/s after 3 s). A 3.7 kg wheel alone
// and a loaded one (21 kg on its axle, the tyre told the 21 kg), 0.4-2 ms.
TEST(TyreDynamicsTest, AFreeWheelRollingSlowlySlowsAsRollingResistanceSaysAndComesToRest) {
  constexpr double kStartMps = 0.05, kSlowMps = 0.02, kRestMps = 1e-4, kSeconds = 3.0;
  const Terrain flat = tiltedSlab(0.0);
  for (const double mass : {3.7, 21.0}) {
    for (const double h : {4e-4, 1e-3, 2e-3}) {
      SimWheel wheel;
      wheel.mass = mass;
      wheel.description.inertia.effective_mass = mass;
      restOnSlab(wheel, 0.0);
      const double r_f = wheel.description.geometry.free_radius, inertia = wheel.description.inertia.axial_inertia;
      const double r_0 = wheel.description.tyre.rolling_radius_ratio * r_f;
      wheel.velocity = {kStartMps, 0, 0};
      wheel.spin = kStartMps / (r_f - mass * kGravityMps2 / 1e5);
      const double deceleration =
          Material{}.rolling_resistance * mass * kGravityMps2 * r_0 / r_f / (mass + inertia / (r_f * r_f));
      const TyreModel model(EffectSet::full());
      int reversals = 0;
      double previous = kStartMps, slow_at = -1.0, fastest_late = 0.0;
      const long steps = std::lround(kSeconds / h);
      for (long k = 1; k <= steps; ++k) {
        step(model, flat, h, wheel);
        const double v = wheel.velocity.x();
        if (std::abs(v) > kStillMps) {
          if (v * previous < 0.0) ++reversals;
          previous = v;
        }
        if (slow_at < 0.0 && v < kSlowMps) slow_at = k * h;
        if (k * h > kSeconds - 1.0) fastest_late = std::max(fastest_late, std::abs(v));
      }
      const std::string label = std::to_string(mass) + " kg, h = " + std::to_string(h) + " s";
      const double expected = (kStartMps - kSlowMps) / deceleration;
      EXPECT_NEAR(slow_at, expected, 0.05 * expected) << label;
      EXPECT_LE(reversals, 3) << label;  // the tread spring's rebound as it stops, damped
      EXPECT_LT(fastest_late, kRestMps) << label;
      EXPECT_EQ(wheel.state.unstableSteps(), 0u) << label;
    }
  }
}

// Case: on 45 deg (tan = 1 > mu_max = 0.8) a locked wheel slides with
// a = g (sin - mu(1) cos): sliding without rolling has s = |V_s| / |V_O| = 1.
TEST(TyreDynamicsTest, LockedWheelSlidesAboveTheFrictionLimit) {
  const double slope = 45 * kDegree, h = 1e-3;
  const Terrain incline = tiltedSlab(slope);
  SimWheel wheel;
  wheel.locked = true;
  restOnSlab(wheel, slope);
  const TyreModel model(EffectSet::full());
  for (int k = 0; k < 500; ++k) step(model, incline, h, wheel);
  const double v0 = wheel.velocity.dot(downhill(slope));
  for (int k = 0; k < 1000; ++k) step(model, incline, h, wheel);
  const double acceleration = (wheel.velocity.dot(downhill(slope)) - v0) / 1.0;
  const double expected = kGravityMps2 * (std::sin(slope) - tractionCoefficient(Material{}, 1.0) * std::cos(slope));
  EXPECT_NEAR(acceleration, expected, 0.01 * expected);
}

// Case: just below the limit (tan = 0.75 < 0.8) it still holds: creep
// s_eq eps with mu(s_eq) = 0.75, s_eq = 0.28: 3 mm in 10 s.
TEST(TyreDynamicsTest, LockedWheelHoldsJustBelowTheFrictionLimit) {
  const double slope = std::atan(0.75), h = 1e-3;
  const Terrain incline = tiltedSlab(slope);
  SimWheel wheel;
  wheel.locked = true;
  restOnSlab(wheel, slope);
  const TyreModel model(EffectSet::full());
  for (int k = 0; k < 500; ++k) step(model, incline, h, wheel);
  const Vector3d start = wheel.center;
  for (int k = 0; k < 10000; ++k) step(model, incline, h, wheel);
  EXPECT_LT((wheel.center - start).dot(downhill(slope)), 0.01);
}

// Case: the centre held still, the wheel spinning: V_t = 0, s = |V_s| / eps
// is huge, so the traction is mu_max R_z opposing the contact point.
TEST(TyreDynamicsTest, WheelSpinningInPlaceFeelsMuMax) {
  const Terrain flat = tiltedSlab(0.0);
  const TyreModel model(EffectSet{Effect::kSlipTraction});
  SimWheel wheel;
  restOnSlab(wheel, 0.0);
  WheelMotion spinning;
  spinning.angular_velocity = {0, 5.0, 0};
  const ContactForce* c = nullptr;
  for (int k = 0; k < 500; ++k) {
    c = &model.step(flat, wheel.description, {wheel.center, wheel.axle}, spinning, 1e-3, wheel.state).contacts[0];
  }
  // omega x OP = (-omega r, 0, 0): the tread slips backward, the ground pushes forward.
  EXPECT_NEAR(c->tangential_force.x(), 0.8 * c->normal_force, 1e-3 * c->normal_force);
  // Case: the spin stops; the tread unwinds within its capped deflection:
  // after a few centimetres of travel nothing of the spin is left.
  SimWheel after = wheel;
  after.spin = 0.0;
  for (int k = 0; k < 2000; ++k) step(model, flat, 1e-3, after);
  EXPECT_LT(after.velocity.norm(), 0.05);
}

// Case: a driven wheel on flat ground with a torque far beyond the grip
// spins up; its traction saturates at mu_max R_z and never exceeds it.
TEST(TyreDynamicsTest, DrivenWheelTractionSaturatesAtMuTimesNormalForce) {
  const Terrain flat = tiltedSlab(0.0);
  const TyreModel model(EffectSet::full());
  SimWheel wheel;
  restOnSlab(wheel, 0.0);
  wheel.drive_torque = 100.0;  // N m, the robot's wheel motor; grip is ~0.8 x 206 x 0.19 = 31 N m
  double largest_ratio = 0.0;
  for (int k = 0; k < 1000; ++k) {  // 1 s: about 4 m, well inside the 20 m slab
    const WheelForces& f = step(model, flat, 1e-3, wheel);
    for (const ContactForce& c : f.contacts) {
      if (c.normal_force > 0) largest_ratio = std::max(largest_ratio, c.tangential_force.norm() / c.normal_force);
    }
  }
  EXPECT_LE(largest_ratio, 0.8 * (1 + 1e-12));
  EXPECT_GT(largest_ratio, 0.8 * (1 - 1e-3));
  // The body then accelerates at mu_max g (the spin-up takes a few ms).
  EXPECT_NEAR(wheel.velocity.x() / 1.0, 0.8 * kGravityMps2, 0.01 * 0.8 * kGravityMps2);
}

// Case: a stiff tyre at a large step is reported, with its numbers.
TEST(TyreDynamicsTest, StepBeyondTheExplicitSpringLimitIsReported) {
  const Terrain flat = tiltedSlab(0.0);
  const TyreModel model(EffectSet::full());
  SimWheel wheel;
  wheel.description.tyre.radial_stiffness = 1e7;  // h sqrt(c/m) = 2e-3 sqrt(1e7/3.7) = 3.3
  restOnSlab(wheel, 0.0);
  const WheelForces& f = step(model, flat, 2e-3, wheel);
  EXPECT_FALSE(f.normal_stability.stable());
  EXPECT_NEAR(f.normal_stability.step_number, 2e-3 * std::sqrt(1e7 / 3.7), 1e-12);
  EXPECT_EQ(wheel.state.unstableSteps(), 1u);
  SimWheel soft;
  restOnSlab(soft, 0.0);
  EXPECT_TRUE(step(model, flat, 2e-3, soft).normal_stability.stable());
  EXPECT_EQ(soft.state.unstableSteps(), 0u);
  // Case: in constraint and implicit mode the engine solves the spring
  // implicitly: the same stiff tyre is reported with its step number but
  // never unstable.
  for (const ContactMode mode : {ContactMode::kConstraint, ContactMode::kImplicit}) {
    const TyreModel solved(EffectSet::full(), mode);
    SimWheel engine;
    engine.description.tyre.radial_stiffness = 1e7;
    restOnSlab(engine, 0.0);
    const WheelForces& g = step(solved, flat, 2e-3, engine);
    EXPECT_TRUE(g.normal_stability.stable()) << contactModeName(mode);
    EXPECT_NEAR(g.normal_stability.step_number, 2e-3 * std::sqrt(1e7 / 3.7), 1e-12) << contactModeName(mode);
    EXPECT_EQ(engine.state.unstableSteps(), 0u) << contactModeName(mode);
  }
}

}  // namespace
}  // namespace wtc
