// A terrain holding compact heightfields (addCompactHeightfield) and
// compact triangle meshes (MeshExtrusionOptions::compact) against the same
// terrain with them stored as prisms (addHeightfield, addTriangleMesh): the
// same ids, materials and boxes, the same candidates for any box, and a
// wheel driven over both gets the same contacts bit for bit, mixed with
// stored pieces (a ledge, a rock) before, between and after them.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <stdexcept>
#include <vector>

#include "random_heightfield.hpp"
#include "wtc/base/error.hpp"
#include "wtc/terrain/heightfield.hpp"
#include "wtc/geometry/point_query.hpp"
#include "wtc/terrain/terrain.hpp"
#include "wtc/terrain/terrain_primitives.hpp"
#include "wtc/terrain/triangle_mesh.hpp"
#include "wtc/contact/wheel_contact.hpp"

namespace wtc {
namespace {

double uniform(std::mt19937& gen, double lo, double hi) { return lo + (hi - lo) * (gen() / 4294967296.0); }

// Gentle random relief (a few cm) on 0.25 x 0.3 m cells, centred on y = 0.
Heightfield field(int rows, int cols, double x0, std::uint32_t seed) {
  return testing::randomHeightfield(
      rows, cols, 0.03, seed,
      {.spacing_x = 0.25, .spacing_y = 0.3, .origin = {x0, -0.5 * (rows - 1) * 0.3, 0.0}, .base_depth = 0.5});
}

// A bumpy sheet over x0 ... x0 + 2 m, |y| <= 1.5 m, on jittered vertices,
// its cells split along either diagonal at random; the last row's
// triangles repeat their vertices (as STL files do) and one triangle is
// degenerate (skipped, counted).
TriangleMesh bumpySheet(double x0, std::uint32_t seed) {
  std::mt19937 gen(seed);
  constexpr int kCols = 11, kRows = 13;
  TriangleMesh m;
  m.name = "sheet";
  for (int r = 0; r < kRows; ++r) {
    for (int c = 0; c < kCols; ++c) {
      const bool edge = c == 0 || r == 0 || r == kRows - 1;  // c == 0 meets field B's edge
      const double x = x0 + 0.2 * c + (edge ? 0.0 : uniform(gen, -0.05, 0.05));
      const double y = -1.5 + 0.25 * r + (edge ? 0.0 : uniform(gen, -0.06, 0.06));
      m.vertices.emplace_back(x, y, c == 0 ? 0.0 : uniform(gen, -0.03, 0.03));
    }
  }
  for (int r = 0; r + 1 < kRows; ++r) {
    for (int c = 0; c + 1 < kCols; ++c) {
      const std::int32_t v00 = r * kCols + c, v01 = v00 + 1, v10 = v00 + kCols, v11 = v10 + 1;
      std::array<std::array<std::int32_t, 3>, 2> two = {{{v00, v01, v11}, {v00, v11, v10}}};
      if (gen() % 2 == 0) two = {{{v00, v01, v10}, {v01, v11, v10}}};
      for (auto t : two) {
        if (r == kRows - 2) {  // STL style: own copies of the same positions
          for (std::int32_t& i : t) {
            m.vertices.push_back(m.vertices[i]);
            i = static_cast<std::int32_t>(m.vertices.size() - 1);
          }
        }
        m.triangles.push_back(t);
      }
    }
  }
  m.triangles.push_back({0, 1, 1});  // degenerate
  return m;
}

// A closed box wound inside-out (flipped before extrusion), as a rock.
TriangleMesh insideOutRock(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  TriangleMesh m;
  m.name = "rock";
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
  // Outward quads (counter-clockwise from outside), then each reversed.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[2], q[1]});
    m.triangles.push_back({q[0], q[3], q[2]});
  }
  return m;
}

// Field A's holes: three cells in the wheel's way (row 5, where y = 0),
// a corner, and a run along a row.
constexpr std::array<std::array<int, 2>, 10> kFieldAHoles = {
    {{5, 4}, {5, 5}, {6, 5}, {0, 0}, {10, 18}, {2, 7}, {2, 8}, {2, 9}, {2, 10}, {2, 11}}};

std::vector<std::uint8_t> fieldAHoles() {
  std::vector<std::uint8_t> holes(11 * 19, 0);
  for (const auto& [r, c] : kFieldAHoles) holes[r * 19 + c] = 1;
  return holes;
}

// Stored box, field A (materials per cell, holes), a ledge, field B, a rock, a
// mesh sheet and a mesh rock on it: ids interleave.
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
  a.cell_holes = fieldAHoles();
  add(a, gravel);
  b.addPiece(ConvexPolyhedron::box({2.75, -1.5, -0.2}, {3.0, 1.5, 0.12}), asphalt);  // a ledge between the fields
  add(field(12, 16, 3.0, 2), asphalt);
  b.addPiece(ConvexPolyhedron::box({5.0, -0.2, 0.0}, {5.3, 0.2, 0.08}), gravel);  // a rock on field B
  const MeshExtrusionOptions options{.thickness = 0.3, .compact = compact};
  const MeshBuildReport sheet = addTriangleMesh(b, bumpySheet(6.75, 3), gravel, options);
  EXPECT_EQ(sheet.degenerate_skipped, 1);
  const MeshBuildReport rock = addTriangleMesh(b, insideOutRock({7.6, -0.3, -0.05}, {7.9, 0.25, 0.07}), asphalt,
                                               {.thickness = 0.05, .compact = compact});
  EXPECT_EQ(rock.flipped_parts, 1);
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
      ConvexPolyhedron into = ConvexPolyhedron::box({0, 0, 0}, {1, 1, 1});  // a box's buffers, reused
      compact.formPiece(id, into);
      for (int v = 0; v < p.vertexCount(); ++v) EXPECT_EQ(into.vertex(v), stored.piece(id).vertex(v));
      for (int f = 0; f < p.faceCount(); ++f) EXPECT_EQ(into.faceOffset(f), stored.piece(id).faceOffset(f));
    } else {
      EXPECT_EQ(&compact.piece(id), &compact.piece(id, scratch));  // stored: itself, no copy
    }
  }
  EXPECT_EQ(formed, static_cast<int>(stored.pieceCount()) - 3);
  ConvexPolyhedron into = ConvexPolyhedron::box({0, 0, 0}, {1, 1, 1});
  for (const PieceId id : {PieceId{0}, PieceId{-1}, static_cast<PieceId>(stored.pieceCount())}) {
    EXPECT_THROW(compact.formPiece(id, into), InvalidInputError) << id;  // stored, or no piece
  }
  // All in, indexes counted (the compact meshes keep one each).
  EXPECT_LT((compact.pieceMemoryBytes() + compact.indexMemoryBytes()) * 30,
            stored.pieceMemoryBytes() + stored.indexMemoryBytes());
}

