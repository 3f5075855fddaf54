// A body's underside on soft soil (wtc/tyre/body_soil.hpp): a flat plate at
// rest sinks Bekker's z = (W / (A (k_c / b + k_phi)))^(1/n), a sliding
// one is held back by (c A + W tan phi), a plate set down again in the
// hollow it pressed sinks by the elastic part only, and hard ground and bad
// input give nothing or a clear error.
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "expect_refused.hpp"
#include "soil_plate.hpp"
#include "wtc/base/error.hpp"
#include "wtc/terrain/terrain_primitives.hpp"
#include "wtc/tyre/body_soil.hpp"
#include "wtc/tyre/ground_memory.hpp"

namespace wtc {
namespace body_soil_test {

constexpr double kGravityMps2 = 9.81;
constexpr double kStepS = 1e-3;
// A 0.5 m x 0.3 m plate whose edges lie on the 2 cm cells' edges (nodes at
// multiples of 2 cm, cells +-1 cm about them): 25 x 15 nodes, A exact.
constexpr double kLengthM = 0.5, kWidthM = 0.3, kThicknessM = 0.1;
constexpr double kMassKg = 60.0;

// A 4 m x 4 m slab of the named soil, remembering over [-1, 1]^2 when
// asked at the bodies' 2 cm; `soft` false: the same slab as hard ground.
Terrain soilSlab(const char* soil_name, bool remember, bool soft = true) {
  if (!soft) {
    TerrainBuilder builder;
    SlabParams slab;
    slab.size_x = slab.size_y = 4.0;
    addSlab(builder, slab, builder.addMaterial(Material{}));
    return std::move(builder).build();
  }
  std::optional<SoilRegion> region;
  if (remember) {
    region.emplace();
    region->origin = {-1.0, -1.0};
    region->size = {2.0, 2.0};
    region->spacing = kBodySoilSpacingM;
  }
  return testing::soilSlab(soil_name, 4.0, 4.0, region);
}

BodyOnSoil plate() {
  return BodyOnSoil({ConvexPolyhedron::box({-kLengthM / 2, -kWidthM / 2, -kThicknessM / 2},
                                           {kLengthM / 2, kWidthM / 2, kThicknessM / 2})},
                    kMassKg);
}

BodySoilMotion at(double bottom_z, const Eigen::Vector3d& velocity = Eigen::Vector3d::Zero()) {
  BodySoilMotion m;
  m.pose.translation() = Eigen::Vector3d(0, 0, bottom_z + kThicknessM / 2);
  m.velocity = velocity;
  return m;
}

// The depth at which the plate at rest carries `load` (bisection on the
// soil's normal force, which grows with the depth; nothing pressed).
double restingDepth(BodyOnSoil& body, const Terrain& terrain, double load) {
  double lo = 0.0, hi = 0.5;
  for (int k = 0; k < 80; ++k) {
    const double mid = 0.5 * (lo + hi);
    (body.step(terrain, nullptr, at(-mid), kStepS).normal_force < load ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(BodySoilTest, APlateAtRestSinksBekkersDepth) {
  for (const char* name : {"toyoura_sand", "sandy_loam", "lete_sand"}) {
    const Terrain terrain = soilSlab(name, false);
    const Soil soil = *namedSoil(name);
    BodyOnSoil body = plate();
    const double load = kMassKg * kGravityMps2;
    const double z = restingDepth(body, terrain, load);
    const double area = kLengthM * kWidthM;
    const double bekker = testing::bekkerPlateSinkage(soil, load, kLengthM, kWidthM);
    const BodySoilForces f = body.step(terrain, nullptr, at(-z), kStepS);
    EXPECT_EQ(f.nodes, 25 * 15) << name;
    EXPECT_NEAR(f.area, area, 1e-12) << name;
    EXPECT_NEAR(f.plate_width, kWidthM, 1e-12) << name;
    EXPECT_NEAR(z, bekker, 1e-9 * bekker) << name;
    // Uniform pressure about the centre: the moment about it vanishes.
    EXPECT_LT(f.torque.norm(), 1e-9 * load * kLengthM) << name;
    EXPECT_NEAR(f.force.z(), load, 1e-6 * load) << name;
    RecordProperty(std::string("bekker_depth_mm_") + name, std::to_string(1e3 * bekker));
    RecordProperty(std::string("depth_mm_") + name, std::to_string(1e3 * z));
  }
}

TEST(BodySoilTest, AnOffsetCellGridCountsTheCellsItsNodesStandFor) {
  // Shifted by 4 mm the plate's edges fall inside cells: its node count,
  // and so its area, is off by at most the cells along its edges.
  const Terrain terrain = soilSlab("toyoura_sand", false);
  BodyOnSoil body = plate();
  BodySoilMotion m = at(-0.01);
  m.pose.translation().x() += 0.004;
  m.pose.translation().y() += 0.004;
  const BodySoilForces f = body.step(terrain, nullptr, m, kStepS);
  const double area = kLengthM * kWidthM, edge_cells = (kLengthM + kWidthM) * kBodySoilSpacingM;
  EXPECT_LE(std::abs(f.area - area), edge_cells);
  EXPECT_GT(f.nodes, 0);
}

TEST(BodySoilTest, ASlidingPlateIsHeldBackByTheSoilsShearStrength) {
  const Terrain terrain = soilSlab("sandy_loam", false);
  const Soil soil = *namedSoil("sandy_loam");
  BodyOnSoil body = plate();
  const double z = 0.02;
  const BodySoilForces f = body.step(terrain, nullptr, at(-z, {1.0, 0.0, 0.0}), kStepS);
  const double expected =
      soil.cohesion * f.area + f.normal_force * std::tan(soil.friction_angle_deg * std::numbers::pi / 180);
  EXPECT_NEAR(f.force.x(), -expected, 1e-9 * expected);
  EXPECT_NEAR(f.force.y(), 0.0, 1e-9 * expected);
  // The shear acts on the underside, h/2 below the centre: a drag along -x
  // there turns the plate about +y (its nose down).
  EXPECT_NEAR(f.torque.y(), kThicknessM / 2 * expected, 1e-6 * expected);
  // At rest the shear is ramped to nothing.
  EXPECT_NEAR(body.step(terrain, nullptr, at(-z), kStepS).force.x(), 0.0, 1e-12);
}

TEST(BodySoilTest, ThePlatesDampingResistsItsSinking) {
  const Terrain terrain = soilSlab("toyoura_sand", false);
  const Soil soil = *namedSoil("toyoura_sand");
  BodyOnSoil body = plate();
  const double still = body.step(terrain, nullptr, at(-0.01), kStepS).normal_force;
  const double sinking = body.step(terrain, nullptr, at(-0.01, {0, 0, -0.1}), kStepS).normal_force;
  EXPECT_NEAR(sinking - still, soil.damping * 0.1 * kLengthM * kWidthM, 1e-9 * still);
}

TEST(BodySoilTest, APlateSetDownInItsOwnHollowSinksByTheElasticPartOnly) {
  const Terrain terrain = soilSlab("toyoura_sand", true);
  const Soil soil = *namedSoil("toyoura_sand");
  GroundMemory memory(terrain);
  BodyOnSoil body = plate();
  const double load = kMassKg * kGravityMps2;
  const double z = restingDepth(body, terrain, load);
  const BodySoilForces pressed = body.step(terrain, &memory, at(-z), kStepS);
  EXPECT_EQ(memory.touchedNodes(), 25u * 15u);
  const double sigma = pressed.normal_force / pressed.area;
  // Lifted off, the hollow stays: z_p = z - sigma / k_u at every node.
  const double plastic = z - sigma / soil.unloading_stiffness;
  EXPECT_NEAR(memory.at(0.0, 0.0).plastic_sinkage, plastic, 1e-6 * z);
  EXPECT_DOUBLE_EQ(body.step(terrain, &memory, at(-plastic + 1e-5), kStepS).normal_force, 0.0);
  // Set down again it carries the load at z: the hollow's bottom plus the
  // elastic part sigma / k_u (k_u ~ 2e8 Pa/m: micrometres).
  double lo = 0.0, hi = 0.5;
  for (int k = 0; k < 80; ++k) {
    const double mid = 0.5 * (lo + hi);
    BodyOnSoil probe = plate();
    GroundMemory copy(terrain);
    memory.forEachTouchedNode([&](double x, double y, const SoilMemory& m) { copy.setNode(x, y, m); });
    (probe.step(terrain, &copy, at(-mid), kStepS).normal_force < load ? lo : hi) = mid;
  }
  const double elastic = 0.5 * (lo + hi) - plastic;
  RecordProperty("plastic_mm", std::to_string(1e3 * plastic));
  RecordProperty("elastic_um", std::to_string(1e6 * elastic));
  EXPECT_NEAR(elastic, sigma / soil.unloading_stiffness, 0.01 * sigma / soil.unloading_stiffness);
}

TEST(BodySoilTest, HardGroundAndAPlateAboveTheSoilCarryNothing) {
  BodyOnSoil body = plate();
  const Terrain hard = soilSlab("toyoura_sand", false, false);
  EXPECT_EQ(body.step(hard, nullptr, at(-0.01), kStepS).nodes, 0);
  const Terrain soft = soilSlab("toyoura_sand", false);
  EXPECT_EQ(body.step(soft, nullptr, at(0.001), kStepS).nodes, 0);
  BodySoilMotion nan = at(-0.01);
  nan.velocity.x() = std::nan("");
  const BodySoilForces f = body.step(soft, nullptr, nan, kStepS);
  EXPECT_EQ(f.nodes, 0);
  EXPECT_TRUE(f.force.allFinite());
}

TEST(BodySoilTest, BadBodiesAreRefusedWithTheirReason) {
  const auto refused = [](auto make, const std::string& words) { testing::expectRefused(make, {words, "chassis"}); };
  refused([] { BodyOnSoil({}, 1.0, "chassis"); }, "at least one convex hull");
  refused([] { BodyOnSoil({ConvexPolyhedron::box({0, 0, 0}, {1, 1, 1})}, -2.0, "chassis"); }, "mass");
  refused([] { BodyOnSoil({ConvexPolyhedron::box({0, 0, 0}, {1, 1, 1})}, std::nan(""), "chassis"); }, "mass");
}

}  // namespace body_soil_test
}  // namespace wtc
