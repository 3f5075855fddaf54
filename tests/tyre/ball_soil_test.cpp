// A ball on soft soil (wtc/tyre/wheel_soil.hpp, sphereSoilForces): at rest
// against the pressure k Z^n integrated over its spherical cap in closed
// form (written here, sharing no code with the library), the signs and
// mirror symmetries of a rolling and side-slipping ball, the memory read
// beside its centre line, and a ball caster set down on a slab, which
// rests where the cap carries it and, on ground that remembers, leaves a
// round hollow, not a wheel's flat-bottomed band.
#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "soil_profiles.hpp"
#include "wheel_sim.hpp"
#include "wtc/terrain/terrain_primitives.hpp"
#include "wtc/tyre/ground_memory.hpp"
#include "wtc/tyre/wheel_soil.hpp"

namespace wtc {
namespace ball_soil_test {

using testing::kGravityMps2;

constexpr double kRadiusM = 0.15;    // the towed system's ball casters
constexpr double kFloorMps = 0.005;  // soilSlip's floor

// The cap's load at rest: the ball's surface lies at depth
//   Z(rho) = z - r + sqrt(r^2 - rho^2)
// under the surface at rho off its axis, and carries k Z^n there, k = k_c /
// b + k_phi with b = 2 a, a = sqrt(z (2 r - z)) the patch's radius. With
// rho d rho = -(r - z + Z) dZ:
//   W = 2 pi k int_0^z Z^n (r - z + Z) dZ = 2 pi k ((r - z) z^(n+1) / (n+1) + z^(n+2) / (n+2)).
// (The slices' normal stress at rest is the vertical pressure over this
// cap exactly: rho_s (cos theta - cos theta_1) is the rim's depth below the
// surface and rho_s cos theta d theta the horizontal dx.)
double capLoad(const Soil& s, double r, double z) {
  const double a = std::sqrt(z * (2 * r - z)), k = s.k_c / (2 * a) + s.k_phi, n = s.n;
  return 2 * std::numbers::pi * k * ((r - z) * std::pow(z, n + 1) / (n + 1) + std::pow(z, n + 2) / (n + 2));
}

SphereSoilState ball(double sinkage, double travel, double rim, double side = 0.0) {
  return {.radius = kRadiusM, .sinkage = sinkage, .travel_speed = travel, .rim_speed = rim,
          .side_slip_speed = side, .speed_floor = kFloorMps};
}

TEST(BallSoilTest, AtRestABallCarriesThePressureOverItsCap) {
  double worst = 0.0;
  for (const std::string& name : soilNames()) {
    const Soil soil = *namedSoil(name);
    for (const double z : {0.0015, 0.015, 0.05, 0.1, 0.15}) {
      SphereSoilState state = ball(z, 0.0, 0.0);
      state.symmetry = 1.0;
      const WheelSoilForces f = sphereSoilForces(soil, state);
      EXPECT_NEAR(f.normal, capLoad(soil, kRadiusM, z), 2e-4 * f.normal) << name << " z " << z;
      worst = std::max(worst, std::abs(f.normal / capLoad(soil, kRadiusM, z) - 1.0));
      EXPECT_NEAR(f.drawbar_pull, 0.0, 1e-12 * f.normal) << name;
      EXPECT_EQ(f.lateral, 0.0) << name;
      EXPECT_NEAR(f.torque, 0.0, 1e-9 * f.normal * kRadiusM) << name;
      // The patch is the cap's disc, pi a^2.
      EXPECT_NEAR(f.patch_area, std::numbers::pi * z * (2 * kRadiusM - z), 2e-3 * f.patch_area) << name;
    }
  }
  RecordProperty("worst_load_relative", std::to_string(worst));
}

// Driving pulls and costs torque; a free-rolling ball is resisted (the
// compaction of its track); a side slip is resisted both ways alike, and
// the bulldozing of its leading side adds to it.
TEST(BallSoilTest, ARollingBallPullsWhenDrivenAndIsResistedWhenFree) {
  const Soil soil = *namedSoil("sandy_loam");
  const double z = 0.02, v = 0.5;
  const WheelSoilForces driven = sphereSoilForces(soil, ball(z, v, v / 0.7));  // slip 0.3 at the equator
  EXPECT_GT(driven.drawbar_pull, 0.0);
  EXPECT_GT(driven.torque, 0.0);
  const WheelSoilForces free = sphereSoilForces(soil, ball(z, v, v));
  EXPECT_LT(free.drawbar_pull, 0.0);
  EXPECT_GT(free.normal, 0.0);
  const WheelSoilForces left = sphereSoilForces(soil, ball(z, v, v, 0.1));
  const WheelSoilForces right = sphereSoilForces(soil, ball(z, v, v, -0.1));
  EXPECT_LT(left.lateral, 0.0);
  EXPECT_NEAR(left.lateral, -right.lateral, 1e-12 * std::abs(left.lateral));
  EXPECT_NEAR(left.normal, right.normal, 1e-12 * left.normal);
  EXPECT_GT(left.bulldozing, 0.0);
  EXPECT_EQ(free.bulldozing, 0.0);
  RecordProperty("free_resistance_over_load", std::to_string(-free.drawbar_pull / free.normal));
  RecordProperty("driven_pull_over_load", std::to_string(driven.drawbar_pull / driven.normal));
}

using testing::FunctionProfile;
using testing::UniformProfile;

// Fresh memory is no memory; a rut beside the centre line is read by the
// slices over it (the ball carries less), the same on either side.
TEST(BallSoilTest, ItsSlicesReadTheMemoryBesideTheCentreLine) {
  const Soil soil = *namedSoil("sandy_loam");
  const double z = 0.03, v = 0.3;
  const UniformProfile fresh;
  SphereSoilState state = ball(z, v, v / 0.8);
  const WheelSoilForces none = sphereSoilForces(soil, state);
  state.memory = &fresh;
  const WheelSoilForces remembered = sphereSoilForces(soil, state);
  EXPECT_NEAR(remembered.normal, none.normal, 1e-9 * none.normal);
  EXPECT_NEAR(remembered.drawbar_pull, none.drawbar_pull, 1e-9 * none.normal);
  EXPECT_NEAR(remembered.torque, none.torque, 1e-9 * none.normal * kRadiusM);

  const SoilMemory rut{.plastic_sinkage = 0.02, .max_pressure = 1e5, .fresh = false};
  const FunctionProfile left([&](double, double aside) { return aside > 0.02 ? rut : SoilMemory{}; });
  const FunctionProfile right([&](double, double aside) { return aside < -0.02 ? rut : SoilMemory{}; });
  state.memory = &left;
  const WheelSoilForces on_left = sphereSoilForces(soil, state);
  state.memory = &right;
  const WheelSoilForces on_right = sphereSoilForces(soil, state);
  EXPECT_LT(on_left.normal, 0.95 * none.normal);
  EXPECT_NEAR(on_left.normal, on_right.normal, 1e-9 * none.normal);
}

// The ball sinkage at rest under `load` (bisection on the closed form).
double capSinkage(const Soil& soil, double load) {
  double lo = 0.0, hi = kRadiusM;
  while (hi - lo > 1e-12) {
    const double mid = 0.5 * (lo + hi);
    (capLoad(soil, kRadiusM, mid) < load ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// A ball caster of kLoadN set down on a sandy loam slab remembering at
// `spacing` (0: nowhere), its weight growing over 2 s and then held (set
// down gently: a plunge overshoots, and the ground keeps the overshoot).
// It spins about any axis (a ball joint), which tests/support's wheel,
// spinning about its axle only, cannot: its own semi-implicit Euler loop.
constexpr double kLoadN = 1000.0;

struct SetDown {
  Terrain ground;
  std::unique_ptr<GroundMemory> memory;
  double sinkage = 0.0, speed = 0.0;
};

// A 4 x 4 m slab of `soil` (top z = 0), remembering over its middle 2 x 2 m
// at `spacing` (0: nowhere).
Terrain soilSlab(const Soil& soil, double spacing) {
  TerrainBuilder builder;
  Material material;
  material.name = soil.name;
  material.soil = soil;
  SlabParams slab;
  slab.size_x = slab.size_y = 4.0;
  addSlab(builder, slab, builder.addMaterial(material));
  if (spacing > 0.0) {
    SoilRegion region;
    region.origin = {-1.0, -1.0};
    region.size = {2.0, 2.0};
    region.spacing = spacing;
    builder.addSoilRegion(region);
  }
  return std::move(builder).build();
}

SetDown setDown(const Soil& soil, double spacing) {
  SetDown out{.ground = soilSlab(soil, spacing), .memory = nullptr};
  out.memory = std::make_unique<GroundMemory>(out.ground);

  constexpr double kStepS = 1e-3;
  const double mass = kLoadN / kGravityMps2, inertia = 0.4 * mass * kRadiusM * kRadiusM;  // a solid ball
  WheelDescription description;
  description.geometry.free_radius = kRadiusM;
  description.geometry.tread_width = 2 * kRadiusM;  // a whole sphere
  description.inertia = {.effective_mass = mass, .axial_inertia = inertia};
  WheelState state;
  state.setGroundMemory(out.memory.get());
  const TyreModel model(EffectSet{Effect::kSoftSoil});
  Eigen::Vector3d at(0, 0, kRadiusM), velocity = Eigen::Vector3d::Zero(), spin = Eigen::Vector3d::Zero();
  for (int k = 0; k < 6000; ++k) {
    const double gravity = std::min(1.0, k * kStepS / 2.0) * kGravityMps2;
    const WheelForces& f = model.step(out.ground, description, {at, Eigen::Vector3d::UnitY()}, {velocity, spin},
                                      kStepS, state);
    velocity += kStepS * (f.force / mass - gravity * Eigen::Vector3d::UnitZ());
    at += kStepS * velocity;
    spin += kStepS * f.torque / inertia;
  }
  out.sinkage = kRadiusM - at.z();
  out.speed = velocity.norm() + kRadiusM * spin.norm();
  return out;
}

// On soil that forgets the ball rests where its cap carries it. On soil
// that remembers it leaves a round hollow: the nodes 4 cm ahead of its
// centre and 4 cm beside it lie at the same depth, the sphere's, less the
// elastic part (as closely as the nodes hold the sphere's shape: s^2 /
// (8 r), 0.33 mm at 2 cm). It rests a little deeper there: between the
// last pressed node and the first fresh one the remembered surface is a
// chord above the cap's edge, which carries nothing under it; the excess
// shrinks with the spacing.
TEST(BallSoilTest, ABallCasterRestsWhereItsCapCarriesItAndLeavesARoundHollow) {
  const Soil soil = *namedSoil("sandy_loam");
  const SetDown fresh = setDown(soil, 0.0);
  const double expected = capSinkage(soil, kLoadN);
  EXPECT_LT(fresh.speed, 1e-4);
  EXPECT_NEAR(fresh.sinkage, expected, 1e-3 * expected) << "rests where its cap carries it";

  const SetDown coarse = setDown(soil, 0.02), fine = setDown(soil, 0.01);
  EXPECT_LT(coarse.speed, 1e-4);
  const GroundMemory& memory = *coarse.memory;
  const double sinkage = coarse.sinkage, sag = 0.02 * 0.02 / (8 * kRadiusM);
  const SoilMemory centre = memory.at(0.0, 0.0), ahead = memory.at(0.04, 0.0), beside = memory.at(0.0, 0.04);
  ASSERT_FALSE(ahead.fresh);
  ASSERT_FALSE(beside.fresh);
  EXPECT_NEAR(ahead.plastic_sinkage, beside.plastic_sinkage, 1e-6) << "a round hollow";
  EXPECT_NEAR(centre.plastic_sinkage, sinkage - centre.max_pressure / soil.unloading_stiffness, sag);
  const double sphere = sinkage - (kRadiusM - std::sqrt(kRadiusM * kRadiusM - 0.04 * 0.04));
  EXPECT_NEAR(beside.plastic_sinkage, sphere - beside.max_pressure / soil.unloading_stiffness, sag);
  const double patch = std::sqrt(sinkage * (2 * kRadiusM - sinkage));
  EXPECT_TRUE(memory.at(0.0, patch + 0.02).fresh) << "beyond the patch's radius " << patch;

  EXPECT_GT(coarse.sinkage, fine.sinkage);
  EXPECT_GT(fine.sinkage, fresh.sinkage);
  EXPECT_LT(coarse.sinkage - fresh.sinkage, 0.05 * fresh.sinkage);
  EXPECT_LT(fine.sinkage - fresh.sinkage, 0.6 * (coarse.sinkage - fresh.sinkage)) << "shrinks with the spacing";
  RecordProperty("closed_form_sinkage_mm", std::to_string(expected * 1e3));
  RecordProperty("fresh_sinkage_mm", std::to_string(fresh.sinkage * 1e3));
  RecordProperty("remembering_sinkage_2cm_mm", std::to_string(coarse.sinkage * 1e3));
  RecordProperty("remembering_sinkage_1cm_mm", std::to_string(fine.sinkage * 1e3));
}

// A ball rolling along a rut a narrower ball left (0.1 m), whose floor
// lies 0.1 um above the ball's lowest point: its centre line meets the
// remembered surface right at the bottom (the entry's sinkage z a fraction
// of a micrometre) while the rut's walls, steeper than the ball, carry W on
// the reloading line beside it. The soil's spring reported (the stability
// report's, the engine-solved modes' row) is at most that line, k_u over
// the patch; the tangent (n + 1) W / z was 1e4 times stiffer, and wtc-sim
// warned on towed_loam's front caster in such a rut.
TEST(BallSoilTest, InANarrowerRutABallsSoilSpringIsAtMostTheReloadingLine) {
  const Soil soil = *namedSoil("sandy_loam");
  const Terrain ground = soilSlab(soil, 0.01);
  GroundMemory memory(ground);
  constexpr double kSinkageM = 0.05, kRutRadiusM = 0.1, kFloorAboveM = 1e-7;
  for (int i = -20; i <= 20; ++i) {
    for (int j = -9; j <= 9; ++j) {
      const double x = 0.01 * i, y = 0.01 * j;
      const double floor = kSinkageM - kFloorAboveM - (kRutRadiusM - std::sqrt(kRutRadiusM * kRutRadiusM - y * y));
      if (floor <= 0.0) continue;
      ASSERT_TRUE(memory.setNode(x, y, {.plastic_sinkage = floor, .max_pressure = 1e5, .fresh = false}));
    }
  }
  WheelDescription ball;
  ball.geometry.free_radius = kRadiusM;
  ball.geometry.tread_width = 2 * kRadiusM;
  ball.inertia = {.effective_mass = 10.0, .axial_inertia = 0.09};
  WheelState state;
  state.setGroundMemory(&memory);
  const TyreModel model(EffectSet{Effect::kSoftSoil});
  const WheelMotion rolling{.velocity = {0.02, 0, 0}, .angular_velocity = {0, 0.02 / kRadiusM, 0}};
  const WheelForces& f =
      model.step(ground, ball, {{0, 0, kRadiusM - kSinkageM}, {0, 1, 0}}, rolling, 4e-4, state);
  ASSERT_EQ(f.contacts.size(), 1u);
  const ContactForce& c = f.contacts[0];
  EXPECT_GT(c.normal_force, 0.0);
  const double patch = std::numbers::pi * kSinkageM * (2 * kRadiusM - kSinkageM);
  EXPECT_LT(c.soil_sinkage, 1e-5) << "the centre line meets the rut's floor at the bottom";
  EXPECT_LE(c.soil_stiffness, soil.unloading_stiffness * patch);
  EXPECT_NEAR(c.soil_stiffness * c.soil_depth, c.normal_force, 0.05 * c.normal_force) << "the row carries W";
  EXPECT_EQ(state.unstableSteps(), 0u);
}

}  // namespace ball_soil_test
}  // namespace wtc
