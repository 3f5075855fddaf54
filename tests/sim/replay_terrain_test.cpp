// What of a terrain the replay page draws (wtc::sim::replayTerrain, issue
// 35, row 4): a small terrain whole, a large one only around the path, and
// one too large even there as a height grid on its top surface, always
// within the budget of triangles.
#include "wtc/sim/replay_terrain.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "wtc/terrain/heightfield.hpp"
#include "wtc/terrain/terrain_primitives.hpp"

namespace wtc::sim {
namespace {

constexpr double kMmToleranceM = 0.5e-3 + 1e-9;  // positions are written rounded to mm
constexpr double kMmPerM = 1000.0;

// The path of a vehicle that drove 3 m along x near the origin (m).
Aabb shortPath() { return {{-1.5, -0.5, 0.0}, {1.5, 0.5, 0.5}}; }

// Every drawn vertex (m) lies in `box` padded by `pad` (m) horizontally.
void expectVerticesWithin(const ReplayTerrain& t, const Aabb& box, double pad) {
  for (std::size_t k = 0; k + 2 < t.positions.size(); k += 3) {
    const double x = static_cast<double>(t.positions[k]) / kMmPerM,
                 y = static_cast<double>(t.positions[k + 1]) / kMmPerM;
    ASSERT_GE(x, box.min.x() - pad - kMmToleranceM);
    ASSERT_LE(x, box.max.x() + pad + kMmToleranceM);
    ASSERT_GE(y, box.min.y() - pad - kMmToleranceM);
    ASSERT_LE(y, box.max.y() + pad + kMmToleranceM);
  }
}

// A 1500 x 1500-cell compact heightfield at 5 cm (75 m square, centred on
// the origin) whose surface is the plane z = 0.01 x + 0.02 y: the issue's
// 2.25 million cells, 31 million triangles if drawn whole.
Terrain largeTiltedField() {
  constexpr int kSamples = 1501;
  constexpr double kSpacingM = 0.05;
  Heightfield field;
  field.rows = field.cols = kSamples;
  field.spacing_x = field.spacing_y = kSpacingM;
  field.origin = Eigen::Vector3d(-37.5, -37.5, 0.0);
  field.heights.resize(static_cast<std::size_t>(kSamples) * kSamples);
  for (int r = 0; r < kSamples; ++r) {
    for (int c = 0; c < kSamples; ++c) {
      const Eigen::Vector3d p = field.origin + Eigen::Vector3d(c * kSpacingM, r * kSpacingM, 0.0);
      field.heights[static_cast<std::size_t>(r) * kSamples + c] = 0.01 * p.x() + 0.02 * p.y();
    }
  }
  TerrainBuilder builder;
  addCompactHeightfield(builder, std::move(field), builder.addMaterial({}));
  return std::move(builder).build();
}

TEST(ReplayTerrainTest, ASmallTerrainIsDrawnWholeFaceForFace) {
  TerrainBuilder builder;
  addLedge(builder, {}, builder.addMaterial({}));
  const Terrain ledge = std::move(builder).build();
  const ReplayTerrain t = replayTerrain(ledge, shortPath());
  EXPECT_EQ(t.kind, ReplayTerrain::Kind::kWhole);
  EXPECT_EQ(t.note(), "");
  // Two boxes: every vertex, and the five faces of each that do not look down, as two triangles each.
  EXPECT_EQ(t.positions.size(), 2u * 8u * 3u);
  EXPECT_EQ(t.triangles(), 2 * 5 * 2);
}

TEST(ReplayTerrainTest, ALargeTerrainIsDrawnOnlyAroundThePath) {
  // Case: 200 x 200 rocks 1 m apart: 400,000 triangles whole; about 22 x 22 of them near the path.
  TerrainBuilder builder;
  const MaterialId m = builder.addMaterial({});
  for (int i = -100; i < 100; ++i) {
    for (int j = -100; j < 100; ++j) {
      addBox(builder, {.size = {0.5, 0.5, 0.2}, .pose_WL = Eigen::Isometry3d(Eigen::Translation3d(i, j, 0.0))}, m);
    }
  }
  const Terrain rocks = std::move(builder).build();
  const ReplayTerrain t = replayTerrain(rocks, shortPath());
  EXPECT_EQ(t.kind, ReplayTerrain::Kind::kRegion);
  EXPECT_EQ(t.full_triangles, 200 * 200 * 10);
  EXPECT_LE(t.triangles(), kReplayTerrainMaxTriangles);
  EXPECT_EQ(t.note(), "terrain within 10 m of the path");
  // Every rock whose box meets the path padded by 10 m, x in [-11.5, 11.5] and y in [-10.5, 10.5], and no
  // other: the rocks at x = -11 ... 11 and y = -10 ... 10.
  EXPECT_EQ(t.triangles(), 23 * 21 * 10);
  expectVerticesWithin(t, shortPath(), kReplayTerrainMarginM + 0.25);
}

TEST(ReplayTerrainTest, AHugeCompactHeightfieldIsAHeightGridOnItsSurfaceWithinTheBudget) {
  const Terrain field = largeTiltedField();
  const ReplayTerrain t = replayTerrain(field, shortPath());
  EXPECT_EQ(t.kind, ReplayTerrain::Kind::kGrid);
  EXPECT_GT(t.full_triangles, kReplayTerrainMaxTriangles);
  EXPECT_LE(t.triangles(), kReplayTerrainMaxTriangles);
  EXPECT_GT(t.triangles(), kReplayTerrainMaxTriangles * 9 / 10);  // the budget used, not wasted
  EXPECT_LT(t.grid_spacing_m, 0.1);
  EXPECT_EQ(t.note().rfind("terrain within 10 m of the path, as a 0.0", 0), 0u) << t.note();
  // The region: the path padded by the margin, every vertex on the field's surface.
  EXPECT_NEAR(t.region.min.x(), shortPath().min.x() - kReplayTerrainMarginM, 1e-12);
  EXPECT_NEAR(t.region.max.y(), shortPath().max.y() + kReplayTerrainMarginM, 1e-12);
  expectVerticesWithin(t, shortPath(), kReplayTerrainMarginM);
  for (std::size_t k = 0; k + 2 < t.positions.size(); k += 3) {
    const double x = static_cast<double>(t.positions[k]) / kMmPerM,
                 y = static_cast<double>(t.positions[k + 1]) / kMmPerM;
    // x and y rounded by up to 0.5 mm each move the plane by 0.015 mm.
    ASSERT_NEAR(static_cast<double>(t.positions[k + 2]) / kMmPerM, 0.01 * x + 0.02 * y, kMmToleranceM + 2e-5);
  }
}

TEST(ReplayTerrainTest, AHoleLeavesItsCellsOutOfTheGrid) {
  // Case: a 400 x 400 compact field at 0.1 m with a 2 m square hole at the middle, drawn on a budget of 2000
  // triangles (a 0.7 m grid over the 23 m x 21 m region).
  constexpr int kSamples = 401;
  Heightfield field;
  field.rows = field.cols = kSamples;
  field.spacing_x = field.spacing_y = 0.1;
  field.origin = Eigen::Vector3d(-20.0, -20.0, 0.0);
  field.heights.assign(static_cast<std::size_t>(kSamples) * kSamples, 0.0);
  field.cell_holes.assign(field.cellCount(), 0);
  for (int r = 190; r < 210; ++r) {
    for (int c = 190; c < 210; ++c) field.cell_holes[static_cast<std::size_t>(r) * (kSamples - 1) + c] = 1;
  }
  TerrainBuilder builder;
  addCompactHeightfield(builder, std::move(field), builder.addMaterial({}));
  const Terrain holed = std::move(builder).build();
  const ReplayTerrain t = replayTerrain(holed, shortPath(), 2000);
  ASSERT_EQ(t.kind, ReplayTerrain::Kind::kGrid);
  EXPECT_LE(t.triangles(), 2000);
  EXPECT_GT(t.triangles(), 1800);  // all but the cells at the hole
  // No triangle has a corner strictly inside the hole (x, y in (-1, 1)).
  for (std::size_t k = 0; k < t.positions.size(); k += 3) {
    const double x = static_cast<double>(t.positions[k]) / kMmPerM,
                 y = static_cast<double>(t.positions[k + 1]) / kMmPerM;
    EXPECT_FALSE(std::abs(x) < 1.0 - 1e-3 && std::abs(y) < 1.0 - 1e-3) << x << ", " << y;
  }
}

TEST(ReplayTerrainTest, APathThatNeverCameNearTheTerrainDrawsNothing) {
  const Terrain field = largeTiltedField();
  const ReplayTerrain t = replayTerrain(field, {{500.0, 500.0, 0.0}, {501.0, 501.0, 0.0}});
  EXPECT_EQ(t.triangles(), 0);
  EXPECT_TRUE(t.positions.empty());
}

}  // namespace
}  // namespace wtc::sim
