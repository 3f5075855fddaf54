#include "wtc/terrain/terrain_primitives.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "wtc/base/error.hpp"
#include "wtc/geometry/point_query.hpp"
#include "wtc/terrain/terrain.hpp"

namespace wtc {
namespace terrain_primitives_test {

using ::testing::AllOf;
using ::testing::HasSubstr;

// Builders compute exact binary fractions here; 1e-12 m absorbs the rounding
// of the rotated cases.
constexpr double kTolerance = 1e-12;

// A builder with the default material, and its id.
struct Fixture {
  TerrainBuilder builder;
  MaterialId material = builder.addMaterial(Material{});
};

Aabb unionOf(const Terrain& terrain, PieceRange range) {
  Aabb box = terrain.piece(range.first).bounds();
  for (PieceId id = range.first; id < range.end(); ++id) {
    box.min = box.min.cwiseMin(terrain.piece(id).bounds().min);
    box.max = box.max.cwiseMax(terrain.piece(id).bounds().max);
  }
  return box;
}

void expectBox(const Aabb& box, const Eigen::Vector3d& min, const Eigen::Vector3d& max) {
  EXPECT_TRUE((box.min - min).norm() < kTolerance) << formatVector(box.min) << " vs " << formatVector(min);
  EXPECT_TRUE((box.max - max).norm() < kTolerance) << formatVector(box.max) << " vs " << formatVector(max);
}

double distance(const Terrain& terrain, PieceId id, const Eigen::Vector3d& p) {
  return queryPoint(terrain.piece(id), p).signed_distance;
}

TEST(TerrainPrimitivesTest, TiledSlabCoversItsRectangleWithSharedTileFaces) {
  Fixture f;
  SlabParams slab;
  slab.size_x = 6.0;
  slab.size_y = 2.0;
  slab.thickness = 0.3;
  slab.tiles_x = 3;
  slab.tiles_y = 2;
  const PieceRange range = addSlab(f.builder, slab, f.material);
  EXPECT_EQ(range.first, 0);
  EXPECT_EQ(range.count, 6);
  const Terrain terrain = std::move(f.builder).build();
  expectBox(unionOf(terrain, range), {-3.0, -1.0, -0.3}, {3.0, 1.0, 0.0});
  // Case: neighbours along x share their face exactly (the seam test needs
  // no gap and no overlap).
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i + 1 < 3; ++i) {
      EXPECT_EQ(terrain.piece(j * 3 + i).bounds().max.x(), terrain.piece(j * 3 + i + 1).bounds().min.x());
    }
  }
  for (PieceId id = 0; id < 6; ++id) {
    EXPECT_EQ(terrain.piece(id).vertexCount(), 8);
    EXPECT_EQ(terrain.piece(id).faceCount(), 6);
    EXPECT_EQ(terrain.piece(id).bounds().max.z(), 0.0);
  }
}

TEST(TerrainPrimitivesTest, RotatedSlabIsAnInclinePlane) {
  Fixture f;
  SlabParams slab;
  const double angle = 10.0 * std::numbers::pi / 180.0;
  slab.pose_WL = Eigen::AngleAxisd(-angle, Eigen::Vector3d::UnitY());  // rises toward +x
  addSlab(f.builder, slab, f.material);
  const Terrain terrain = std::move(f.builder).build();
  const Eigen::Vector3d normal = slab.pose_WL.linear() * Eigen::Vector3d::UnitZ();
  EXPECT_GT(normal.x(), -1.0);
  EXPECT_NEAR(normal.x(), -std::sin(angle), kTolerance);
  // Case: a point 0.2 m above the plane along its normal, off-centre.
  const Eigen::Vector3d on_plane = slab.pose_WL * Eigen::Vector3d(2.0, 1.0, 0.0);
  EXPECT_NEAR(distance(terrain, 0, on_plane + 0.2 * normal), 0.2, kTolerance);
}

