// A terrain's stored pieces live in one arena (src/terrain/piece_arena.hpp)
// after build(): every piece answers exactly as the piece that was added,
// whatever its topology and however the builder's list grew; equal
// topologies are stored once; copies of pieces and of whole terrains own
// their memory and outlive the terrain they came from.
#include "terrain/piece_arena.hpp"

#include "geometry/polyhedron_layout.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <random>
#include <vector>

#include "wtc/geometry/point_query.hpp"
#include "random_heightfield.hpp"
#include "wtc/terrain/heightfield.hpp"
#include "wtc/terrain/terrain.hpp"
#include "wtc/terrain/triangle_mesh.hpp"

namespace {

using Eigen::Vector3d;
using wtc::ConvexPolyhedron;

// Two doubles the same to the bit (answers must not merely agree to a
// tolerance: the arena copies numbers, it computes nothing).
bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

void expectSameVector(const Vector3d& a, const Vector3d& b) {
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(sameBits(a[k], b[k])) << a.transpose() << " vs " << b.transpose();
}

// Everything a user can read of a piece, and its query answers at `points`.
void expectSamePiece(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const std::vector<Vector3d>& points) {
  ASSERT_EQ(a.vertexCount(), b.vertexCount());
  ASSERT_EQ(a.faceCount(), b.faceCount());
  EXPECT_EQ(a.isFlat(), b.isFlat());
  expectSameVector(a.origin(), b.origin());
  for (int i = 0; i < a.vertexCount(); ++i) expectSameVector(a.vertexLocal(i), b.vertexLocal(i));
  for (int f = 0; f < a.faceCount(); ++f) {
    expectSameVector(a.faceNormal(f), b.faceNormal(f));
    EXPECT_TRUE(sameBits(a.faceOffsetLocal(f), b.faceOffsetLocal(f)));
    const auto fa = a.faceVertices(f), fb = b.faceVertices(f);
    EXPECT_TRUE(std::equal(fa.begin(), fa.end(), fb.begin(), fb.end())) << "face " << f;
  }
  for (const Vector3d& p : points) {
    const wtc::PointQuery qa = wtc::queryPoint(a, p), qb = wtc::queryPoint(b, p);
    EXPECT_TRUE(sameBits(qa.signed_distance, qb.signed_distance)) << p.transpose();
    expectSameVector(qa.closest_point, qb.closest_point);
    expectSameVector(qa.normal, qb.normal);
    EXPECT_EQ(qa.status, qb.status);
    EXPECT_EQ(a.support(p), b.support(p));
  }
}

std::vector<Vector3d> pointsAround(const ConvexPolyhedron& piece, std::mt19937_64& rng, int count) {
  const Vector3d c = piece.bounds().center(), half = piece.bounds().extent();
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  std::vector<Vector3d> points;
  for (int k = 0; k < count; ++k) points.push_back(c + Vector3d(u(rng), u(rng), u(rng)).cwiseProduct(half));
  return points;
}

// Boxes, hulls of 5 to 60 points (the large ones keep vertex adjacency for
// the hill climb: a longer topology) and flat polygons, in random order.
std::vector<ConvexPolyhedron> mixedPieces(std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> at(-100.0, 100.0), u(-1.0, 1.0);
  std::uniform_int_distribution<int> kind(0, 2), points(5, 60);
  std::vector<ConvexPolyhedron> pieces;
  for (int k = 0; k < count; ++k) {
    const Vector3d c(at(rng), at(rng), 0.1 * at(rng));
    switch (kind(rng)) {
      case 0:
        pieces.push_back(ConvexPolyhedron::box(c, c + Vector3d(1.0 + u(rng), 1.5 + u(rng), 0.5 + 0.4 * u(rng))));
        break;
      case 1: {
        std::vector<Vector3d> cloud;
        for (int i = points(rng); i > 0; --i) cloud.push_back(c + Vector3d(u(rng), u(rng), u(rng)));
        pieces.push_back(ConvexPolyhedron::fromPoints(cloud));
        break;
      }
      default: {
        std::vector<Vector3d> polygon;
        for (int i = 0; i < 7; ++i) polygon.push_back(c + Vector3d(std::cos(0.9 * i), std::sin(0.9 * i), 0.0));
        pieces.push_back(ConvexPolyhedron::fromPoints(polygon));
      }
    }
  }
  return pieces;
}

// Case: a terrain of many pieces of many topologies, added one at a time
// without reserve (the builder's list reallocates, moving every piece, a
// dozen times), answers for every piece exactly as the piece added.
TEST(PieceArenaTest, EveryPieceOfAGrownTerrainAnswersAsThePieceAdded) {
  std::mt19937_64 rng(20261127);
  const std::vector<ConvexPolyhedron> added = mixedPieces(rng, 3000);
  wtc::TerrainBuilder builder;
  const auto material = builder.addMaterial({});
  for (const ConvexPolyhedron& piece : added) builder.addPiece(piece, material);
  const wtc::Terrain terrain = std::move(builder).build();
  ASSERT_EQ(terrain.pieceCount(), added.size());
  for (std::size_t id = 0; id < added.size(); ++id) {
    SCOPED_TRACE("piece " + std::to_string(id));
    expectSamePiece(terrain.piece(static_cast<wtc::PieceId>(id)), added[id], pointsAround(added[id], rng, 4));
  }
}

// Case: a heightfield's and a mesh's prisms are made only when the terrain
// is built, straight into the arena (src/terrain/pending_prisms.hpp): each
// is, bit for bit and in its query kernel, the prism makeTriangularPrism
// and makeExtrudedTriangle make of its corners, with its cell's material,
// its id where the pieces added one by one put it (holes skipped, stored
// pieces and a compact field between).
TEST(PieceArenaTest, MakesAHeightfieldsAndAMeshsPrismsInPlaceAsTheirBuildersDo) {
  std::mt19937_64 rng(11);
  wtc::Heightfield field = wtc::testing::randomHeightfield(9, 12, 0.4, 5);
  const int cells = (field.rows - 1) * (field.cols - 1);
  field.cell_holes.assign(static_cast<std::size_t>(cells), 0);
  for (int cell = 0; cell < cells; cell += 7) field.cell_holes[static_cast<std::size_t>(cell)] = 1;
  wtc::TerrainBuilder builder;
  const auto first_material = builder.addMaterial({});
  const auto second_material = builder.addMaterial({});
  for (int cell = 0; cell < cells; ++cell) field.cell_materials.push_back(cell % 3 == 0 ? second_material : first_material);
  builder.addPiece(ConvexPolyhedron::box(Vector3d(0, 0, -9), Vector3d(1, 1, -8)), first_material);
  const wtc::PieceRange grid = wtc::addHeightfield(builder, field, first_material);
  wtc::addCompactHeightfield(builder, wtc::testing::randomHeightfield(4, 5, 0.2, 6), first_material);
  wtc::TriangleMesh mesh;
  mesh.name = "bumps";
  for (int k = 0; k < 30; ++k) mesh.vertices.emplace_back(0.3 * k, 0.2 * (k % 2), 0.05 * std::sin(k));  // a zigzag strip
  for (int k = 0; k + 2 < 30; ++k) mesh.triangles.push_back({k, k + 1, k + 2});
  wtc::MeshExtrusionOptions options;
  options.thickness = 0.25;
  const wtc::MeshBuildReport extruded = wtc::addTriangleMesh(builder, mesh, second_material, options);
  builder.addPiece(ConvexPolyhedron::box(Vector3d(5, 0, -9), Vector3d(6, 1, -8)), second_material);
  const wtc::Terrain terrain = std::move(builder).build();

  const double base_z = field.baseZ();
  const auto expectMade = [&](wtc::PieceId id, const ConvexPolyhedron& expected, wtc::MaterialId material) {
    SCOPED_TRACE("piece " + std::to_string(id));
    const ConvexPolyhedron& made = terrain.piece(id);
    expectSamePiece(made, expected, pointsAround(expected, rng, 4));
    EXPECT_EQ(wtc::detail::PolyhedronLayout::kernel(made), wtc::detail::PolyhedronLayout::kernel(expected));
    EXPECT_EQ(terrain.materialId(id), material);
    EXPECT_EQ(made.bounds().min, expected.bounds().min);
    EXPECT_EQ(made.bounds().max, expected.bounds().max);
  };
  wtc::PieceId id = grid.first;
  for (int r = 0; r + 1 < field.rows; ++r) {
    for (int c = 0; c + 1 < field.cols; ++c) {
      if (field.isHole(r, c)) continue;
      const auto cell = static_cast<std::size_t>(r * (field.cols - 1) + c);
      const Vector3d p00 = field.sample(r, c), p01 = field.sample(r, c + 1);
      const Vector3d p10 = field.sample(r + 1, c), p11 = field.sample(r + 1, c + 1);
      expectMade(id++, wtc::makeTriangularPrism(p00, p01, p11, base_z), field.cell_materials[cell]);
      expectMade(id++, wtc::makeTriangularPrism(p00, p11, p10, base_z), field.cell_materials[cell]);
    }
  }
  EXPECT_EQ(id, grid.end());
  ASSERT_EQ(extruded.pieces.count, static_cast<wtc::PieceId>(mesh.triangles.size()));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    expectMade(extruded.pieces.first + static_cast<wtc::PieceId>(t),
               wtc::makeExtrudedTriangle(mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]],
                                         options.thickness),
               second_material);
  }
  EXPECT_EQ(terrain.materialId(extruded.pieces.end()), second_material);  // the last box
}

