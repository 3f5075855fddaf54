// A vehicle's body (not a wheel) against a ledge sampled into a compact
// heightfield, in every engine: the bodies meet the engine's own heightfield
// shape. ODE's dHeightfield meets a body with each triangle's plane: a body
// across the field's top edge got the steep face's normal, a wall on the
// edge, and a body whose sides lie on grid lines got sideways pushes from
// the walls between cells; their friction held the robot's rear carrier on
// the ledge's edge (docs/terrain.md, "The bodies on a field"). A body must
// feel only the field's surface (src/sim/terrain_normal_cone.hpp): ODE and
// MuJoCo hold their contacts to it; Bullet's GJK on its heightfield's
// triangles gives no walls.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <ostream>
#include <string>
#include <vector>

#include "sim_test_support.hpp"
#include "wtc/base/constants.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/sim_constants.hpp"
#include "wtc/terrain/terrain_primitives.hpp"

namespace wtc::testing {
namespace {

// The robot's rear carrier's section, 0.08 m (vehicles/six_wheel_robot.yaml).
constexpr double kLengthM = 0.43, kSideM = 0.08, kMassKg = 10.0;
// Grid lines at y = -0.5 + 0.02 k, two of them on the body's sides (y = +-0.04).
constexpr double kSpacingM = 0.02, kWidthM = 1.0;

Terrain sampledLedge(double height) {
  TerrainBuilder builder;
  const MaterialId m = builder.addMaterial(Material{});
  addLedge(builder,
           LedgeParams{.height = height,
                       .approach_length = 0.5,
                       .top_length = 1.0,
                       .width = kWidthM,
                       .thickness = 0.2,
                       .heightfield_spacing = kSpacingM,
                       .compact_heightfield = true},
           m);
  return std::move(builder).build();
}

// One body along x: a box of kSideM square section, or a cylinder of
// diameter kSideM.
vehicle::VehicleDescription onePlank(vehicle::Shape::Kind kind, double length) {
  vehicle::Body plank;
  plank.name = "plank";
  plank.mass = kMassKg;
  plank.shape.kind = kind;
  plank.shape.box_size = {length, kSideM, kSideM};
  plank.shape.radius = 0.5 * kSideM;
  plank.shape.length = length;
  plank.shape.cylinder_axis = 0;
  plank.inertia = vehicle::solidInertia(plank.shape, kMassKg);
  vehicle::VehicleDescription v;
  v.name = "plank";
  v.bodies = {plank};
  return v;
}

struct Case {
  std::string engine;
  vehicle::Shape::Kind shape;
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.engine << (c.shape == vehicle::Shape::Kind::kBox ? " box" : " cylinder");
}

std::vector<Case> everyEngineAndShape() {
  std::vector<Case> cases;
  for (const std::string& engine : everyEngineName(Variants::kLeftOut)) {
    for (const auto shape : {vehicle::Shape::Kind::kBox, vehicle::Shape::Kind::kCylinder})
      cases.push_back({engine, shape});
  }
  return cases;
}

class BodyFieldContactTest : public ::testing::TestWithParam<Case> {};

// Case: a plank leans at 40 degrees on the ledge's top edge (0.25 m), its
// lower end on the ground, and is pushed up along itself by 1.5 m g.
// Friction 0.6 at both ends cannot hold that push (the balance along and
// across the plank needs normal forces its weight cannot give: about 0.12
// m g of friction against 1.15 m g), so it slides up over the edge.
// Measured (docs/terrain.md, "The bodies on a field"): 28-46 mm in every
// engine. ODE gave the box the face's normal on the edge, a wall: 0.008 mm.
// Sideways, ODE's held contacts are exact (1e-21 m); MuJoCo's held ones
// drift 0.04 mm (box) and 0.35 mm (cylinder); Bullet's heightfield, not
// held, pushes the box 6.1 mm sideways along its triangles' diagonals.
TEST_P(BodyFieldContactTest, APlankLeaningOnTheEdgeSlidesUpWhenPushedAlongItself) {
  constexpr double kHeightM = 0.25, kPitchRad = 40.0 * std::numbers::pi / 180.0;
  constexpr double kPushG = 1.5, kSettleSeconds = 0.1, kPushSeconds = 0.1;
  constexpr double kMinSlideM = 0.01;
  // Each engine's bound over its measured drift; an engine not named here
  // has none measured yet (at() throws).
  const std::map<std::string, double> sideways_m{{"bullet", 1e-2}, {"ode", 1e-6}, {"mujoco", 1e-3}};
  const Terrain ledge = sampledLedge(kHeightM);
  const vehicle::VehicleDescription plank = onePlank(GetParam().shape, kLengthM);
  // The pose that puts the lower bottom edge on the ground (z = 0) and the
  // bottom face on the top edge (x = 0, z = kHeightM): with u = (c, 0, s)
  // along the plank and n = (-s, 0, c) its bottom face's normal,
  // centre_z = L/2 s + a/2 c and centre . n = kHeightM c + a/2 (a the side).
  const double s = std::sin(kPitchRad), c = std::cos(kPitchRad);
  const double z = 0.5 * kLengthM * s + 0.5 * kSideM * c;
  const double x = (z * c - kHeightM * c - 0.5 * kSideM) / s;
  const Eigen::Isometry3d placement =
      Eigen::Translation3d(x, 0.0, z) * Eigen::AngleAxisd(-kPitchRad, Eigen::Vector3d::UnitY());
  const sim::EngineSettings settings{.engine = GetParam().engine, .mode = ContactMode::kForce};
  const auto engine = sim::makeEngine(settings, ledge, plank, placement);
  const auto steps = [&](double seconds) { return static_cast<int>(std::round(seconds / settings.step_seconds)); };
  for (int k = 0; k < steps(kSettleSeconds); ++k) engine->step();
  const vehicle::BodyKinematics start = engine->body(0);
  for (int k = 0; k < steps(kPushSeconds); ++k) {
    const vehicle::BodyKinematics b = engine->body(0);
    const Eigen::Vector3d u = b.pose.linear() * Eigen::Vector3d::UnitX();
    engine->addForce(0, kPushG * kMassKg * kGravityMps2 * u, b.pose.translation());
    engine->step();
  }
  const vehicle::BodyKinematics end = engine->body(0);
  const Eigen::Vector3d moved = end.pose.translation() - start.pose.translation();
  EXPECT_GT(moved.dot(start.pose.linear() * Eigen::Vector3d::UnitX()), kMinSlideM);
  EXPECT_LT(std::abs(end.pose.translation().y()), sideways_m.at(GetParam().engine));
}

INSTANTIATE_TEST_SUITE_P(EveryEngine, BodyFieldContactTest, ::testing::ValuesIn(everyEngineAndShape()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return info.param.engine +
                                  (info.param.shape == vehicle::Shape::Kind::kBox ? "Box" : "Cylinder");
                         });

class BodyFieldFlatTest : public ::testing::TestWithParam<std::string> {};

// Case: a box lies on the ledge's top along x, its side faces on two grid
// lines, settles, and is pushed along x by 1.2 m g: it slides as Coulomb
// says, a = (F - mu m g) / m, straight on. The surface's normals leave a
// face's contacts as the engine gives them (up), so a body resting on the
// field's top keeps its friction exact. (Bullet's hulls carry a 1 mm margin:
// a box placed on the surface starts 1 mm deep and Bullet's position
// correction lifts it off at erp depth / h, 0.5 m/s; the settling lets it
// land.)
TEST_P(BodyFieldFlatTest, ABoxLyingAlongGridLinesSlidesAsCoulombSays) {
  constexpr double kHeightM = 0.3, kShortM = 0.06;  // 3 x 4 cells under it: ODE's direct solver stays fast
  constexpr double kPushG = 1.2, kSettleSeconds = 0.2, kPushSeconds = 0.1;
  // Of the expected acceleration: measured Bullet 0.14 %, ODE 0.00 %,
  // MuJoCo 2.5 % (its soft cone; 2.1 % on a box's face), sideways 0.8 %.
  constexpr double kAccelerationTolerance = 0.03;
  const Terrain ledge = sampledLedge(kHeightM);
  const vehicle::VehicleDescription box = onePlank(vehicle::Shape::Kind::kBox, kShortM);
  const sim::EngineSettings settings{.engine = GetParam(), .mode = ContactMode::kForce};
  const Eigen::Isometry3d placement(Eigen::Translation3d(0.3, 0.0, kHeightM + 0.5 * kSideM));
  const auto engine = sim::makeEngine(settings, ledge, box, placement);
  const auto steps = [&](double seconds) { return static_cast<int>(std::round(seconds / settings.step_seconds)); };
  for (int k = 0; k < steps(kSettleSeconds); ++k) engine->step();
  const vehicle::BodyKinematics start = engine->body(0);
  for (int k = 0; k < steps(kPushSeconds); ++k) {
    engine->addForce(0, {kPushG * kMassKg * kGravityMps2, 0.0, 0.0}, engine->body(0).pose.translation());
    engine->step();
  }
  const Eigen::Vector3d a = (engine->body(0).linear_velocity - start.linear_velocity) / kPushSeconds;
  const double expected = (kPushG - sim::kBodyGroundFriction) * kGravityMps2;
  EXPECT_NEAR(a.x(), expected, kAccelerationTolerance * expected);
  EXPECT_NEAR(a.y(), 0.0, kAccelerationTolerance * expected);
}

INSTANTIATE_TEST_SUITE_P(EveryEngine, BodyFieldFlatTest, ::testing::ValuesIn(everyEngineName(Variants::kLeftOut)));

}  // namespace
}  // namespace wtc::testing