TEST(TerrainPrimitivesTest, InclineRisesAtItsAngleAndEndsInAFlatTop) {
  Fixture f;
  InclineParams incline;
  incline.angle = 12.0 * std::numbers::pi / 180.0;
  incline.length = 3.0;
  incline.width = 2.0;
  incline.top_length = 1.0;
  const PieceRange range = addIncline(f.builder, incline, f.material);
  ASSERT_EQ(range.count, 2);
  const Terrain terrain = std::move(f.builder).build();
  const double rise = 3.0 * std::tan(incline.angle);
  expectBox(unionOf(terrain, range), {0.0, -1.0, -0.5}, {4.0, 1.0, rise});
  // Case: 5 cm above the ramp's middle, the distance is 5 cm x cos(angle).
  EXPECT_NEAR(distance(terrain, range.first, {1.5, 0.0, 0.5 * rise + 0.05}), 0.05 * std::cos(incline.angle),
              kTolerance);
  // Case: just below the ramp surface is inside the wedge.
  EXPECT_LT(distance(terrain, range.first, {1.5, 0.0, 0.5 * rise - 0.01}), 0.0);
  EXPECT_NEAR(distance(terrain, range.first + 1, {3.5, 0.0, rise + 0.1}), 0.1, kTolerance);
}

TEST(TerrainPrimitivesTest, SpecLedgeHasAVerticalFaceAtXZeroAndA065MetreTop) {
  Fixture f;
  const LedgeParams ledge;  // the spec's: 0.65 m, 4 m approach, 4 m top
  const PieceRange range = addLedge(f.builder, ledge, f.material);
  ASSERT_EQ(range.count, 2);
  const Terrain terrain = std::move(f.builder).build();
  expectBox(terrain.piece(0).bounds(), {-4.0, -1.5, -0.5}, {0.0, 1.5, 0.0});
  expectBox(terrain.piece(1).bounds(), {0.0, -1.5, -0.5}, {4.0, 1.5, 0.65});
  // Case: a wheel centre 0.19 m in front of the face and 0.3 m up touches
  // the face at distance 0.19; above the top edge it sees the top.
  EXPECT_NEAR(distance(terrain, 1, {-0.19, 0.0, 0.3}), 0.19, kTolerance);
  EXPECT_NEAR(distance(terrain, 1, {0.5, 0.0, 0.65 + 0.19}), 0.19, kTolerance);
  // Case: the top edge is a genuine corner: from (-0.1, 0, 0.75) the
  // closest point is the edge (0, y, 0.65).
  EXPECT_NEAR(distance(terrain, 1, {-0.1, 0.0, 0.75}), std::hypot(0.1, 0.1), kTolerance);
}

TEST(TerrainPrimitivesTest, LedgeOfAnyHeightWithATiledApproach) {
  for (double height : {0.0, 0.1, 0.65, 1.2}) {
    Fixture f;
    LedgeParams ledge;
    ledge.height = height;
    ledge.approach_tiles = 4;
    const PieceRange range = addLedge(f.builder, ledge, f.material);
    ASSERT_EQ(range.count, 5) << "height " << height;
    const Terrain terrain = std::move(f.builder).build();
    EXPECT_EQ(terrain.piece(4).bounds().max.z(), height);
    for (PieceId id = 0; id < 4; ++id) {
      EXPECT_EQ(terrain.piece(id).bounds().max.x(), terrain.piece(id + 1).bounds().min.x()) << "tile " << id;
    }
  }
}