// Case: the arena itself: equal topologies once, each piece pointed at its
// own numbers, the block counted whole.
TEST(PieceArenaTest, StoresEachDistinctTopologyOnceAndEveryPiecesNumbers) {
  std::mt19937_64 rng(7);
  std::vector<ConvexPolyhedron> pieces;
  for (int k = 0; k < 500; ++k) {
    const Vector3d lo(k, 0.5 * k, 0.0);
    pieces.push_back(ConvexPolyhedron::box(lo, lo + Vector3d(1.0, 2.0, 0.5 + 0.001 * k)));
  }
  const ConvexPolyhedron hull = ConvexPolyhedron::fromPoints(
      {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0), Vector3d(0, 0, 1)});
  pieces.push_back(hull);
  const std::vector<ConvexPolyhedron> before = pieces;
  // Reversed order: the arena lays pieces out in the order asked.
  std::vector<std::int32_t> order(pieces.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<std::int32_t>(order.size() - 1 - k);
  std::vector<std::uint32_t> first_line;
  const wtc::detail::PieceArena arena(pieces, {}, order, first_line);
  EXPECT_EQ(arena.topologyCount(), 2u);  // a box's and the tetrahedron's
  ASSERT_EQ(first_line.size(), pieces.size());
  for (std::size_t k = 1; k < first_line.size(); ++k) EXPECT_GT(first_line[k], first_line[k - 1]);
  // A box's 3 x 8 + 4 x 6 + 4 x 24 numbers (1152 bytes), on whole lines,
  // plus the tetrahedron's and two topologies: nothing per piece besides.
  EXPECT_LT(arena.memoryBytes(), 501 * 1152 + 4096);
  const auto* begin = reinterpret_cast<const unsigned char*>(arena.base());
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const auto numbers = wtc::detail::PolyhedronLayout::numbers(pieces[k]);
    const auto topology = wtc::detail::PolyhedronLayout::topology(pieces[k]);
    const auto* at = reinterpret_cast<const unsigned char*>(numbers.data());
    EXPECT_EQ(at, begin + 64 * std::size_t{first_line[order.size() - 1 - k]}) << "piece " << k;
    EXPECT_TRUE(reinterpret_cast<const unsigned char*>(topology.data()) >= begin &&
                reinterpret_cast<const unsigned char*>(topology.data() + topology.size()) <=
                    begin + arena.memoryBytes())
        << "piece " << k << "'s topology is not in the arena";
    expectSamePiece(pieces[k], before[k], pointsAround(before[k], rng, 3));
  }
}