// Case: what an engine plugin walks: the stored pieces by their ids
// (storedId), and each compact field by its id range and samples
// (compactField); pieceUnder names the triangle under a point, clamped
// onto the grid, and none over a hole.
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
  EXPECT_EQ(last, compact.compactField(2).first - 1);  // the rock on field B, before the meshes
  ASSERT_EQ(compact.compactFieldCount(), 4u);
  EXPECT_EQ(compact.compactField(0).first, 1);  // after the box
  const int field_a_pieces = 2 * (11 * 19 - static_cast<int>(kFieldAHoles.size()));
  EXPECT_EQ(compact.compactField(0).count, field_a_pieces);
  EXPECT_EQ(compact.compactField(1).first, 1 + field_a_pieces + 1);  // after the ledge
  EXPECT_EQ(compact.compactField(1).material, compact.materialId(compact.compactField(1).first));
  EXPECT_THROW(compact.compactField(4), std::out_of_range);
  std::mt19937 gen(3);
  std::optional<ConvexPolyhedron> scratch;
  int over_holes = 0;
  for (std::size_t k = 0; k < 2; ++k) {
    const Terrain::CompactField field = compact.compactField(k);
    ASSERT_NE(field.field, nullptr);
    EXPECT_EQ(field.mesh, nullptr);
    const Heightfield& f = *field.field;
    const PieceRange range{field.first, field.count};
    for (int i = 0; i < 500; ++i) {
      // Some points off the grid: they belong to the nearest edge's triangle.
      const Eigen::Vector2d p = testing::randomPointOn(f, gen, -0.2);
      const std::optional<PieceId> under = pieceUnder(range, f, p.x(), p.y());
      const double x = std::clamp(p.x(), f.origin.x(), f.origin.x() + (f.cols - 1) * f.spacing_x);
      const double y = std::clamp(p.y(), f.origin.y(), f.origin.y() + (f.rows - 1) * f.spacing_y);
      if (!under) {  // over a hole: no surface either
        EXPECT_FALSE(surfaceHeight(f, x, y).has_value());
        ++over_holes;
        continue;
      }
      const PieceId id = *under;
      ASSERT_GE(id, field.first);
      ASSERT_LT(id, field.first + field.count);
      const Eigen::Vector3d on_top(x, y, *surfaceHeight(f, x, y));
      EXPECT_LE(testing::outside(compact.piece(id, scratch), on_top), 1e-12) << "field " << k << ", piece " << id;
    }
  }
  // Field A's 10 holes are 2.4 % of its area: about 12 of its 500 points.
  EXPECT_GT(over_holes, 3);
}

