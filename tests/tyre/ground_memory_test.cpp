// The ground that remembers, stepped in time (tests/support/wheel_sim.hpp's
// semi-implicit Euler loop, what an engine does in force mode) on a soil
// slab with a soil region (wtc/tyre/ground_memory.hpp): a wheel set down in
// the hollow it left sinks by the elastic part only, and rolling passes over
// one track leave, pass after pass, the rut the model predicts; outside a
// region the soil forgets as in part 1.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "soil_profiles.hpp"
#include "wheel_sim.hpp"
#include "wtc/terrain/terrain_primitives.hpp"
#include "wtc/tyre/ground_memory.hpp"
#include "wtc/tyre/wheel_soil.hpp"

namespace wtc {
namespace ground_memory_test {

using testing::kGravityMps2;
using testing::SimWheel;
using testing::step;

constexpr double kRadiusM = 0.09, kWidthM = 0.11, kLoadN = 64.68;  // Ishigami's wheel
constexpr double kStepS = 1e-3;
constexpr double kSpacingM = 0.02;  // the soil regions' grid

// A 4 x 4 m slab of Toyoura sand (top z = 0), remembering over `region`
// ([x0, y0, x1, y1], m) at a 2 cm spacing, or nowhere.
Terrain sandSlab(const std::vector<double>& region, double flow_factor = 0.0) {
  TerrainBuilder builder;
  Material sand;
  sand.name = "sand";
  sand.soil = *namedSoil("toyoura_sand");
  SlabParams slab;
  slab.size_x = slab.size_y = 4.0;
  addSlab(builder, slab, builder.addMaterial(sand));
  if (!region.empty()) {
    SoilRegion r;
    r.origin = {region[0], region[1]};
    r.size = {region[2] - region[0], region[3] - region[1]};
    r.spacing = kSpacingM;
    r.flow_factor = flow_factor;
    builder.addSoilRegion(r);
  }
  return std::move(builder).build();
}

SimWheel ishigamiWheel(GroundMemory& memory, double load = kLoadN) {
  SimWheel wheel;
  wheel.description.geometry.free_radius = kRadiusM;
  wheel.description.geometry.tread_width = kWidthM;
  wheel.mass = load / kGravityMps2;
  wheel.center = {0, 0, kRadiusM};
  wheel.state.setGroundMemory(&memory);
  return wheel;
}

// Lets the wheel settle at rest for `seconds`; its sinkage below the fresh surface.
double settle(const TyreModel& model, const Terrain& ground, SimWheel& wheel, double seconds) {
  for (int k = 0; k < static_cast<int>(seconds / kStepS); ++k) step(model, ground, kStepS, wheel);
  EXPECT_LT(std::abs(wheel.velocity.z()), 1e-4);
  return kRadiusM - wheel.center.z();
}

// Wong's repetitive loading in a run. Set down on fresh sand, the wheel sinks
// to d1 and leaves a hollow whose floor is d1 less the elastic part, as
// closely as nodes 2 cm apart hold a rim's shape: between two nodes the
// rim sags below their chord by up to s^2 / (8 r) (0.56 mm here, against an
// elastic part of 0.06 mm; the wheel rests on those chords). Lifted and set
// down again at the hollow's floor it goes back to d1, sinking by no more
// than the elastic part and that sag. A wheel half again as heavy goes on down the virgin
// curve, at least to where the fresh sand carries it at rest: further by
// what its plunge overshoots, which the ground keeps (the memoryless
// fresh surface gives that back).
TEST(GroundMemoryTest, SetDownAgainInItsHollowAWheelSinksByTheElasticPartOnly) {
  const TyreModel model(EffectSet{Effect::kSoftSoil});
  const Soil soil = *namedSoil("toyoura_sand");
  const Terrain ground = sandSlab({-1, -1, 1, 1});
  GroundMemory memory(ground);
  SimWheel wheel = ishigamiWheel(memory);
  const double first = settle(model, ground, wheel, 3.0);
  const SoilMemory floor = memory.at(0.0, 0.0);
  EXPECT_FALSE(floor.fresh);
  EXPECT_GT(memory.touchedNodes(), 0u);
  const double elastic = floor.max_pressure / soil.unloading_stiffness;
  const double sag = kSpacingM * kSpacingM / (8.0 * kRadiusM);
  EXPECT_NEAR(floor.plastic_sinkage, first - elastic, sag);

  // Lifted (a step clear of the ground), set down on the floor at rest.
  wheel.center.z() = kRadiusM + 0.01;
  step(model, ground, kStepS, wheel);
  wheel.center.z() = kRadiusM - floor.plastic_sinkage;
  wheel.velocity.setZero();
  const double again = settle(model, ground, wheel, 2.0);
  EXPECT_NEAR(again, first, 1e-3 * first);
  EXPECT_LT(again - floor.plastic_sinkage, elastic + sag) << "sinks by the elastic part and the chords' sag";
  RecordProperty("first_sinkage_mm", std::to_string(first * 1e3));
  RecordProperty("hollow_floor_mm", std::to_string(floor.plastic_sinkage * 1e3));
  RecordProperty("second_sinkage_mm", std::to_string(again * 1e3));

  // Heavier: beyond the largest pressure the hollow carried, the virgin curve.
  SimWheel heavy = ishigamiWheel(memory, 1.5 * kLoadN);
  heavy.center.z() = kRadiusM - first;
  const double deeper = settle(model, ground, heavy, 3.0);
  const Terrain fresh_ground = sandSlab({});
  GroundMemory none(fresh_ground);
  SimWheel fresh = ishigamiWheel(none, 1.5 * kLoadN);
  const double on_fresh = settle(model, fresh_ground, fresh, 3.0);
  EXPECT_GT(deeper, 0.99 * on_fresh);
  RecordProperty("heavier_sinkage_mm", std::to_string(deeper * 1e3));
  RecordProperty("heavier_on_fresh_mm", std::to_string(on_fresh * 1e3));
}

// Passes over one track at slip 0.3, each wheel on a carriage at 0.05 m/s
// from x = -0.1 m to 0.6 m. Where a rut ends, the next wheel plunges into
// the end's hollow as its front reaches it, and deepens the rut before it:
// the disturbance moves back 3-5 cm a pass (ending the passes at 0.2 m, it
// reached x = 0.06 m by the fourth). Over x in [0.05, 0.10] m, well before
// it, each pass sinks to the steady state on the
// rut the passes before it left there (steadyWheelOnSoil with that memory,
// uniform), and leaves the rut pressedSoil gives at its sinkage: the
// prediction of tests/tyre/soil_memory_test.cpp, now in a run on a 2 cm
// grid. The chain of predictions from fresh sand alone is recorded beside
// it (each pass's 1-2 % compounds along it).
TEST(GroundMemoryTest, RollingPassesLeaveTheRutTheModelPredicts) {
  const TyreModel model(EffectSet{Effect::kSoftSoil});
  const Soil soil = *namedSoil("toyoura_sand");
  const Terrain ground = sandSlab({-1, -1, 1, 1});
  GroundMemory memory(ground);
  const double speed = 0.05, slip = 0.3, x_mid = 0.075;
  SoilMemory chain;  // the prediction from fresh sand alone
  std::vector<double> sinkages;
  for (int pass = 1; pass <= 5; ++pass) {
    const testing::UniformProfile before(memory.at(x_mid, 0.0)), chained(chain);
    const SoilSteadyState want =
        steadyWheelOnSoil(soil, kRadiusM, kWidthM, kLoadN, slip, 0.0, pass == 1 ? nullptr : &before);
    const double chain_sinkage =
        steadyWheelOnSoil(soil, kRadiusM, kWidthM, kLoadN, slip, 0.0, pass == 1 ? nullptr : &chained).sinkage;
    chain = pressedSoil(soil, kWidthM, chain, chain_sinkage);

    SimWheel wheel = ishigamiWheel(memory);
    wheel.center.x() = -0.1;
    wheel.center.z() = kRadiusM - memory.at(-0.1, 0.0).plastic_sinkage;
    wheel.locked = true;
    wheel.spin = speed / (kRadiusM * (1 - slip));
    double sinkage = 0.0;
    int n = 0;
    for (int k = 0; k < 14000; ++k) {
      wheel.velocity.x() = speed;
      step(model, ground, kStepS, wheel);
      if (wheel.center.x() >= 0.05 && wheel.center.x() <= 0.10) {
        sinkage += kRadiusM - wheel.center.z();
        ++n;
      }
    }
    sinkage /= n;
    sinkages.push_back(sinkage);
    EXPECT_NEAR(sinkage, want.sinkage, 0.02 * want.sinkage) << "pass " << pass;
    const SoilMemory rut = pressedSoil(soil, kWidthM, before.at(0.0), sinkage);
    EXPECT_NEAR(memory.at(x_mid, 0.0).plastic_sinkage, rut.plastic_sinkage, 0.02 * rut.plastic_sinkage)
        << "pass " << pass;
    const std::string p = "pass_" + std::to_string(pass);
    RecordProperty(p + "_sinkage_mm", std::to_string(sinkage * 1e3));
    RecordProperty(p + "_predicted_mm", std::to_string(want.sinkage * 1e3));
    RecordProperty(p + "_rut_mm", std::to_string(memory.at(x_mid, 0.0).plastic_sinkage * 1e3));
    RecordProperty(p + "_chain_predicted_rut_mm", std::to_string(chain.plastic_sinkage * 1e3));
  }
  for (std::size_t k = 1; k < sinkages.size(); ++k) EXPECT_GT(sinkages[k], sinkages[k - 1]) << k;
  // Only the track is stored: 6 nodes across a 0.11 m wheel, 0.8 m along.
  RecordProperty("touched_nodes", std::to_string(memory.touchedNodes()));
  RecordProperty("memory_bytes", std::to_string(memory.bytes()));
  EXPECT_LE(memory.touchedNodes(), 6u * 41u);
}

// Bulldozing (flow factor 0.5, repose 30 deg): of the soil one pass
// presses down, half is raised beside the track, the volume kept to a
// float's rounding, and no raised node stands above its outer neighbour by
// more than the angle of repose allows.
TEST(GroundMemoryTest, BulldozingRaisesTheFlowFactorsShareBesideTheTrack) {
  const TyreModel model(EffectSet{Effect::kSoftSoil});
  const double flow = 0.5;
  const Terrain ground = sandSlab({-1, -1, 1, 1}, flow);
  GroundMemory memory(ground);
  SimWheel wheel = ishigamiWheel(memory);
  wheel.center.x() = -0.5;
  wheel.locked = true;
  wheel.spin = 0.05 / (kRadiusM * 0.7);
  for (int k = 0; k < 10000; ++k) {
    wheel.velocity.x() = 0.05;
    step(model, ground, kStepS, wheel);
  }
  double pressed = 0.0, raised = 0.0, steepest = 0.0;
  const int n = static_cast<int>(std::lround(2.0 / kSpacingM));
  const auto height = [&](int i, int j) {  // of the surface above the fresh one (m)
    return -memory.at(-1.0 + i * kSpacingM, -1.0 + j * kSpacingM).plastic_sinkage;
  };
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const double h = height(i, j);
      (h < 0.0 ? pressed : raised) += std::abs(h) * kSpacingM * kSpacingM;
      // Outward across the track (y), beside it (|y| > b / 2).
      const double y = -1.0 + j * kSpacingM;
      if (std::abs(y) > 0.5 * kWidthM && j > 0 && j < n) {
        const int out = y > 0.0 ? j + 1 : j - 1;
        steepest = std::max(steepest, (h - height(i, out)) / kSpacingM);
      }
    }
  }
  EXPECT_GT(pressed, 0.0);
  EXPECT_NEAR(raised, flow * pressed, 1e-5 * pressed);
  // The touched nodes, listed (what the replay page draws), are the grid's
  // nodes the scan found changed, each with the memory at(x, y) reads there.
  std::size_t listed = 0;
  double listed_pressed = 0.0, listed_raised = 0.0;
  memory.forEachTouchedNode([&](double x, double y, const SoilMemory& m) {
    ++listed;
    const double i = (x + 1.0) / kSpacingM, j = (y + 1.0) / kSpacingM;
    EXPECT_NEAR(i, std::round(i), 1e-9);
    EXPECT_NEAR(j, std::round(j), 1e-9);
    // at() interpolates: at a node, to the rounding of (x - x0) / s.
    EXPECT_NEAR(m.plastic_sinkage, memory.at(x, y).plastic_sinkage, 1e-12);
    EXPECT_NEAR(m.max_pressure, memory.at(x, y).max_pressure, 1e-9 * m.max_pressure);
    (m.plastic_sinkage > 0.0 ? listed_pressed : listed_raised) += std::abs(m.plastic_sinkage) * kSpacingM * kSpacingM;
  });
  EXPECT_EQ(listed, memory.touchedNodes());
  EXPECT_NEAR(listed_pressed, pressed, 1e-12 * pressed);
  EXPECT_NEAR(listed_raised, raised, 1e-12 * pressed);
  EXPECT_LE(steepest, std::tan(30.0 * std::numbers::pi / 180.0) * 1.01);
  RecordProperty("pressed_volume_m3", std::to_string(pressed));
  RecordProperty("raised_volume_m3", std::to_string(raised));
  RecordProperty("steepest_outer_slope", std::to_string(steepest));
}

// Outside its regions the ground forgets: a wheel rolling there meets the
// fresh surface every step, exactly as without a memory, and stores nothing.
TEST(GroundMemoryTest, OutsideItsRegionsTheSoilForgets) {
  const TyreModel model(EffectSet{Effect::kSoftSoil});
  const Terrain ground = sandSlab({1.0, 1.0, 1.5, 1.5});
  GroundMemory memory(ground), unused(ground);
  SimWheel with = ishigamiWheel(memory), without = ishigamiWheel(unused);
  without.state.setGroundMemory(nullptr);
  for (SimWheel* w : {&with, &without}) w->drive_torque = 0.5;
  for (int k = 0; k < 1000; ++k) {
    step(model, ground, kStepS, with);
    step(model, ground, kStepS, without);
  }
  EXPECT_EQ(with.center, without.center);
  EXPECT_EQ(with.velocity, without.velocity);
  EXPECT_EQ(memory.touchedNodes(), 0u);
  EXPECT_EQ(memory.regionCount(), 1u);
  EXPECT_TRUE(memory.at(0.0, 0.0).fresh);
}

}  // namespace ground_memory_test
}  // namespace wtc