TEST(TerrainPrimitivesTest, ALedgeAsAHeightfieldIsTheSameGroundAwayFromItsFace) {
  Fixture f;
  LedgeParams ledge;
  ledge.height = 0.6;
  ledge.width = 1.0;
  ledge.heightfield_spacing = 0.05;
  ledge.pose_WL.translation() = Eigen::Vector3d(1.0, 2.0, 0.0);
  const PieceRange range = addLedge(f.builder, ledge, f.material);
  // (4 + 4) / 0.05 = 160 cells along x, 20 along y, two prisms each.
  ASSERT_EQ(range.count, 2 * 160 * 20);
  const Terrain terrain = std::move(f.builder).build();
  const Aabb all = unionOf(terrain, range);
  expectBox(all, {-3.0, 1.5, -0.5}, {5.0, 2.5, 0.6});
  // Nearest ground of a point: the smallest distance over every piece.
  const auto ground = [&](const Eigen::Vector3d& p) {
    double d = std::numeric_limits<double>::infinity();
    for (PieceId id = range.first; id < range.end(); ++id) d = std::min(d, distance(terrain, id, p));
    return d;
  };
  EXPECT_NEAR(ground({-1.0, 2.1, 0.19}), 0.19, kTolerance);       // above the approach
  EXPECT_NEAR(ground({3.0, 1.9, 0.6 + 0.19}), 0.19, kTolerance);  // above the top
  // The face is a slope across the cell in front of x = 0 (here x = 1):
  // the top edge is where the box's is, its foot one cell earlier.
  EXPECT_NEAR(ground({1.0 - 0.1, 2.0, 0.75}), std::hypot(0.1, 0.15), kTolerance);
  const double slope = std::atan2(0.6, 0.05);
  const Eigen::Vector3d foot(1.0 - 0.05, 2.0, 0.0), along(std::cos(slope), 0.0, std::sin(slope)),
      out(-std::sin(slope), 0.0, std::cos(slope));
  EXPECT_NEAR(ground(foot + 0.3 * along + 0.01 * out), 0.01, 1e-12);

  LedgeParams turned = ledge;
  turned.pose_WL.linear() = Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_THAT(
      [&] { addLedge(f.builder, turned, f.material); },
      ::testing::ThrowsMessage<InvalidInputError>(HasSubstr("heightfield_spacing needs a pose without rotation")));
  LedgeParams negative = ledge;
  negative.heightfield_spacing = -0.01;
  EXPECT_THAT([&] { addLedge(f.builder, negative, f.material); },
              ::testing::ThrowsMessage<InvalidInputError>(HasSubstr("heightfield_spacing")));
}

TEST(TerrainPrimitivesTest, StairsClimbOneRisePerRun) {
  Fixture f;
  StairsParams stairs;
  stairs.steps = 5;
  stairs.rise = 0.17;
  stairs.run = 0.29;
  stairs.top_length = 1.0;
  const PieceRange range = addStairs(f.builder, stairs, f.material);
  ASSERT_EQ(range.count, 5);
  const Terrain terrain = std::move(f.builder).build();
  for (int i = 0; i < 5; ++i) {
    const Aabb& box = terrain.piece(range.first + i).bounds();
    EXPECT_NEAR(box.max.z(), (i + 1) * 0.17, kTolerance) << "step " << i;
    EXPECT_NEAR(box.min.x(), i * 0.29, kTolerance) << "step " << i;
  }
  EXPECT_NEAR(terrain.piece(range.first + 4).bounds().max.x(), 5 * 0.29 + 1.0, kTolerance);
}

TEST(TerrainPrimitivesTest, RotatedBoxHasTheRotatedBounds) {
  Fixture f;
  BoxParams box;
  box.size = {1.0, 1.0, 0.2};
  box.pose_WL = Eigen::Translation3d(5.0, 0.0, 0.1) * Eigen::AngleAxisd(std::numbers::pi / 4, Eigen::Vector3d::UnitZ());
  const PieceRange range = addBox(f.builder, box, f.material);
  ASSERT_EQ(range.count, 1);
  const Terrain terrain = std::move(f.builder).build();
  const double h = std::sqrt(0.5);
  expectBox(terrain.piece(0).bounds(), {5.0 - h, -h, 0.0}, {5.0 + h, h, 0.2});
}

TEST(TerrainPrimitivesTest, RangesFollowEachOtherInInsertionOrder) {
  Fixture f;
  const PieceRange a = addLedge(f.builder, LedgeParams{}, f.material);
  const PieceRange b = addStairs(f.builder, StairsParams{}, f.material);
  const PieceRange c = addBox(f.builder, BoxParams{}, f.material);
  EXPECT_EQ(a.first, 0);
  EXPECT_EQ(b.first, a.end());
  EXPECT_EQ(c.first, b.end());
  EXPECT_EQ(f.builder.pieceCount(), static_cast<std::size_t>(c.end()));
}

