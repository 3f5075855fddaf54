// The soft_soil effect stepped in time by tests/support/wheel_sim.hpp's
// semi-implicit Euler loop (what an engine does in force mode): a wheel on a
// carriage at constant speed and imposed slip settles at the steady state
// of the soil's equations (steadyWheelOnSoil), a dropped wheel loses its
// plastic work, and the effect changes nothing on ground without a soil.
#include <cmath>

#include <gtest/gtest.h>

#include "wheel_sim.hpp"
#include "wtc/tyre/wheel_soil.hpp"

namespace wtc {
namespace {

using testing::flatGround;
using testing::kGravityMps2;
using testing::SimWheel;
using testing::step;

constexpr double kRadiusM = 0.09, kWidthM = 0.11, kLoadN = 64.68;

Material soilMaterial(const char* name) {
  Material material;
  material.name = name;
  material.soil = *namedSoil(name);
  return material;
}

SimWheel ishigamiWheel() {
  SimWheel wheel;
  wheel.description.geometry.free_radius = kRadiusM;
  wheel.description.geometry.tread_width = kWidthM;
  wheel.mass = kLoadN / kGravityMps2;
  wheel.center = {0, 0, kRadiusM + 0.002};
  return wheel;
}

// The test bed: the carriage holds the travel speed v, the drive the rim
// speed v / (1 - i); the wheel is free to sink under its weight. After 4 s
// (the wheel bobs on the soil's spring and settles as it rolls onto fresh
// soil) its sinkage, pull and drive torque are the steady state's.
TEST(SoilDynamicsTest, ACarriageAtImposedSlipSettlesAtTheSteadyState) {
  const TyreModel model(EffectSet{Effect::kSoftSoil});
  for (const char* name : {"toyoura_sand", "lete_sand"}) {
    const Terrain ground = flatGround(1, soilMaterial(name));
    for (const double slip : {0.1, 0.3, 0.6}) {
      SimWheel wheel = ishigamiWheel();
      const double speed = 0.05;  // (m/s)
      wheel.locked = true;
      wheel.spin = speed / (kRadiusM * (1 - slip));
      double pull = 0, torque = 0, sinkage = 0;
      const int steps = 4000, averaged = 1000;
      for (int k = 0; k < steps; ++k) {
        wheel.velocity.x() = speed;
        const WheelForces& f = step(model, ground, 1e-3, wheel);
        if (k >= steps - averaged) {
          pull += f.force.x() / averaged;
          torque += -f.axial_moment.dot(wheel.axle) / averaged;
          sinkage += (kRadiusM - wheel.center.z()) / averaged;
        }
      }
      const SoilSteadyState want = steadyWheelOnSoil(*namedSoil(name), kRadiusM, kWidthM, kLoadN, slip);
      EXPECT_NEAR(sinkage, want.sinkage, 0.02 * want.sinkage) << name << " i " << slip;
      EXPECT_NEAR(pull, want.forces.drawbar_pull, 0.02 * kLoadN) << name << " i " << slip;
      EXPECT_NEAR(torque, want.forces.torque, 0.02 * std::abs(want.forces.torque)) << name << " i " << slip;
    }
  }
}

// Dropped from 3 cm onto sand at rest: the soil's damping takes the
// bounce, the wheel's energy (kinetic + potential) never grows, and it
// comes to rest where the symmetric hollow of a wheel at rest carries its
// weight (W(z) with theta_2 = -theta_1, no shear).
TEST(SoilDynamicsTest, ADroppedWheelComesToRestWhereTheSoilCarriesIt) {
  const TyreModel model(EffectSet{Effect::kSoftSoil});
  const Soil soil = *namedSoil("toyoura_sand");
  const Terrain ground = flatGround(1, soilMaterial("toyoura_sand"));
  SimWheel wheel = ishigamiWheel();
  const double drop = 0.03;
  wheel.center.z() = kRadiusM + drop;
  auto energy = [&] {
    return 0.5 * wheel.mass * wheel.velocity.squaredNorm() + wheel.mass * kGravityMps2 * wheel.center.z();
  };
  double most = energy(), growth = 0.0;
  for (int k = 0; k < 3000; ++k) {
    step(model, ground, 1e-3, wheel);
    // Symplectic Euler's energy wanders by about one step's travel times the force.
    EXPECT_LE(energy(), most + 2e-3 * kLoadN * 1e-3 * 10) << k;
    growth = std::max(growth, energy() - most);
    most = std::max(most, energy());
  }
  RecordProperty("largest_energy_growth_J", std::to_string(growth));
  RecordProperty("energy_lost_J", std::to_string(most - energy()));
  WheelSoilState rest;
  rest.radius = kRadiusM;
  rest.width = kWidthM;
  rest.sinkage = kRadiusM - wheel.center.z();
  rest.symmetry = 1.0;
  EXPECT_NEAR(wheelSoilForces(soil, rest).normal, kLoadN, 1e-3 * kLoadN);
  EXPECT_LT(std::abs(wheel.velocity.z()), 1e-4);
}

TEST(SoilDynamicsTest, WithoutASoilTheEffectChangesNothing) {
  const Terrain ground = flatGround(1);
  SimWheel with = ishigamiWheel(), without = ishigamiWheel();
  const TyreModel soft(EffectSet::full().with(Effect::kSoftSoil)), hard(EffectSet::full());
  for (SimWheel* w : {&with, &without}) w->drive_torque = 0.5;
  for (int k = 0; k < 500; ++k) {
    step(soft, ground, 1e-3, with);
    step(hard, ground, 1e-3, without);
  }
  EXPECT_EQ(with.center, without.center);
  EXPECT_EQ(with.velocity, without.velocity);
  EXPECT_EQ(with.spin, without.spin);
}

// A wheel heavier than the soil can carry at its axle (three times W at
// z = r) sinks to it: the state counts those steps (wtc-sim warns), while
// Ishigami's wheel under 64.68 N never gets there. On soil alone the
// stability report is the soil's spring's, not the tyre's.
TEST(SoilDynamicsTest, AWheelTheSoilCannotCarryIsCountedAtItsAxle) {
  const TyreModel model(EffectSet{Effect::kSoftSoil});
  const Soil soil = *namedSoil("toyoura_sand");
  const Terrain ground = flatGround(1, soilMaterial("toyoura_sand"));
  WheelSoilState at_axle;
  at_axle.radius = kRadiusM;
  at_axle.width = kWidthM;
  at_axle.sinkage = kRadiusM;
  const double most = wheelSoilForces(soil, at_axle).normal;
  for (const double load : {kLoadN, 3.0 * most}) {
    SimWheel wheel = ishigamiWheel();
    wheel.mass = load / kGravityMps2;
    for (int k = 0; k < 2000; ++k) {
      const WheelForces& f = step(model, ground, 1e-3, wheel);
      if (!f.contacts.empty()) {
        ASSERT_TRUE(f.normal_stability.soil) << k;
      }
    }
    if (load == kLoadN) {
      EXPECT_EQ(wheel.state.sunkSteps(), 0u);
    } else {
      EXPECT_GT(wheel.state.sunkSteps(), 0u) << load << " N";
      EXPECT_LE(wheel.center.z(), 0.0) << "the axle is in the soil";
    }
  }
}

// A wheel rolling on sand with a side slip meets its side's bulldozing
// (Ishigami's F_u) against it; as the side speed goes to zero the force
// goes to zero with it, ramped over the side speed it could reverse within
// a step, not Coulomb's step at v_y = 0 (with it, a wheel rolling straight
// was pushed back and forth by the rounding of its side speed). Mirrored
// side slips meet mirrored forces.
TEST(SoilDynamicsTest, TheSideBulldozingFadesWithTheSideSlipInsteadOfSteppingAtZero) {
  const TyreModel model(EffectSet{Effect::kSoftSoil});
  const Terrain ground = flatGround(1, soilMaterial("toyoura_sand"));
  WheelDescription wheel;
  wheel.geometry.free_radius = kRadiusM;
  wheel.geometry.tread_width = kWidthM;
  const auto lateral = [&](double side_speed) {
    WheelState state;
    WheelMotion motion;
    motion.velocity = {0.05, side_speed, 0.0};
    motion.angular_velocity = {0.0, 0.05 / 0.7 / kRadiusM, 0.0};  // slip 0.3
    const WheelForces& f = model.step(ground, wheel, {{0, 0, kRadiusM - 0.01}, {0, 1, 0}}, motion, 1e-3, state);
    return std::pair{f.force.y(), f.force.z()};
  };
  const auto [steady, load] = lateral(0.02);
  EXPECT_LT(steady, -0.05 * load) << "the side slip is resisted";
  // Below the ramp (>= the slip floor, 1 mm/s) F_y is proportional to v_y.
  const double slope = lateral(1e-5).first / 1e-5;
  EXPECT_LT(slope, 0.0);
  for (const double v_y : {1e-12, 1e-9, 1e-6}) {
    const double f = lateral(v_y).first;
    EXPECT_NEAR(f / v_y, slope, 0.01 * std::abs(slope)) << v_y;
    EXPECT_EQ(lateral(-v_y).first, -f) << v_y;
  }
  EXPECT_LT(std::abs(lateral(1e-12).first), 1e-6 * load);
}

}  // namespace
}  // namespace wtc
