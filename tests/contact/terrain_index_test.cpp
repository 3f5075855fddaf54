// The terrain's spatial index against brute force over random terrains and
// random wheels: the same candidate set, every time.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include <wtc/base/error.hpp>
#include <wtc/terrain/terrain.hpp>
#include <wtc/contact/wheel_contact.hpp>

namespace {

using Eigen::Vector3d;

wtc::Terrain randomTerrain(std::mt19937_64& rng, int pieces) {
  std::uniform_real_distribution<double> position(-50.0, 50.0);
  std::uniform_real_distribution<double> size(0.01, 3.0);
  wtc::TerrainBuilder builder;
  const auto material = builder.addMaterial({});
  for (int k = 0; k < pieces; ++k) {
    const Vector3d lo(position(rng), position(rng), position(rng) * 0.1);
    builder.addPiece(wtc::ConvexPolyhedron::box(lo, lo + Vector3d(size(rng), size(rng), size(rng))), material);
  }
  return std::move(builder).build();
}

TEST(TerrainIndexTest, OverlappingMatchesBruteForceOnRandomTerrainsAndWheels) {
  std::mt19937_64 rng(20261121);
  std::uniform_real_distribution<double> position(-52.0, 52.0);
  std::uniform_real_distribution<double> radius(0.05, 2.0);
  int nonempty = 0;
  for (const int pieces : {1, 2, 5, 17, 100, 1000, 5000}) {
    const wtc::Terrain terrain = randomTerrain(rng, pieces);
    std::vector<wtc::PieceId> found;
    for (int trial = 0; trial < 2000; ++trial) {
      const Vector3d c(position(rng), position(rng), position(rng) * 0.1);
      const double r = radius(rng);
      const wtc::Aabb box{c.array() - r, c.array() + r};
      found.clear();
      terrain.overlapping(box, found);
      std::vector<wtc::PieceId> expected;
      for (wtc::PieceId id = 0; id < static_cast<wtc::PieceId>(terrain.pieceCount()); ++id) {
        if (terrain.piece(id).bounds().overlaps(box)) expected.push_back(id);
      }
      std::sort(found.begin(), found.end());
      ASSERT_EQ(found, expected) << pieces << " pieces, trial " << trial;
      nonempty += !expected.empty();
    }
  }
  EXPECT_GT(nonempty, 2000);  // the trials really hit pieces
}

TEST(TerrainIndexTest, BoxesTouchingAtAFaceAreBothFound) {
  // Case: float rounding of node boxes must never lose a piece whose box
  // just touches the query box.
  wtc::TerrainBuilder builder;
  const auto material = builder.addMaterial({});
  for (int k = 0; k < 100; ++k) {
    builder.addPiece(wtc::ConvexPolyhedron::box({0.125 * k, 0, 0}, {0.125 * (k + 1), 1, 1}), material);
  }
  const wtc::Terrain terrain = std::move(builder).build();
  std::vector<wtc::PieceId> found;
  terrain.overlapping({{0.375, 0.5, 0.5}, {0.375, 0.5, 0.5}}, found);  // 3 x 0.125 exactly
  std::sort(found.begin(), found.end());
  EXPECT_EQ(found, (std::vector<wtc::PieceId>{2, 3}));
}

TEST(TerrainIndexTest, EmptyTerrainIsAnError) {
  wtc::TerrainBuilder builder;
  EXPECT_THROW(std::move(builder).build(), wtc::InvalidInputError);
}

}  // namespace