// Each case: a builder call with one bad parameter, and what the message
// must contain.
struct BadParameter {
  std::string expected;
  std::function<void(TerrainBuilder&, MaterialId)> add;
};

TEST(TerrainPrimitivesTest, BadParametersAreNamedInTheMessage) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<BadParameter> cases = {
      {"wtc::addSlab: thickness = -1", [](auto& b, auto m) { addSlab(b, {.thickness = -1.0}, m); }},
      {"wtc::addSlab: size_x = nan", [nan](auto& b, auto m) { addSlab(b, {.size_x = nan}, m); }},
      {"wtc::addSlab: tiles_y = 0", [](auto& b, auto m) { addSlab(b, {.tiles_y = 0}, m); }},
      {"wtc::addIncline: angle = 1.6", [](auto& b, auto m) { addIncline(b, {.angle = 1.6}, m); }},
      {"wtc::addIncline: top_length = -0.5", [](auto& b, auto m) { addIncline(b, {.top_length = -0.5}, m); }},
      {"wtc::addLedge: height = -0.65", [](auto& b, auto m) { addLedge(b, {.height = -0.65}, m); }},
      {"wtc::addLedge: width = nan", [nan](auto& b, auto m) { addLedge(b, {.width = nan}, m); }},
      {"wtc::addLedge: approach_length = 0", [](auto& b, auto m) { addLedge(b, {.approach_length = 0.0}, m); }},
      {"wtc::addStairs: steps = 0", [](auto& b, auto m) { addStairs(b, {.steps = 0}, m); }},
      {"wtc::addStairs: rise = inf",
       [](auto& b, auto m) { addStairs(b, {.rise = std::numeric_limits<double>::infinity()}, m); }},
      {"wtc::addBox: size.y = -2",
       [](auto& b, auto m) {
         addBox(b, {.size = {1.0, -2.0, 1.0}}, m);
       }},
      {"wtc::addBox: pose_WL must be a finite rigid transform",
       [](auto& b, auto m) {
         BoxParams box;
         box.pose_WL.linear() *= 2.0;  // a scale is not a placement
         addBox(b, box, m);
       }},
      {"wtc::addSlab: pose_WL must be a finite rigid transform",
       [](auto& b, auto m) {
         SlabParams slab;
         slab.pose_WL.linear() = Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal();  // a mirror
         addSlab(b, slab, m);
       }},
      // Absurd counts are refused before anything is allocated: 10^10 tiles
      // pass PieceId's range; 2e9 steps need more memory than any machine here.
      {"wtc::addSlab (tiles_x x tiles_y): 10000000000 pieces would pass the largest terrain",
       [](auto& b, auto m) { addSlab(b, {.tiles_x = 100000, .tiles_y = 100000}, m); }},
      {"wtc::addStairs (steps): 2000000000 pieces need more than",
       [](auto& b, auto m) { addStairs(b, {.steps = 2000000000}, m); }},
  };
  for (const auto& c : cases) {
    Fixture f;
    try {
      c.add(f.builder, f.material);
      ADD_FAILURE() << "no error, expected: " << c.expected;
    } catch (const InvalidInputError& e) {
      EXPECT_THAT(e.what(), HasSubstr(c.expected));
    }
    EXPECT_EQ(f.builder.pieceCount(), 0u) << c.expected;
  }
}

TEST(TerrainPrimitivesTest, UnknownMaterialIsRejectedBeforeAnyPieceIsAdded) {
  Fixture f;
  EXPECT_THROW(addLedge(f.builder, LedgeParams{}, f.material + 1), InvalidInputError);
  EXPECT_EQ(f.builder.pieceCount(), 0u);
}

}  // namespace terrain_primitives_test
}  // namespace wtc