// Case: a compact mesh as a plugin sees it: piece first + k is triangle k
// (wound outward) over its prism, each position once.
TEST(CompactTerrainTest, TellsThePluginsItsMeshes) {
  const Terrain compact = mixed(true);
  std::optional<ConvexPolyhedron> scratch;
  const std::size_t expected_vertices[2] = {11 * 13, 8};  // the sheet's copies welded away
  for (std::size_t k = 2; k < 4; ++k) {
    const Terrain::CompactField part = compact.compactField(k);
    EXPECT_EQ(part.field, nullptr);
    ASSERT_NE(part.mesh, nullptr);
    EXPECT_EQ(part.count, static_cast<PieceId>(part.mesh->triangles.size()));
    EXPECT_EQ(part.mesh->vertices.size(), expected_vertices[k - 2]);
    EXPECT_EQ(part.thickness, k == 2 ? 0.3 : 0.05);
    for (PieceId i = 0; i < part.count; ++i) {
      const auto& t = part.mesh->triangles[i];
      const Eigen::Vector3d& a = part.mesh->vertices[t[0]];
      const Eigen::Vector3d& b = part.mesh->vertices[t[1]];
      const Eigen::Vector3d& c = part.mesh->vertices[t[2]];
      const ConvexPolyhedron& p = compact.piece(part.first + i, scratch);
      const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
      for (const Eigen::Vector3d& v : {a, b, c}) {
        EXPECT_LE(testing::outside(p, v), 1e-12);
        // Outward: the corner is on the prism's top, nothing above it.
        EXPECT_GT(testing::outside(p, v + 1e-3 * n), 0.5e-3);
      }
    }
  }
}

