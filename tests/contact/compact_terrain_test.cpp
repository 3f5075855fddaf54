// A terrain holding compact heightfields (addCompactHeightfield) against
// the same terrain with the fields stored as prisms (addHeightfield): the
// same ids, materials and boxes, the same candidates for any box, and a
// wheel driven over both gets the same contacts bit for bit, mixed with
// stored pieces (a ledge, a rock) before, between and after the fields.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <random>
#include <stdexcept>
#include <vector>

#include "random_heightfield.hpp"
#include "wtc/error.hpp"
#include "wtc/heightfield.hpp"
#include "wtc/terrain.hpp"
#include "wtc/terrain_primitives.hpp"
#include "wtc/wheel_contact.hpp"

namespace wtc {
namespace {

double uniform(std::mt19937& gen, double lo, double hi) { return lo + (hi - lo) * (gen() / 4294967296.0); }

// Gentle random relief (a few cm) on 0.25 x 0.3 m cells, centred on y = 0.
Heightfield field(int rows, int cols, double x0, std::uint32_t seed) {
  return testing::randomHeightfield(
      rows, cols, 0.03, seed,
      {.spacing_x = 0.25, .spacing_y = 0.3, .origin = {x0, -0.5 * (rows - 1) * 0.3, 0.0}, .base_depth = 0.5});
}

// Stored box, field A (materials per cell), a ledge, field B, a rock: ids
// interleave.
Terrain mixed(bool compact) {
  TerrainBuilder b;
  const MaterialId asphalt = b.addMaterial(Material{});
  const MaterialId gravel = b.addMaterial(Material{.name = "gravel", .mu_max = 0.6});
  b.addPiece(ConvexPolyhedron::box({-20, -3, -1}, {-19, 3, 0}), asphalt);
  const auto add = [&](const Heightfield& f, MaterialId m) {
    return compact ? addCompactHeightfield(b, f, m) : addHeightfield(b, f, m);
  };
  Heightfield a = field(12, 20, -2.0, 1);
  a.cell_materials.resize(11 * 19, gravel);  // field A: gravel, with an asphalt stripe
  for (int c = 0; c < 19; ++c) a.cell_materials[5 * 19 + c] = a.cell_materials[6 * 19 + c] = asphalt;
  add(a, gravel);
  b.addPiece(ConvexPolyhedron::box({2.75, -1.5, -0.2}, {3.0, 1.5, 0.12}), asphalt);  // a ledge between the fields
  add(field(12, 16, 3.0, 2), asphalt);
  b.addPiece(ConvexPolyhedron::box({5.0, -0.2, 0.0}, {5.3, 0.2, 0.08}), gravel);  // a rock on field B
  return std::move(b).build();
}

TEST(CompactTerrainTest, NumbersItsPiecesAsTheStoredTerrainDoes) {
  const Terrain stored = mixed(false), compact = mixed(true);
  ASSERT_EQ(compact.pieceCount(), stored.pieceCount());
  EXPECT_EQ(compact.pieces().size(), 3u);  // the box, the ledge, the rock
  EXPECT_EQ(compact.bounds().min, stored.bounds().min);
  EXPECT_EQ(compact.bounds().max, stored.bounds().max);
  std::optional<ConvexPolyhedron> scratch;
  int formed = 0;
  for (PieceId id = 0; id < static_cast<PieceId>(stored.pieceCount()); ++id) {
    SCOPED_TRACE(id);
    EXPECT_EQ(compact.materialId(id), stored.materialId(id));
    const Aabb box = compact.pieceBounds(id);
    EXPECT_EQ(box.min, stored.piece(id).bounds().min);
    EXPECT_EQ(box.max, stored.piece(id).bounds().max);
    const ConvexPolyhedron& p = compact.piece(id, scratch);
    ASSERT_EQ(p.vertexCount(), stored.piece(id).vertexCount());
    for (int v = 0; v < p.vertexCount(); ++v) EXPECT_EQ(p.vertex(v), stored.piece(id).vertex(v));
    for (int f = 0; f < p.faceCount(); ++f) EXPECT_EQ(p.faceOffset(f), stored.piece(id).faceOffset(f));
    if (compact.isFormed(id)) {
      ++formed;
      EXPECT_THROW(compact.piece(id), InvalidInputError);
    } else {
      EXPECT_EQ(&compact.piece(id), &compact.piece(id, scratch));  // stored: itself, no copy
    }
  }
  EXPECT_EQ(formed, static_cast<int>(stored.pieceCount()) - 3);
  EXPECT_LT(compact.pieceMemoryBytes() * 50, stored.pieceMemoryBytes());
}

// Case: what an engine plugin walks: the stored pieces by their ids
// (storedId), and each compact field by its id range and samples
// (compactField); pieceUnder names the triangle under a point, clamped
// onto the grid.
TEST(CompactTerrainTest, TellsThePluginsItsStoredPiecesAndItsFields) {
  const Terrain compact = mixed(true);
  ASSERT_EQ(compact.pieces().size(), 3u);
  PieceId last = -1;
  for (std::size_t s = 0; s < compact.pieces().size(); ++s) {
    const PieceId id = compact.storedId(s);
    EXPECT_GT(id, last);
    last = id;
    EXPECT_FALSE(compact.isFormed(id));
    EXPECT_EQ(&compact.piece(id), &compact.pieces()[s]);
  }
  EXPECT_EQ(last, static_cast<PieceId>(compact.pieceCount()) - 1);  // the rock, added last
  ASSERT_EQ(compact.compactFieldCount(), 2u);
  EXPECT_EQ(compact.compactField(0).first, 1);  // after the box
  EXPECT_EQ(compact.compactField(0).count, 2 * 11 * 19);
  EXPECT_EQ(compact.compactField(1).first, 1 + 2 * 11 * 19 + 1);  // after the ledge
  EXPECT_EQ(compact.compactField(1).material, compact.materialId(compact.compactField(1).first));
  EXPECT_THROW(compact.compactField(2), std::out_of_range);
  std::mt19937 gen(3);
  std::optional<ConvexPolyhedron> scratch;
  for (std::size_t k = 0; k < 2; ++k) {
    const Terrain::CompactField field = compact.compactField(k);
    const Heightfield& f = *field.field;
    const PieceRange range{field.first, field.count};
    for (int i = 0; i < 500; ++i) {
      // Some points off the grid: they belong to the nearest edge's triangle.
      const Eigen::Vector2d p = testing::randomPointOn(f, gen, -0.2);
      const PieceId id = pieceUnder(range, f, p.x(), p.y());
      ASSERT_GE(id, field.first);
      ASSERT_LT(id, field.first + field.count);
      const double x = std::clamp(p.x(), f.origin.x(), f.origin.x() + (f.cols - 1) * f.spacing_x);
      const double y = std::clamp(p.y(), f.origin.y(), f.origin.y() + (f.rows - 1) * f.spacing_y);
      const Eigen::Vector3d on_top(x, y, *surfaceHeight(f, x, y));
      EXPECT_LE(testing::outside(compact.piece(id, scratch), on_top), 1e-12) << "field " << k << ", piece " << id;
    }
  }
}

TEST(CompactTerrainTest, FindsTheSameCandidatesForAnyBox) {
  const Terrain stored = mixed(false), compact = mixed(true);
  std::mt19937 gen(5);
  std::vector<PieceId> a, b;
  for (int trial = 0; trial < 3000; ++trial) {
    const Eigen::Vector3d c(uniform(gen, -21, 7), uniform(gen, -3, 3), uniform(gen, -0.7, 0.4));
    const Eigen::Vector3d half = Eigen::Vector3d::Constant(uniform(gen, 0.01, 0.6));
    a.clear();
    b.clear();
    stored.overlapping({c - half, c + half}, a);
    compact.overlapping({c - half, c + half}, b);
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    ASSERT_EQ(b, a) << "trial " << trial;
  }
}

TEST(CompactTerrainTest, AWheelDrivenOverItMeetsTheSameContactsBitForBit) {
  const Terrain stored = mixed(false), compact = mixed(true);
  const WheelGeometry wheel{.free_radius = 0.19, .tread_width = 0.12};
  WheelContactFinder on_stored, on_compact;
  std::size_t contacts = 0, seams = 0;
  // Across field A, up the ledge's face, over field B and the rock: 1 mm
  // steps, the centre bobbing so that it sinks 0-30 mm into the relief.
  for (int k = 0; k < 9000; ++k) {
    const double x = -1.8 + 0.001 * k;
    const WheelPose pose{.center = {x, 0.1 * std::sin(0.7 * x), 0.19 - 0.015 * (1.0 + std::sin(9.0 * x))},
                         .axle = {0.05, 1.0, 0.02}};
    const auto a = on_stored.find(stored, wheel, pose);
    const auto b = on_compact.find(compact, wheel, pose);
    ASSERT_EQ(b.size(), a.size()) << "step " << k;
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(b[i].piece, a[i].piece);
      EXPECT_EQ(b[i].material, a[i].material);
      EXPECT_EQ(b[i].point, a[i].point);
      EXPECT_EQ(b[i].ground_point, a[i].ground_point);
      EXPECT_EQ(b[i].e, a[i].e);
      EXPECT_EQ(b[i].deflection, a[i].deflection);
      EXPECT_EQ(b[i].load_share, a[i].load_share);
      seams += a[i].load_share < 1.0;
    }
    contacts += a.size();
    if (::testing::Test::HasFailure()) FAIL() << "step " << k;
  }
  EXPECT_GT(contacts, 7000u);  // on the ground most of the way (measured: 8413 contacts in 9000 steps)
  EXPECT_GT(seams, 0u);        // and the seam rule had creases to share
}

TEST(CompactTerrainTest, RefusesAnUnregisteredMaterialAndABadField) {
  TerrainBuilder b;
  b.addMaterial(Material{});
  EXPECT_THROW(addCompactHeightfield(b, field(3, 3, 0.0, 1), 7), InvalidInputError);
  Heightfield bad = field(3, 3, 0.0, 1);
  bad.heights.pop_back();
  EXPECT_THROW(addCompactHeightfield(b, bad, 0), InvalidInputError);
  EXPECT_EQ(b.pieceCount(), 0u);
}

}  // namespace
}  // namespace wtc
