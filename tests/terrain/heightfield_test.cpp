#include "wtc/terrain/heightfield.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <optional>
#include <random>

#include "random_heightfield.hpp"
#include "wtc/base/error.hpp"
#include "wtc/geometry/point_query.hpp"
#include "wtc/terrain/terrain.hpp"
#include "wtc/terrain/triangle_mesh.hpp"

namespace wtc {
namespace {

using ::testing::HasSubstr;

// Distances here are of order 1e-3 m on pieces of a few metres; the query is
// exact to ~1e-15 relative, so 1e-12 m is loose and still meaningful.
constexpr double kTolerance = 1e-12;

Heightfield randomField(int rows, int cols, double amplitude, std::uint32_t seed) {
  return testing::randomHeightfield(rows, cols, amplitude, seed);
}

std::string messageOf(const Heightfield& f) {
  try {
    validate(f);
  } catch (const InvalidInputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(HeightfieldTest, EachCellBecomesTwoPrismsInRowMajorOrder) {
  const Heightfield f = randomField(4, 5, 0.1, 1);
  TerrainBuilder builder;
  const MaterialId m = builder.addMaterial(Material{});
  builder.addPiece(ConvexPolyhedron::box({0, 0, -1}, {1, 1, 0}), m);  // ids need not start at 0
  const PieceRange range = addHeightfield(builder, f, m);
  EXPECT_EQ(range.first, 1);
  EXPECT_EQ(range.count, 24);
  EXPECT_EQ(f.pieceCount(), 24u);
  const Terrain terrain = std::move(builder).build();
  for (int r = 0; r + 1 < f.rows; ++r) {
    for (int c = 0; c + 1 < f.cols; ++c) {
      for (int k = 0; k < 2; ++k) {
        const ConvexPolyhedron& prism = terrain.piece(*cellPiece(range, f, r, c, k));
        EXPECT_EQ(prism.vertexCount(), 6);
        EXPECT_EQ(prism.faceCount(), 5);
        // Case: the prism covers its cell in x and y and reaches the base.
        EXPECT_NEAR(prism.bounds().min.x(), f.origin.x() + c * f.spacing_x, kTolerance);
        EXPECT_NEAR(prism.bounds().max.x(), f.origin.x() + (c + 1) * f.spacing_x, kTolerance);
        EXPECT_NEAR(prism.bounds().min.y(), f.origin.y() + r * f.spacing_y, kTolerance);
        EXPECT_NEAR(prism.bounds().max.y(), f.origin.y() + (r + 1) * f.spacing_y, kTolerance);
        EXPECT_EQ(prism.bounds().min.z(), f.baseZ());
      }
      // Case: triangle 0 holds p01 (below the diagonal), triangle 1 holds p10.
      const Eigen::Vector3d p01 = f.sample(r, c + 1);
      const Eigen::Vector3d p10 = f.sample(r + 1, c);
      EXPECT_NEAR(queryPoint(terrain.piece(*cellPiece(range, f, r, c, 0)), p01).signed_distance, 0.0, kTolerance);
      EXPECT_GT(queryPoint(terrain.piece(*cellPiece(range, f, r, c, 0)), p10).signed_distance, 0.0);
      EXPECT_NEAR(queryPoint(terrain.piece(*cellPiece(range, f, r, c, 1)), p10).signed_distance, 0.0, kTolerance);
    }
  }
}

TEST(HeightfieldTest, PrismFacesPointOutwardForAnyHeights) {
  // Case: steep random relief (slopes up to ~4:1) over 3 seeds. fromMesh
  // validates every prism (all vertices below every face plane, outward
  // normals); here the surface itself is checked from both sides.
  const double offset = 1e-3;  // m above / below the surface
  for (std::uint32_t seed = 1; seed <= 3; ++seed) {
    const Heightfield f = randomField(9, 7, 1.5, seed);
    TerrainBuilder builder;
    const PieceRange range = addHeightfield(builder, f, builder.addMaterial(Material{}));
    const Terrain terrain = std::move(builder).build();
    for (int r = 0; r + 1 < f.rows; ++r) {
      for (int c = 0; c + 1 < f.cols; ++c) {
        for (int k = 0; k < 2; ++k) {
          // The centroid of triangle k in cell coordinates (s along x, t along y).
          const double s = k == 0 ? 2.0 / 3.0 : 1.0 / 3.0;
          const double t = k == 0 ? 1.0 / 3.0 : 2.0 / 3.0;
          const double x = f.origin.x() + (c + s) * f.spacing_x;
          const double y = f.origin.y() + (r + t) * f.spacing_y;
          const double z = surfaceHeight(f, x, y).value();
          const ConvexPolyhedron& prism = terrain.piece(*cellPiece(range, f, r, c, k));
          const Eigen::Vector3d normal = prism.faceNormal(0);  // the top triangle
          EXPECT_GT(normal.z(), 0.0);
          const PointQuery above = queryPoint(prism, {x, y, z + offset});
          const PointQuery below = queryPoint(prism, {x, y, z - offset});
          // Vertically offset by h from a plane with normal n: distance h n_z.
          EXPECT_NEAR(above.signed_distance, offset * normal.z(), kTolerance) << "cell " << r << "," << c;
          EXPECT_NEAR(below.signed_distance, -offset * normal.z(), kTolerance) << "cell " << r << "," << c;
          EXPECT_EQ(below.status, QueryStatus::kInside);
        }
      }
    }
  }
}

TEST(HeightfieldTest, SurfaceHeightInterpolatesTheSamePlanes) {
  const Heightfield f = randomField(5, 6, 0.3, 7);
  for (int r = 0; r < f.rows; ++r) {
    for (int c = 0; c < f.cols; ++c) {
      const Eigen::Vector3d p = f.sample(r, c);
      EXPECT_NEAR(surfaceHeight(f, p.x(), p.y()).value(), p.z(), kTolerance);
    }
  }
  EXPECT_FALSE(surfaceHeight(f, f.origin.x() - 0.01, f.origin.y()).has_value());
  EXPECT_FALSE(surfaceHeight(f, f.origin.x(), f.origin.y() + 5 * f.spacing_y + 0.01).has_value());
}

TEST(HeightfieldTest, BaseIsBaseDepthBelowTheLowestHeight) {
  Heightfield f;
  f.rows = 2;
  f.cols = 2;
  f.heights = {0.3, -0.2, 0.1, 0.0};
  f.origin = {0.0, 0.0, 5.0};
  f.base_depth = 0.5;
  EXPECT_DOUBLE_EQ(f.baseZ(), 5.0 - 0.2 - 0.5);
}

TEST(HeightfieldTest, MalformedGridsAreNamedInTheMessage) {
  Heightfield good = randomField(3, 4, 0.1, 3);
  EXPECT_EQ(messageOf(good), "(no error)");
  // Case: a non-finite height is named by row and column.
  Heightfield f = good;
  f.heights[2 * 4 + 3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(messageOf(f), HasSubstr("height at (row 2, col 3) = nan is not finite"));
  f = good;
  f.heights.pop_back();
  EXPECT_THAT(messageOf(f), HasSubstr("heights has 11 values, but rows x cols = 3 x 4 = 12"));
  f = good;
  f.rows = 1;
  EXPECT_THAT(messageOf(f), HasSubstr("rows = 1 must be >= 2"));
  f = good;
  f.spacing_y = -0.5;
  EXPECT_THAT(messageOf(f), HasSubstr("spacing_y = -0.5 must be finite and > 0 (m)"));
  f = good;
  f.base_depth = 0.0;
  EXPECT_THAT(messageOf(f), HasSubstr("base_depth = 0 must be finite and > 0 (m)"));
  f = good;
  f.origin.x() = std::numeric_limits<double>::infinity();
  EXPECT_THAT(messageOf(f), HasSubstr("origin = (inf, 2, 10) is not finite"));
  // Case: addHeightfield validates before adding anything.
  TerrainBuilder builder;
  f = good;
  f.heights[0] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(addHeightfield(builder, f, builder.addMaterial(Material{})), InvalidInputError);
  EXPECT_EQ(builder.pieceCount(), 0u);
}

// Case: per-cell materials: each cell's two pieces take its entry, stored
// or compact alike; a wrong count or an unregistered id is named (the
// cell by row and column) before anything is added.
TEST(HeightfieldTest, EachCellTakesItsOwnMaterial) {
  Heightfield f = randomField(4, 5, 0.1, 2);
  for (const bool compact : {false, true}) {
    TerrainBuilder builder;
    const MaterialId asphalt = builder.addMaterial(Material{});
    const MaterialId gravel = builder.addMaterial(Material{.name = "gravel", .mu_max = 0.6});
    f.cell_materials.assign(3 * 4, asphalt);
    f.cell_materials[1 * 4 + 2] = gravel;  // cell (1, 2)
    const PieceRange range = compact ? addCompactHeightfield(builder, f, asphalt) : addHeightfield(builder, f, asphalt);
    const Terrain terrain = std::move(builder).build();
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 4; ++c) {
        for (int k = 0; k < 2; ++k) {
          EXPECT_EQ(terrain.materialId(*cellPiece(range, f, r, c, k)), r == 1 && c == 2 ? gravel : asphalt)
              << (compact ? "compact" : "prisms") << " cell (" << r << ", " << c << ")";
        }
      }
    }
  }
  Heightfield wrong = f;
  wrong.cell_materials.pop_back();
  EXPECT_THAT(messageOf(wrong),
              HasSubstr("cell_materials has 11 ids, but the grid has (rows - 1) x (cols - 1) = 12 cells"));
  wrong = f;
  wrong.cell_materials.assign(3 * 4, 0);
  wrong.cell_materials[2 * 4 + 1] = 7;
  for (const bool compact : {false, true}) {
    TerrainBuilder builder;
    const MaterialId m = builder.addMaterial(Material{});
    const auto add = [&] { compact ? addCompactHeightfield(builder, wrong, m) : addHeightfield(builder, wrong, m); };
    EXPECT_THAT(add, ::testing::ThrowsMessage<InvalidInputError>(
                         HasSubstr("cell (row 2, col 1) has material id 7, which is not registered (1 materials)")));
    EXPECT_EQ(builder.pieceCount(), 0u);
  }
}

// Case: holes. A hole cell has no pieces, no surface and no triangles; the
// other cells keep their prisms, numbered on without gaps, stored or
// compact alike. A hole mask of the wrong size, or one without ground, is
// refused.
TEST(HeightfieldTest, AHoleCellHasNoGround) {
  const Heightfield whole = randomField(4, 5, 0.1, 3);
  Heightfield f = whole;
  f.cell_holes.assign(3 * 4, 0);
  f.cell_holes[0 * 4 + 1] = f.cell_holes[1 * 4 + 2] = 1;  // cells (0, 1) and (1, 2)
  EXPECT_EQ(f.pieceCount(), 2u * 10);
  EXPECT_TRUE(f.hasHoles());
  EXPECT_FALSE(whole.hasHoles());
  for (const bool compact : {false, true}) {
    SCOPED_TRACE(compact ? "compact" : "prisms");
    TerrainBuilder builder;
    const MaterialId m = builder.addMaterial(Material{});
    const PieceRange all = addHeightfield(builder, whole, m);
    const PieceRange range = compact ? addCompactHeightfield(builder, f, m) : addHeightfield(builder, f, m);
    const Terrain terrain = std::move(builder).build();
    ASSERT_EQ(range.count, 20);
    PieceId next = range.first;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 4; ++c) {
        for (int k = 0; k < 2; ++k) {
          const std::optional<PieceId> id = cellPiece(range, f, r, c, k);
          ASSERT_EQ(id.has_value(), !f.isHole(r, c)) << "cell (" << r << ", " << c << ")";
          if (!id) continue;
          EXPECT_EQ(*id, next++);
          // The same prism as the field without holes has on that cell.
          std::optional<ConvexPolyhedron> scratch;
          const ConvexPolyhedron& p = terrain.piece(*id, scratch);
          const ConvexPolyhedron& q = terrain.piece(*cellPiece(all, whole, r, c, k));
          for (int v = 0; v < p.vertexCount(); ++v) EXPECT_EQ(p.vertex(v), q.vertex(v));
        }
      }
    }
  }
  // The surface: none over a hole, the same elsewhere; the mesh's triangle
  // k on piece k.
  const Eigen::Vector3d in_hole = f.origin + Eigen::Vector3d(1.5 * f.spacing_x, 0.4 * f.spacing_y, 0.0);
  EXPECT_FALSE(surfaceHeight(f, in_hole.x(), in_hole.y()).has_value());
  EXPECT_FALSE(pieceUnder({0, 20}, f, in_hole.x(), in_hole.y()).has_value());
  const Eigen::Vector3d beside = in_hole + Eigen::Vector3d(f.spacing_x, 0.0, 0.0);
  EXPECT_EQ(surfaceHeight(f, beside.x(), beside.y()), surfaceHeight(whole, beside.x(), beside.y()));
  EXPECT_EQ(pieceUnder({0, 20}, f, beside.x(), beside.y()), PieceId{2});  // cell (0, 2) follows one hole
  const TriangleMesh mesh = surfaceMesh(f);
  EXPECT_EQ(mesh.vertices.size(), whole.heights.size());
  ASSERT_EQ(mesh.triangles.size(), 20u);
  const TriangleMesh full = surfaceMesh(whole);
  EXPECT_EQ(mesh.triangles[2], full.triangles[4]);    // cell (0, 2)
  EXPECT_EQ(mesh.triangles[19], full.triangles[23]);  // cell (2, 3)
  // Refused: a mask of the wrong size, and holes everywhere.
  Heightfield wrong = f;
  wrong.cell_holes.pop_back();
  EXPECT_THAT(messageOf(wrong),
              HasSubstr("cell_holes has 11 entries, but the grid has (rows - 1) x (cols - 1) = 12 cells"));
  wrong.cell_holes.assign(12, 1);
  EXPECT_THAT(messageOf(wrong), HasSubstr("every one of the 12 cells is a hole; the field has no ground"));
  TerrainBuilder builder;
  EXPECT_THROW(addCompactHeightfield(builder, wrong, builder.addMaterial(Material{})), InvalidInputError);
  EXPECT_EQ(builder.pieceCount(), 0u);
}

// Case: the terrain knows which stored pieces are a heightfield's prisms
// (an engine holds a body's contact with them to the surface, as on a
// compact field): addHeightfield's, between a box, a mesh's prisms and a
// compact field's pieces, none of which are; a copy knows it too.
TEST(HeightfieldTest, TheTerrainKnowsAHeightfieldsStoredPrisms) {
  TerrainBuilder builder;
  const MaterialId m = builder.addMaterial(Material{});
  const PieceId box = builder.addPiece(ConvexPolyhedron::box({0, 0, -1}, {1, 1, 0}), m);
  const PieceRange stored = addHeightfield(builder, randomField(4, 5, 0.1, 3), m);
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}};
  const PieceRange extruded = addTriangleMesh(builder, mesh, m).pieces;
  const PieceRange compact = addCompactHeightfield(builder, randomField(3, 3, 0.1, 4), m);
  const PieceRange second = addHeightfield(builder, randomField(3, 4, 0.1, 5), m);
  const Terrain terrain = std::move(builder).build();
  const Terrain copy(terrain);
  for (const Terrain* t : {&terrain, &copy}) {
    EXPECT_FALSE(t->isFieldPrism(box));
    for (PieceId id = stored.first; id < stored.end(); ++id) EXPECT_TRUE(t->isFieldPrism(id)) << id;
    for (PieceId id = second.first; id < second.end(); ++id) EXPECT_TRUE(t->isFieldPrism(id)) << id;
    for (PieceId id = extruded.first; id < extruded.end(); ++id) EXPECT_FALSE(t->isFieldPrism(id)) << id;
    for (PieceId id = compact.first; id < compact.end(); ++id) EXPECT_FALSE(t->isFieldPrism(id)) << id;
    EXPECT_FALSE(t->isFieldPrism(-1));
    EXPECT_FALSE(t->isFieldPrism(static_cast<PieceId>(t->pieceCount())));
  }
}