TEST(CompactTerrainTest, FindsTheSameCandidatesForAnyBox) {
  const Terrain stored = mixed(false), compact = mixed(true);
  std::mt19937 gen(5);
  std::vector<PieceId> a, b;
  for (int trial = 0; trial < 3000; ++trial) {
    const Eigen::Vector3d c(uniform(gen, -21, 9.5), uniform(gen, -3, 3), uniform(gen, -0.7, 0.4));
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

// Terrain::within (the wheel's search since issue 53) against its
// definition, read off every piece: the boxes that meet the ball's cube and
// lie within the reach (so that the wheel's candidates stay the ones it
// had, the cube's, less those its first test turned away), on stored
// pieces (the index walked by the ball) and on compact fields and meshes
// (their own disc of cells, their default). Half the balls are placed to
// graze a piece's box: at exactly the reach, and one ulp beyond it.
TEST(CompactTerrainTest, FindsThePiecesWithinAReachAsTheirBoxesDecide) {
  const Terrain stored = mixed(false), compact = mixed(true);
  std::mt19937 gen(11);
  std::vector<PieceId> got, expected;
  int grazes = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Eigen::Vector3d c(uniform(gen, -21, 9.5), uniform(gen, -3, 3), uniform(gen, -0.7, 0.4));
    double reach = uniform(gen, 0.01, 0.6);
    const auto id = static_cast<PieceId>(uniform(gen, 0, static_cast<double>(stored.pieceCount() - 1)));
    const bool graze = trial % 2 == 1;
    if (graze) {  // straight above the piece's box, the reach its distance or one ulp less
      const Aabb box = stored.pieceBounds(id);
      c = Eigen::Vector3d(box.center().x(), box.center().y(), box.max.z() + reach);
      reach = c.z() - box.max.z();
      if (trial % 4 == 3) reach = std::nextafter(reach, 0.0);
    }
    for (const Terrain* terrain : {&stored, &compact}) {
      got.clear();
      expected.clear();
      terrain->within(c, reach, got);
      const Aabb cube{c.array() - reach, c.array() + reach};
      for (PieceId k = 0; k < static_cast<PieceId>(terrain->pieceCount()); ++k) {
        const Aabb box = terrain->pieceBounds(k);
        if (box.overlaps(cube) && box.squaredDistance(c) <= reach * reach) expected.push_back(k);
      }
      std::sort(got.begin(), got.end());
      ASSERT_EQ(got, expected) << "trial " << trial << (terrain == &compact ? ", compact" : ", stored");
      if (graze && terrain == &compact) grazes += std::count(got.begin(), got.end(), id) == (trial % 4 == 1);
    }
  }
  EXPECT_GT(grazes, 1000);  // most grazing balls did decide their piece at the edge
}

// Case: boxes that touch a mesh piece's box exactly at one face, or miss it
// by one double ulp: below the single-precision boxes' resolution, where
// only the exact box decides.
TEST(CompactTerrainTest, DecidesBoxesGrazingAMeshPieceAsItsExactBox) {
  const Terrain stored = mixed(false), compact = mixed(true);
  std::vector<PieceId> a, b;
  int grazes = 0;
  for (std::size_t part = 2; part < 4; ++part) {
    const Terrain::CompactField mesh = compact.compactField(part);
    for (PieceId id = mesh.first; id < mesh.first + mesh.count; id += 3) {
      const Aabb piece = stored.piece(id).bounds();
      for (int axis = 0; axis < 3; ++axis) {
        for (const bool miss : {false, true}) {
          Aabb box{piece.center().array() - 0.01, piece.center().array() + 0.01};
          box.min[axis] = miss ? std::nextafter(piece.max[axis], 1e300) : piece.max[axis];
          box.max[axis] = box.min[axis] + 0.01;
          a.clear();
          b.clear();
          stored.overlapping(box, a);
          compact.overlapping(box, b);
          std::sort(a.begin(), a.end());
          std::sort(b.begin(), b.end());
          ASSERT_EQ(b, a) << "piece " << id << ", axis " << axis << (miss ? ", one ulp beyond" : ", touching");
          grazes += std::count(a.begin(), a.end(), id) == (miss ? 0 : 1);
        }
      }
    }
  }
  EXPECT_GT(grazes, 300);  // each box did graze its piece as meant
}

TEST(CompactTerrainTest, AWheelDrivenOverItMeetsTheSameContactsBitForBit) {
  const Terrain stored = mixed(false), compact = mixed(true);
  const WheelGeometry wheel{.free_radius = 0.19, .tread_width = 0.12};
  WheelContactFinder on_stored, on_compact;
  ContactOptions per_prism;  // a field's surface as prisms, as a stored field is met
  per_prism.field_surface = false;
  std::size_t contacts = 0, seams = 0, on_meshes = 0, over_hole = 0;
  const PieceId first_mesh_piece = compact.compactField(2).first;
  // Across field A and its hole, up the ledge's face, over field B, the rock, the mesh
  // sheet and the mesh rock: 1 mm steps, the centre bobbing so that it
  // sinks 0-30 mm into the relief.
  for (int k = 0; k < 10700; ++k) {
    const double x = -1.8 + 0.001 * k;
    const WheelPose pose{.center = {x, 0.1 * std::sin(0.7 * x), 0.19 - 0.015 * (1.0 + std::sin(9.0 * x))},
                         .axle = {0.05, 1.0, 0.02}};
    const auto a = on_stored.find(stored, wheel, pose);
    const auto b = on_compact.find(compact, wheel, pose, per_prism);
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
      on_meshes += a[i].piece >= first_mesh_piece;
    }
    contacts += a.size();
    over_hole += a.empty() && x > -0.9 && x < -0.6;
    if (::testing::Test::HasFailure()) FAIL() << "step " << k;
  }
  EXPECT_GT(contacts, 8000u);   // on the ground most of the way
  EXPECT_GT(seams, 0u);         // and the seam rule had creases to share
  EXPECT_GT(on_meshes, 1500u);  // the sheet and the rock carried it for their 2 m
  EXPECT_GT(over_hole, 200u);   // and it met nothing over field A's 0.5 m hole
}

