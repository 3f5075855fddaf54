// The soil grid (src/terrain/soil_grid.hpp): a ground's memory costs only
// the nodes a wheel touched, at most 16 bytes each along a rut (issue 55),
// does not grow over the same ground, interpolates between its nodes, and
// refuses a grid too fine or too large with the numbers.
#include "terrain/soil_grid.hpp"
#include "tyre/soil_grid_profile.hpp"

#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "soil_profiles.hpp"
#include "wtc/base/error.hpp"
#include "wtc/tyre/wheel_soil.hpp"

namespace wtc::detail {
namespace {

SoilRegion field(double size_m, double spacing_m) {
  SoilRegion spec;
  spec.origin = {-0.5 * size_m, -0.5 * size_m};
  spec.size = {size_m, size_m};
  spec.spacing = spacing_m;
  return spec;
}

// A straight rut, a wheel 0.11 m wide driven `length` along x at y = y0:
// every node under its width touched, as a pass writes them.
void rut(SoilGrid& grid, double y0, double length, float depth) {
  const SoilRegion& s = grid.spec();
  const int j0 = static_cast<int>(std::ceil((y0 - 0.055 - s.origin.y()) / s.spacing));
  const int j1 = static_cast<int>(std::floor((y0 + 0.055 - s.origin.y()) / s.spacing));
  const int i1 = static_cast<int>(std::floor((-0.5 * s.size.x() + length) / s.spacing));
  for (int i = 0; i <= i1; ++i) {
    for (int j = j0; j <= j1; ++j) {
      const SoilNode n = grid.node(i, j);
      grid.set(i, j, {std::max(n.plastic_sinkage, depth), std::max(n.max_pressure, 2e4f)});
    }
  }
}

TEST(SoilGridTest, UntouchedGroundCostsNothingAndReadsFresh) {
  const SoilGrid grid(field(50.0, 0.02));
  EXPECT_EQ(grid.columns(), 2501);
  EXPECT_EQ(grid.touchedNodes(), 0u);
  EXPECT_EQ(grid.tiles(), 0u);
  EXPECT_EQ(grid.node(1200, 1300).plastic_sinkage, 0.0f);
  EXPECT_EQ(grid.sample(3.0, -4.0).max_pressure, 0.0f);
  EXPECT_LT(grid.bytes(), 64u);  // an empty index
}

// Four ruts side by side over 50 m at 2 and 1 cm, then the same ruts ten
// times again: at most 16 bytes per touched node, and no growth.
TEST(SoilGridTest, ARutCostsAtMostSixteenBytesANodeAndRepassesCostNothing) {
  for (const double spacing : {0.02, 0.01}) {
    SoilGrid grid(field(50.0, spacing));
    for (const double y : {-0.6, -0.2, 0.2, 0.6}) rut(grid, y, 50.0, 0.01f);
    const std::size_t touched = grid.touchedNodes(), bytes = grid.bytes();
    const double per_node = static_cast<double>(bytes) / static_cast<double>(touched);
    EXPECT_LE(per_node, 16.0) << spacing;
    RecordProperty("bytes_per_touched_node_at_" + std::to_string(static_cast<int>(spacing * 1e3)) + "_mm",
                   std::to_string(per_node));
    for (int pass = 0; pass < 10; ++pass) {
      for (const double y : {-0.6, -0.2, 0.2, 0.6}) rut(grid, y, 50.0, 0.012f);
    }
    EXPECT_EQ(grid.touchedNodes(), touched);
    EXPECT_EQ(grid.bytes(), bytes);
  }
}

// The largest pressure is kept as a bfloat16 rounded up: never below what
// was written, within 2^-7 above it.
TEST(SoilGridTest, TheLargestPressureIsKeptRoundedUp) {
  SoilGrid grid(field(1.0, 0.02));
  for (const float p : {0.0f, 1.0f, 12345.678f, 2.5e5f, 3.14159e6f}) {
    grid.set(3, 4, {0.0f, p});
    const float kept = grid.node(3, 4).max_pressure;
    EXPECT_GE(kept, p);
    EXPECT_LE(kept, p * (1.0f + 1.0f / 128.0f)) << p;
  }
}

// Bilinear: a plane of sinkage over the nodes is read back exactly between
// them; outside the region the ground is fresh.
TEST(SoilGridTest, SamplesInterpolateBetweenNodes) {
  SoilGrid grid(field(1.0, 0.05));
  const auto plane = [&](int i, int j) { return static_cast<float>(0.001 * i + 0.0005 * j); };
  for (int i = 0; i < grid.columns(); ++i) {
    for (int j = 0; j < grid.rows(); ++j) grid.set(i, j, {plane(i, j), 0.0f});
  }
  for (const auto& [x, y] : {std::pair{0.013, -0.21}, {-0.5, -0.5}, {0.5, 0.5}, {0.4999, 0.0001}}) {
    const double i = (x + 0.5) / 0.05, j = (y + 0.5) / 0.05;
    EXPECT_NEAR(grid.sample(x, y).plastic_sinkage, 0.001 * i + 0.0005 * j, 1e-6) << x << " " << y;
  }
  EXPECT_EQ(grid.sample(0.6, 0.0).plastic_sinkage, 0.0f);
  EXPECT_FALSE(grid.contains(0.6, 0.0));
  EXPECT_TRUE(grid.contains(0.5, -0.5));
}

TEST(SoilGridTest, AGridTooFineOrTooLargeIsRefusedWithItsNumbers) {
  try {
    validate(field(1.0, 5e-4), "soil 'sand'");
    FAIL() << "no exception";
  } catch (const InvalidInputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("soil 'sand': spacing 5e-04 m: must be at least 0.001 m"));
  }
  SoilRegion large = field(2000.0, 0.01);  // 4e10 nodes
  try {
    validate(large, "soil 'sand'");
    FAIL() << "no exception";
  } catch (const InvalidInputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("beyond the cap of"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("2000 x 2000 m at 0.01 m"));
  }
  large.memory_cap_bytes = 1e12;
  EXPECT_NO_THROW(validate(large, "soil 'sand'"));
  SoilRegion flat = field(1.0, 0.02);
  flat.size.y() = 0.0;
  EXPECT_THROW(validate(flat, "soil"), InvalidInputError);
  flat.size.y() = std::nan("");
  EXPECT_THROW(validate(flat, "soil"), InvalidInputError);
}

// The wheel reads the grid through GridProfile: untouched ground is fresh
// (part 1's forces to 1e-12), and a rut written into the nodes answers as the
// same rut given directly, to the nodes' single precision.
TEST(SoilGridTest, AProfileReadsUntouchedGroundAsFreshAndARutAsItsNodes) {
  const Soil soil = *namedSoil("toyoura_sand");
  SoilGrid grid(field(4.0, 0.02));
  WheelSoilState wheel{.radius = 0.09, .width = 0.11, .sinkage = 0.023, .slip = 0.2};
  const WheelSoilForces part1 = wheelSoilForces(soil, wheel);
  const GridProfile profile(grid, {0.3, 0.1}, {1.0, 0.0});
  wheel.memory = &profile;
  EXPECT_NEAR(wheelSoilForces(soil, wheel).normal, part1.normal, 1e-12 * part1.normal);
  for (int i = 0; i < grid.columns(); ++i) {
    for (int j = 0; j < grid.rows(); ++j) grid.set(i, j, {0.02f, 1.5e4f});
  }
  const SoilMemory rut{.plastic_sinkage = 0.02f, .max_pressure = grid.node(0, 0).max_pressure, .fresh = false};
  const testing::UniformProfile uniform(rut);
  wheel.sinkage = 0.026;
  const WheelSoilForces from_grid = wheelSoilForces(soil, wheel);
  wheel.memory = &uniform;
  const WheelSoilForces direct = wheelSoilForces(soil, wheel);
  EXPECT_GT(direct.normal, 0.0);
  EXPECT_NEAR(from_grid.normal, direct.normal, 1e-6 * direct.normal);
  EXPECT_NEAR(from_grid.torque, direct.torque, 1e-6 * std::abs(direct.torque));
}

}  // namespace
}  // namespace wtc::detail
