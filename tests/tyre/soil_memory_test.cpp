// The wheel's stresses on ground that remembers (wtc/tyre/wheel_soil.hpp,
// issue 55): a fresh memory is part 1's surface, a wheel pressed again at
// the same load into the hollow it left sinks by the elastic part only,
// and rolling passes in one rut deepen it by less each time.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "soil_profiles.hpp"
#include "wtc/tyre/wheel_soil.hpp"

namespace wtc {
namespace {

constexpr double kRadiusM = 0.09, kWidthM = 0.11, kLoadN = 64.68;

using testing::FunctionProfile;
using testing::UniformProfile;

TEST(SoilMemoryTest, AFreshMemoryIsPartOnesSurface) {
  const UniformProfile fresh;
  for (const std::string& name : soilNames()) {
    const Soil soil = *namedSoil(name);
    for (const double z : {0.002, 0.02, 0.05}) {
      for (const double i : {-0.5, 0.0, 0.3, 0.9}) {
        WheelSoilState state{.radius = kRadiusM, .width = kWidthM, .sinkage = z, .slip = i, .slip_angle = 0.1};
        const WheelSoilForces part1 = wheelSoilForces(soil, state);
        state.memory = &fresh;
        const WheelSoilForces remembered = wheelSoilForces(soil, state);
        const double scale = 1e-12 * part1.normal;
        EXPECT_NEAR(remembered.normal, part1.normal, scale) << name << " z " << z << " i " << i;
        EXPECT_NEAR(remembered.drawbar_pull, part1.drawbar_pull, scale) << name;
        EXPECT_NEAR(remembered.torque, part1.torque, scale * kRadiusM) << name;
        EXPECT_NEAR(remembered.lateral, part1.lateral, scale) << name;
        EXPECT_NEAR(remembered.peak_stress, part1.peak_stress, 1e-12 * part1.peak_stress) << name;
      }
    }
  }
}

// The sinkage of a wheel at rest (the symmetric hollow) carrying `load`
// on `memory` (null: fresh), by bisection below the fresh surface.
double restingSinkage(const Soil& soil, const SoilMemoryProfile* memory, double load) {
  WheelSoilState state{.radius = kRadiusM, .width = kWidthM, .symmetry = 1.0, .memory = memory};
  double lo = -kRadiusM, hi = 2 * kRadiusM;
  while (hi - lo > 1e-13) {
    state.sinkage = 0.5 * (lo + hi);
    (wheelSoilForces(soil, state).normal < load ? lo : hi) = state.sinkage;
  }
  return 0.5 * (lo + hi);
}

// Wong's repetitive loading: pressed to W, each point under the wheel at
// depth Z(x) carried sigma(x) = k Z^n and keeps z_p = Z - sigma / k_u once
// the wheel is lifted (pressedSoil). Pressed again at W the wheel returns
// to the same depth: from the rebounded surface it sinks by sigma / k_u,
// the elastic part, and no more.
TEST(SoilMemoryTest, PressedAgainAtTheSameLoadAWheelSinksByTheElasticPartOnly) {
  for (const char* name : {"toyoura_sand", "lete_sand"}) {
    const Soil soil = *namedSoil(name);
    const double first = restingSinkage(soil, nullptr, kLoadN);
    const FunctionProfile hollow([&](double x, double) {
      const double depth = first - (kRadiusM - std::sqrt(std::max(0.0, kRadiusM * kRadiusM - x * x)));
      return pressedSoil(soil, kWidthM, SoilMemory{}, depth);
    });
    const double elastic = hollow.at(0.0).max_pressure / soil.unloading_stiffness;
    const double again = restingSinkage(soil, &hollow, kLoadN);
    EXPECT_NEAR(again, first, 1e-9) << name;
    EXPECT_NEAR(again - hollow.at(0.0).plastic_sinkage, elastic, 1e-9) << name;
    // A lighter wheel rides on the compacted hollow: elastic, shallower.
    const double lighter = restingSinkage(soil, &hollow, 0.5 * kLoadN);
    EXPECT_LT(lighter, first) << name;
    EXPECT_GT(lighter, hollow.at(0.0).plastic_sinkage) << name;
    RecordProperty(std::string(name) + "_first_mm", std::to_string(first * 1e3));
    RecordProperty(std::string(name) + "_elastic_part_mm", std::to_string(elastic * 1e3));
  }
}

// The foot of the unloading line: a fresh point pressed to Z keeps
// Z - k Z^n / k_u and k Z^n; pressed again to Z or less it keeps that (a
// wheel at rest presses the same nodes every step), deeper it follows the
// virgin curve again.
TEST(SoilMemoryTest, APressedPointKeepsTheFootOfItsUnloadingLine) {
  for (const std::string& name : soilNames()) {
    const Soil soil = *namedSoil(name);
    const double k = soil.k_c / kWidthM + soil.k_phi, z = 0.015;
    const SoilMemory once = pressedSoil(soil, kWidthM, SoilMemory{}, z);
    const double sigma = k * std::pow(z, soil.n);
    EXPECT_FALSE(once.fresh);
    EXPECT_DOUBLE_EQ(once.max_pressure, sigma) << name;
    EXPECT_DOUBLE_EQ(once.plastic_sinkage, z - sigma / soil.unloading_stiffness) << name;
    EXPECT_GT(once.plastic_sinkage, 0.9 * z) << name << ": the elastic part is small";
    for (const double again : {z, 0.5 * z, once.plastic_sinkage, -0.01}) {
      const SoilMemory twice = pressedSoil(soil, kWidthM, once, again);
      EXPECT_NEAR(twice.plastic_sinkage, once.plastic_sinkage, 1e-12 * z) << name << " at " << again;
      EXPECT_EQ(twice.max_pressure, once.max_pressure) << name << " at " << again;
    }
    const SoilMemory deeper = pressedSoil(soil, kWidthM, once, 2 * z);
    EXPECT_DOUBLE_EQ(deeper.max_pressure, k * std::pow(2 * z, soil.n)) << name;
    EXPECT_GT(deeper.plastic_sinkage, once.plastic_sinkage) << name;
    EXPECT_EQ(pressedSoil(soil, kWidthM, SoilMemory{}, -0.01).fresh, true) << "above the surface nothing changes";
  }
}

// Rolling passes in one rut (slip 0.2): the rim's lowest point presses
// the ground under it to the wheel's sinkage, which keeps the foot of its
// unloading line (pressedSoil); the next wheel meets that uniform rut. The
// rut deepens with each pass, by less each time: the model's own prediction
// that the ground's memory in a run is checked against
// (tests/tyre/ground_memory_test.cpp).
TEST(SoilMemoryTest, RollingPassesDeepenARutByLessEachTime) {
  const Soil soil = *namedSoil("toyoura_sand");
  SoilMemory rut;
  std::vector<double> depths;
  for (int pass = 0; pass < 5; ++pass) {
    const UniformProfile uniform(rut);
    const SoilSteadyState s =
        steadyWheelOnSoil(soil, kRadiusM, kWidthM, kLoadN, 0.2, 0.0, pass == 0 ? nullptr : &uniform);
    rut = pressedSoil(soil, kWidthM, rut, s.sinkage);
    const double floor = rut.plastic_sinkage;
    depths.push_back(floor);
    RecordProperty("rut_after_pass_" + std::to_string(pass + 1) + "_mm", std::to_string(floor * 1e3));
  }
  for (std::size_t k = 1; k < depths.size(); ++k) {
    EXPECT_GT(depths[k], depths[k - 1]) << k;
    if (k >= 2) {
      EXPECT_LT(depths[k] - depths[k - 1], depths[k - 1] - depths[k - 2]) << k;
    }
  }
}

}  // namespace
}  // namespace wtc