// The contact finder forms a compact piece only where formedPieceBeyond
// cannot put it beyond the reach. Sound: wherever it does, queryPoint on
// the stored piece says kBeyond and leaves the cache as it was (so the
// finder's caches stay the stored terrain's). Useful: a piece whose plane
// bound clears the reach by a micrometre is always put beyond, and the
// planes do put some beyond that the box does not. Near the origin (the
// mixed terrain) and 5 km from it (a compact field alone).
void expectBeyondOnlyWhereQueryPointIs(const Terrain& stored, const Terrain& compact, const Aabb& over,
                                       std::uint32_t seed) {
  std::mt19937 gen(seed);
  std::vector<PieceId> near;
  int beyond = 0, by_planes = 0, within = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const Eigen::Vector3d p(uniform(gen, over.min.x(), over.max.x()), uniform(gen, over.min.y(), over.max.y()),
                            uniform(gen, over.min.z(), over.max.z()));
    const double reach = uniform(gen, 0.02, 0.4);
    near.clear();
    stored.overlapping({p.array() - reach, p.array() + reach}, near);
    for (const PieceId id : near) {
      const bool skipped = compact.formedPieceBeyond(id, p, reach);
      if (!compact.isFormed(id)) {
        EXPECT_FALSE(skipped) << "stored piece " << id;
        continue;
      }
      const ConvexPolyhedron& piece = stored.piece(id);
      QueryCache cache{.count = 2, .vertex = {1, 4, 0}};
      const PointQuery q = queryPoint(piece, p, {.max_distance = reach}, cache);
      const bool box_beyond = piece.bounds().squaredDistance(p) > reach * reach;
      if (skipped) {
        ++beyond;
        by_planes += !box_beyond;
        EXPECT_EQ(q.status, QueryStatus::kBeyond) << "piece " << id << ", trial " << trial;
        EXPECT_EQ(cache.count, 2) << "piece " << id << ", trial " << trial;
        EXPECT_EQ(cache.vertex[0], 1);
        EXPECT_EQ(cache.vertex[1], 4);
      } else {
        ++within;
        EXPECT_FALSE(box_beyond) << "piece " << id << ", trial " << trial;
        EXPECT_LE(piece.planeBound(p), reach + 1e-6) << "piece " << id << ", trial " << trial;
      }
      if (::testing::Test::HasFailure()) return;
    }
  }
  EXPECT_GT(by_planes, 500);  // the planes skip pieces the box keeps
  EXPECT_GT(within, 2000);    // and many are left to form
  EXPECT_GT(beyond, by_planes);
}

TEST(CompactTerrainTest, FormsOnlyPiecesThatMayBeWithinReach) {
  expectBeyondOnlyWhereQueryPointIs(mixed(false), mixed(true), {{-2.5, -2.0, -0.4}, {9.0, 2.0, 0.5}}, 7);
  const Heightfield far = testing::randomHeightfield(
      30, 30, 0.05, 9, {.spacing_x = 0.5, .spacing_y = 0.5, .origin = {4000.0, -3000.0, 120.0}, .base_depth = 1.0});
  TerrainBuilder stored, compact;
  addHeightfield(stored, far, stored.addMaterial({}));
  addCompactHeightfield(compact, far, compact.addMaterial({}));
  expectBeyondOnlyWhereQueryPointIs(std::move(stored).build(), std::move(compact).build(),
                                    {{4000.0, -3000.0, 119.8}, {4014.5, -2985.5, 120.6}}, 8);
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