TEST(HeightfieldTest, TriangularPrismRejectsABaseAboveTheTriangle) {
  EXPECT_NO_THROW(makeTriangularPrism({0, 0, 1}, {1, 0, 1.2}, {0, 1, 0.9}, 0.0));
  EXPECT_THROW(makeTriangularPrism({0, 0, 1}, {1, 0, 1.2}, {0, 1, 0.9}, 2.0), InvalidInputError);
}

// The build-time figure of the README (10^6 pieces in a few seconds):
//   wtc_terrain_tests --gtest_also_run_disabled_tests --gtest_filter='*MillionPieces*'
// Needs about 0.6 GB. The benchmark (bench/) times it properly.
TEST(HeightfieldTest, DISABLED_BuildsAMillionPiecesInAFewSeconds) {
  const int n = 708;  // 707 x 707 cells x 2 = 999,698 prisms
  Heightfield f = randomField(n, n, 0.05, 11);
  const auto start = std::chrono::steady_clock::now();
  TerrainBuilder builder;
  const PieceRange range = addHeightfield(builder, f, builder.addMaterial(Material{}));
  const auto pieces_done = std::chrono::steady_clock::now();
  const Terrain terrain = std::move(builder).build();
  const auto index_done = std::chrono::steady_clock::now();
  const double pieces_s = std::chrono::duration<double>(pieces_done - start).count();
  const double index_s = std::chrono::duration<double>(index_done - pieces_done).count();
  std::cout << range.count << " prisms: addHeightfield " << pieces_s << " s, build (index) " << index_s << " s, pieces "
            << terrain.pieceMemoryBytes() / double(range.count) << " B/piece, index "
            << terrain.indexMemoryBytes() / double(range.count) << " B/piece\n";
  EXPECT_EQ(terrain.pieceCount(), 999698u);
  EXPECT_LT(pieces_s + index_s, 10.0);
}

}  // namespace
}  // namespace wtc
