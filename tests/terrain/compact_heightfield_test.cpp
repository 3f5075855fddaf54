// The compact heightfield (src/terrain/compact_heightfield.hpp, internal to
// wtc::core) against the prisms addHeightfield stores: the same pieces bit
// for bit, the same bounds, the same answer to "which pieces overlap this
// box".
#include "terrain/compact_heightfield.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "geometry/polyhedron_layout.hpp"
#include "random_heightfield.hpp"
#include "wtc/base/error.hpp"
#include "wtc/terrain/terrain.hpp"

namespace wtc {
namespace {

using Layout = detail::PolyhedronLayout;

double uniform(std::mt19937& gen, double lo, double hi) { return lo + (hi - lo) * (gen() / 4294967296.0); }

// Unequal, non-binary spacings and an offset origin, so that any difference
// in how a corner is computed shows in the last bits.
Heightfield randomField(int rows, int cols, std::uint32_t seed) {
  return testing::randomHeightfield(rows, cols, 0.5, seed,
                                    {.spacing_x = 0.3, .spacing_y = 0.7, .origin = {-3.1, 2.3, 10.0}});
}

void expectSameBits(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  ASSERT_EQ(a.vertexCount(), b.vertexCount());
  ASSERT_EQ(a.faceCount(), b.faceCount());
  EXPECT_EQ(a.origin(), b.origin());
  for (int i = 0; i < a.vertexCount(); ++i) EXPECT_EQ(a.vertexLocal(i), b.vertexLocal(i)) << "vertex " << i;
  for (int f = 0; f < a.faceCount(); ++f) {
    EXPECT_EQ(a.faceNormal(f), b.faceNormal(f)) << "face " << f;
    EXPECT_EQ(a.faceOffsetLocal(f), b.faceOffsetLocal(f)) << "face " << f;
  }
  EXPECT_EQ(a.bounds().min, b.bounds().min);
  EXPECT_EQ(a.bounds().max, b.bounds().max);
  EXPECT_EQ(a.size(), b.size());
  EXPECT_EQ(a.centroidLocal(), b.centroidLocal());
  EXPECT_EQ(a.isFlat(), b.isFlat());
  EXPECT_EQ(a.memoryBytes(), b.memoryBytes());
  // Topology: face lists and edge twins.
  for (int f = 0; f < a.faceCount(); ++f) {
    const auto fa = a.faceVertices(f), fb = b.faceVertices(f);
    ASSERT_TRUE(std::equal(fa.begin(), fa.end(), fb.begin(), fb.end())) << "face " << f;
    for (std::int32_t e = Layout::faceEdgeStart(a, f);
         e < Layout::faceEdgeStart(a, f) + static_cast<std::int32_t>(fa.size()); ++e) {
      EXPECT_EQ(Layout::faceEdgeTwin(a, e), Layout::faceEdgeTwin(b, e)) << "face-edge " << e;
      for (int i = 0; i < 4; ++i)
        EXPECT_EQ(Layout::faceEdgePlane(a, e)[i], Layout::faceEdgePlane(b, e)[i]) << "face-edge " << e;
    }
  }
}

struct Both {
  Heightfield field;
  Terrain stored;
  PieceRange range;
  detail::CompactHeightfield compact;
};

Both build(const Heightfield& f) {
  TerrainBuilder builder;
  const MaterialId m = builder.addMaterial(Material{});
  builder.addPiece(ConvexPolyhedron::box({0, 0, -20}, {1, 1, -19}), m);  // ids need not start at 0
  const PieceRange range = addHeightfield(builder, f, m);
  return {f, std::move(builder).build(), range, detail::CompactHeightfield(f)};
}

TEST(CompactHeightfieldTest, FormsEveryPrismBitForBitAsAddHeightfieldStoresIt) {
  const Both b = build(randomField(13, 17, 1));
  ASSERT_EQ(b.compact.pieceCount(), static_cast<std::size_t>(b.range.count));
  for (std::size_t k = 0; k < b.compact.pieceCount(); ++k) {
    SCOPED_TRACE(k);
    const ConvexPolyhedron& stored = b.stored.piece(b.range.first + static_cast<PieceId>(k));
    expectSameBits(b.compact.piece(k), stored);
    const Aabb box = b.compact.pieceBounds(k);
    EXPECT_EQ(box.min, stored.bounds().min);
    EXPECT_EQ(box.max, stored.bounds().max);
  }
}

TEST(CompactHeightfieldTest, FindsTheSamePiecesAsTheTerrainIndexForAnyBox) {
  const Both b = build(randomField(21, 14, 2));
  std::mt19937 gen(3);
  // The field's own extent (the terrain's also holds the extra box).
  const Aabb all{b.compact.pieceBounds(0).min, b.compact.pieceBounds(b.compact.pieceCount() - 1).max};
  std::vector<PieceId> expected, found;
  int nonempty = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    // Boxes from wheel-sized to a few cells, some reaching past the field's
    // edges, some above it or below its base; every tenth exactly on cell
    // lines, where the exact test decides.
    const Eigen::Vector3d half(uniform(gen, 0.01, 1.5), uniform(gen, 0.01, 1.5), uniform(gen, 0.01, 1.0));
    Eigen::Vector3d centre(uniform(gen, all.min.x() - 1, all.max.x() + 1),
                           uniform(gen, all.min.y() - 1, all.max.y() + 1),
                           uniform(gen, all.min.z() - 0.5, all.max.z() + 0.5));
    Aabb box{centre - half, centre + half};
    if (trial % 10 == 0) {
      box.min.x() = b.field.origin.x() + static_cast<int>(uniform(gen, 0, 13)) * b.field.spacing_x;
      box.max.y() = b.field.origin.y() + static_cast<int>(uniform(gen, 0, 20)) * b.field.spacing_y;
    }
    expected.clear();
    found.clear();
    b.stored.overlapping(box, expected);
    expected.erase(std::remove(expected.begin(), expected.end(), 0), expected.end());  // the extra box
    b.compact.overlapping(box, b.range.first, found);
    std::sort(expected.begin(), expected.end());
    std::sort(found.begin(), found.end());
    ASSERT_EQ(found, expected) << "trial " << trial;
    nonempty += !found.empty();
  }
  EXPECT_GT(nonempty, 500);  // the boxes did meet the field
  // A box holding everything finds every piece; one with a NaN none.
  found.clear();
  b.compact.overlapping({Eigen::Vector3d::Constant(-1e300), Eigen::Vector3d::Constant(1e300)}, b.range.first, found);
  EXPECT_EQ(found.size(), b.compact.pieceCount());
  found.clear();
  b.compact.overlapping({Eigen::Vector3d(std::nan(""), 0, 0), Eigen::Vector3d::Constant(1e300)}, b.range.first, found);
  EXPECT_TRUE(found.empty());
}

// Holes at random (three in ten cells), a run of 130 (two whole blocks of
// the running count), the first row and the last column (the bounds shrink).
Heightfield holedField(int rows, int cols, std::uint32_t seed) {
  Heightfield f = randomField(rows, cols, seed);
  std::mt19937 gen(seed);
  f.cell_holes.assign(f.cellCount(), 0);
  for (std::uint8_t& h : f.cell_holes) h = gen() % 10 < 3 ? 1 : 0;
  std::fill_n(f.cell_holes.begin() + 300, 130, std::uint8_t{1});
  for (int c = 0; c + 1 < cols; ++c) f.cell_holes[c] = 1;
  for (int r = 0; r + 1 < rows; ++r) f.cell_holes[r * (cols - 1) + cols - 2] = 1;
  f.cell_materials.resize(f.cellCount());
  for (std::size_t cell = 0; cell < f.cellCount(); ++cell) f.cell_materials[cell] = static_cast<MaterialId>(cell % 3);
  return f;
}

// Case: holes shift the ids of every later piece; the compact field maps
// ids to cells through its running count, across blocks and whole blocks
// of holes.
TEST(CompactHeightfieldTest, SkipsHolesAsAddHeightfieldDoes) {
  const Heightfield f = holedField(30, 41, 6);
  TerrainBuilder builder;
  for (int m = 0; m < 3; ++m) builder.addMaterial(Material{});
  const PieceRange range = addHeightfield(builder, f, 0);
  const Terrain stored = std::move(builder).build();
  const detail::CompactHeightfield compact(f);
  ASSERT_EQ(compact.pieceCount(), static_cast<std::size_t>(range.count));
  ASSERT_EQ(compact.pieceCount(), f.pieceCount());
  EXPECT_LT(compact.pieceCount(), 2 * f.cellCount() * 7 / 10);
  Aabb all = stored.piece(0).bounds();
  for (std::size_t k = 0; k < compact.pieceCount(); ++k) {
    SCOPED_TRACE(k);
    const ConvexPolyhedron& piece = stored.piece(static_cast<PieceId>(k));
    expectSameBits(compact.piece(k), piece);
    EXPECT_EQ(compact.materialId(k, 0), stored.materialId(static_cast<PieceId>(k)));
    all.include(piece.bounds().min);
    all.include(piece.bounds().max);
  }
  EXPECT_EQ(compact.bounds().min, all.min);
  EXPECT_EQ(compact.bounds().max, all.max);
  EXPECT_GT(all.min.y(), f.origin.y());  // the first row is all holes
  std::mt19937 gen(7);
  std::vector<PieceId> expected, found;
  for (int trial = 0; trial < 2000; ++trial) {
    const Eigen::Vector3d half(uniform(gen, 0.01, 1.5), uniform(gen, 0.01, 1.5), uniform(gen, 0.01, 1.0));
    const Eigen::Vector3d centre(uniform(gen, all.min.x() - 1, all.max.x() + 1),
                                 uniform(gen, all.min.y() - 1, all.max.y() + 1),
                                 uniform(gen, all.min.z() - 0.5, all.max.z() + 0.5));
    expected.clear();
    found.clear();
    stored.overlapping({centre - half, centre + half}, expected);
    compact.overlapping({centre - half, centre + half}, 0, found);
    std::sort(expected.begin(), expected.end());
    std::sort(found.begin(), found.end());
    ASSERT_EQ(found, expected) << "trial " << trial;
  }
}

TEST(CompactHeightfieldTest, KeepsEightBytesASample) {
  const detail::CompactHeightfield compact(randomField(200, 300, 4));
  // 8 a sample (8.07 a cell here), 12 / 64 for the tiles (top, lowest, slope).
  const double per_cell = static_cast<double>(compact.memoryBytes()) / (199.0 * 299.0);
  EXPECT_LT(per_cell, 8.3);
  EXPECT_GT(per_cell, 8.2);
}

TEST(CompactHeightfieldTest, KeepsAByteACellForHoles) {
  const detail::CompactHeightfield compact(holedField(200, 300, 4));
  // 8 a sample, 4 for the material, 1 for the hole, 4 / 64 for the count,
  // 12 / 64 for the tiles.
  const double per_cell = static_cast<double>(compact.memoryBytes()) / (199.0 * 299.0);
  EXPECT_LT(per_cell, 13.4);
  EXPECT_GT(per_cell, 13.25);
}

TEST(CompactHeightfieldTest, RefusesAMalformedFieldAsValidateDoes) {
  Heightfield f = randomField(3, 3, 5);
  f.heights[4] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(detail::CompactHeightfield{f}, InvalidInputError);
}

}  // namespace
}  // namespace wtc