// Case: a piece copied out of a terrain, and a copy of the terrain, outlive
// the terrain: they own their memory. (Were a copy to keep pointing into
// the arena, reading it after the terrain is gone reads freed memory: on a
// terrain this large the arena's pages are returned, and the read faults.)
TEST(PieceArenaTest, CopiesOfPiecesAndTerrainsOutliveTheTerrain) {
  wtc::Heightfield field;
  field.rows = field.cols = 200;  // 79,202 prisms: a multi-megabyte arena
  field.spacing_x = field.spacing_y = 0.5;
  field.heights.resize(static_cast<std::size_t>(field.rows) * field.cols);
  for (std::size_t k = 0; k < field.heights.size(); ++k) field.heights[k] = 0.01 * static_cast<double>(k % 37);
  const auto build = [&] {
    wtc::TerrainBuilder builder;
    wtc::addHeightfield(builder, field, builder.addMaterial({}));
    return std::move(builder).build();
  };
  auto terrain = std::make_unique<wtc::Terrain>(build());
  const wtc::Terrain reference = build();  // the same pieces, built again
  std::mt19937_64 rng(3);
  const std::vector<wtc::PieceId> ids = {0, 1, 4321, 40000, static_cast<wtc::PieceId>(terrain->pieceCount() - 1)};
  std::vector<ConvexPolyhedron> copies, fresh;
  ConvexPolyhedron assigned = ConvexPolyhedron::box(Vector3d::Zero(), Vector3d::Ones());
  for (const wtc::PieceId id : ids) {
    copies.push_back(terrain->piece(id));
    fresh.push_back(reference.piece(id));
  }
  assigned = terrain->piece(ids[2]);  // assignment into a box's larger block
  auto copy = std::make_unique<wtc::Terrain>(*terrain);
  wtc::Terrain assigned_terrain = *copy;
  assigned_terrain = *terrain;
  terrain.reset();
  for (std::size_t k = 0; k < ids.size(); ++k) {
    SCOPED_TRACE("piece " + std::to_string(ids[k]));
    const std::vector<Vector3d> points = pointsAround(fresh[k], rng, 8);
    expectSamePiece(copies[k], fresh[k], points);
    expectSamePiece(copy->piece(ids[k]), fresh[k], points);
    expectSamePiece(assigned_terrain.piece(ids[k]), fresh[k], points);
  }
  expectSamePiece(assigned, fresh[2], pointsAround(fresh[2], rng, 8));
  // The copy's index still finds the pieces, in its own arena.
  std::vector<wtc::PieceId> near;
  copy->overlapping(fresh[3].bounds(), near);
  EXPECT_NE(std::find(near.begin(), near.end(), ids[3]), near.end());
}

}  // namespace
