#include "wtc/io/terrain_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "temp_dir.hpp"
#include "wtc/base/error.hpp"
#include "wtc/terrain/heightfield.hpp"
#include "wtc/terrain/soil.hpp"
#include "wtc/geometry/point_query.hpp"
#include "wtc/terrain/terrain_primitives.hpp"

namespace wtc::io {
namespace terrain_file_test {

using ::testing::AllOf;
using testing::errorOf;
using ::testing::HasSubstr;
using testing::sourceDir;

// Coordinates in the files are short decimals; rotations by degrees round
// to ~1e-16 relative.
constexpr double kTolerance = 1e-12;

class TerrainFileTest : public testing::TempDirTest {
 protected:
  // The message of loading `yaml` written as dir/name.
  std::string loadError(const std::string& yaml, const std::string& name = "terrain.yaml") {
    const auto path = write(name, yaml);
    return errorOf([&] { loadTerrain(path); });
  }
  std::string at(int line, int column, const std::string& name = "terrain.yaml") const {
    return (dir() / name).string() + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
  }
};

const char* const kMaterials = "materials:\n  ground: {mu_max: 0.7}\n";

TEST_F(TerrainFileTest, EveryShippedTerrainLoads) {
  std::vector<std::filesystem::path> files;
  for (const auto& dir : {sourceDir() / "terrains", sourceDir() / "terrains" / "samples"}) {
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      if (entry.path().extension() == ".yaml") files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 3u);
  for (const auto& path : files) {
    SCOPED_TRACE(path.string());
    EXPECT_NO_THROW({
      const Terrain terrain = loadTerrain(path);
      EXPECT_GT(terrain.pieceCount(), 0u);
    });
  }
}

TEST_F(TerrainFileTest, LedgeIsTheSpecLedgeOfAsphaltConcrete) {
  const Terrain terrain = loadTerrain(sourceDir() / "terrains" / "ledge.yaml");
  ASSERT_EQ(terrain.pieceCount(), 2u);
  const Material& asphalt = terrain.material(1);
  EXPECT_EQ(asphalt.name, "asphalt_concrete");
  EXPECT_EQ(asphalt.mu_max, 0.8);
  EXPECT_EQ(asphalt.rolling_resistance, 0.018);
  EXPECT_EQ(asphalt.s1, 0.1);
  EXPECT_EQ(asphalt.s2, 0.0);
  // The step: vertical face at x = 0, 0.65 m high, 4 m of approach and top.
  EXPECT_EQ(terrain.piece(1).bounds().max.z(), 0.65);
  EXPECT_EQ(terrain.piece(1).bounds().min.x(), 0.0);
  EXPECT_EQ(terrain.piece(0).bounds().min.x(), -4.0);
  EXPECT_EQ(terrain.piece(1).bounds().max.x(), 4.0);
  EXPECT_NEAR(queryPoint(terrain.piece(1), {-0.19, 0.0, 0.3}).signed_distance, 0.19, kTolerance);
}

TEST_F(TerrainFileTest, RoughGroundIsAThirtyMetreHeightfieldWithRocks) {
  TerrainBuilder builder;
  const TerrainFileReport report = addTerrainFile(builder, sourceDir() / "terrains" / "rough_ground.yaml");
  EXPECT_EQ(report.materials, 2);
  EXPECT_EQ(report.pieces.count, 2 * 60 * 60 + 4 + 2);  // prisms, boxes, two convex rocks
  const Terrain terrain = std::move(builder).build();
  EXPECT_NEAR(terrain.bounds().min.x(), -15.0, kTolerance);
  EXPECT_NEAR(terrain.bounds().max.y(), 15.0, kTolerance);
  EXPECT_LT(terrain.bounds().max.z(), 0.15);  // bumps and rocks of a few cm
  EXPECT_EQ(terrain.material(0).name, "compacted_soil");
  EXPECT_EQ(terrain.material(static_cast<PieceId>(terrain.pieceCount() - 1)).name, "rock");
}

TEST_F(TerrainFileTest, AllPieceTypesSampleHasTheDocumentedCounts) {
  TerrainBuilder builder;
  const TerrainFileReport report = addTerrainFile(builder, sourceDir() / "terrains" / "samples" / "all_pieces.yaml");
  EXPECT_EQ(report.pieces.count, 1 + 6 + 2 + 3 + 4 + 8 + 24 + 70 + 6 + 1 + 1);
  EXPECT_EQ(report.degenerate_triangles_skipped, 0);
}

TEST_F(TerrainFileTest, PlacementMatchesTheBuilderCall) {
  const auto path =
      write("box.yaml", std::string(kMaterials) +
                            "pieces:\n"
                            "  - type: box\n"
                            "    size: [1, 2, 0.5]\n"
                            "    translation: [3, -1, 0.25]\n"
                            "    rotation: [{axis: [1, 0, 0], degrees: 30}, {axis: [0, 0, 2], radians: 0.5}]\n");
  const Terrain from_file = loadTerrain(path);
  TerrainBuilder builder;
  BoxParams box;
  box.size = {1, 2, 0.5};
  box.pose_WL = Eigen::Translation3d(3, -1, 0.25) * Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(std::numbers::pi / 6, Eigen::Vector3d::UnitX());
  addBox(builder, box, builder.addMaterial({}));
  const Terrain direct = std::move(builder).build();
  EXPECT_LT((from_file.piece(0).bounds().min - direct.piece(0).bounds().min).norm(), kTolerance);
  EXPECT_LT((from_file.piece(0).bounds().max - direct.piece(0).bounds().max).norm(), kTolerance);
}

TEST_F(TerrainFileTest, InlineHeightsAreAMapWithTheNorthRowFirst) {
  const auto path = write("hf.yaml", std::string(kMaterials) +
                                         "pieces:\n"
                                         "  - type: heightfield\n"
                                         "    spacing: [1, 2]\n"
                                         "    translation: [10, 20, 1]\n"
                                         "    heights: [[0.5, 0.6], [0.0, 0.1]]\n");
  const Terrain terrain = loadTerrain(path);
  ASSERT_EQ(terrain.pieceCount(), 2u);
  // The first row [0.5, 0.6] is the north edge y = 22, the second the south
  // edge y = 20; heights are added to the translation's z = 1.
  EXPECT_NEAR(terrain.bounds().max.z(), 1.6, kTolerance);
  const Eigen::Vector3d corners[] = {{10, 22, 1.5}, {11, 22, 1.6}, {10, 20, 1.0}, {11, 20, 1.1}};
  for (const auto& corner : corners) {
    const double d = std::min(queryPoint(terrain.piece(0), corner).signed_distance,
                              queryPoint(terrain.piece(1), corner).signed_distance);
    EXPECT_NEAR(d, 0.0, kTolerance) << formatVector(corner);
  }
}

// The terrains of a file with a box and then a compact part (`compact`)
// or the same part stored: the box stored in both, and every later piece
// formed, with the stored one's box and planes.
void expectTheStoredPiecesAfterTheBox(const Terrain& stored, const Terrain& compact) {
  ASSERT_EQ(compact.pieceCount(), stored.pieceCount());
  std::optional<ConvexPolyhedron> scratch;
  for (PieceId id = 0; id < static_cast<PieceId>(stored.pieceCount()); ++id) {
    EXPECT_EQ(compact.isFormed(id), id > 0);
    const ConvexPolyhedron& p = compact.piece(id, scratch);
    EXPECT_EQ(p.bounds().min, stored.piece(id).bounds().min);
    EXPECT_EQ(p.bounds().max, stored.piece(id).bounds().max);
    EXPECT_EQ(p.faceOffset(0), stored.piece(id).faceOffset(0));
  }
}

// storage: compact keeps the samples and forms the same prisms: the same
// pieces, ids and boxes as the default storage, in a fraction of the memory.
TEST_F(TerrainFileTest, ACompactHeightfieldHasTheStoredOnesPieces) {
  const std::string field = std::string(kMaterials) +
                            "pieces:\n"
                            "  - {type: box, size: [1, 1, 1], translation: [-5, 0, 0]}\n"
                            "  - type: heightfield\n"
                            "    spacing: 0.5\n"
                            "    heights: [[0.5, 0.6, 0.4], [0.0, 0.1, 0.2], [0.3, 0.0, 0.1]]\n";
  const Terrain stored = loadTerrain(write("stored.yaml", field));
  const Terrain compact = loadTerrain(write("compact.yaml", field + "    storage: compact\n"));
  ASSERT_EQ(compact.pieceCount(), stored.pieceCount());
  expectTheStoredPiecesAfterTheBox(stored, compact);
  EXPECT_THAT(loadError(field + "    storage: packed\n"),
              HasSubstr(at(8, 14) + "pieces[1] (heightfield): storage: 'packed' (expected prisms or compact)"));
}

// A ledge sampled into a heightfield takes the same key (its engines' bodies
// then meet the engines' own heightfield shapes); a ledge of boxes refuses
// it, at its line.
TEST_F(TerrainFileTest, ASampledLedgeTakesCompactStorage) {
  const std::string ledge = std::string(kMaterials) +
                            "pieces:\n"
                            "  - {type: box, size: [1, 1, 1], translation: [-5, 0, 0]}\n"
                            "  - {type: ledge, height: 0.3, approach_length: 1, top_length: 0.5, width: 1,\n"
                            "     heightfield_spacing: 0.1";
  const Terrain stored = loadTerrain(write("stored.yaml", ledge + "}\n"));
  const Terrain compact = loadTerrain(write("compact.yaml", ledge + ", storage: compact}\n"));
  ASSERT_EQ(compact.pieceCount(), stored.pieceCount());
  ASSERT_EQ(compact.pieceCount(), 1u + 2u * 15u * 10u);
  ASSERT_EQ(compact.compactFieldCount(), 1u);
  EXPECT_NE(compact.compactField(0).field, nullptr);
  expectTheStoredPiecesAfterTheBox(stored, compact);
  EXPECT_THAT(loadError(std::string(kMaterials) + "pieces:\n  - {type: ledge, height: 0.3, storage: compact}\n"),
              HasSubstr("storage: compact needs heightfield_spacing > 0"));
}

// A mesh takes the same storage key: its prisms formed from its vertices
// and triangles, the same pieces as stored.
TEST_F(TerrainFileTest, ACompactMeshHasTheStoredOnesPieces) {
  write("hill.obj", "v 0 0 0\nv 1 0 0.1\nv 1 1 0.3\nv 0 1 0.2\nv 2 0.5 0\nf 1 2 3\nf 1 3 4\nf 2 5 3\n");
  const std::string mesh = std::string(kMaterials) +
                           "pieces:\n"
                           "  - {type: box, size: [1, 1, 1], translation: [-5, 0, 0]}\n"
                           "  - type: mesh\n"
                           "    file: hill.obj\n"
                           "    thickness: 0.2\n";
  const Terrain stored = loadTerrain(write("stored.yaml", mesh));
  const Terrain compact = loadTerrain(write("compact.yaml", mesh + "    storage: compact\n"));
  ASSERT_EQ(compact.pieceCount(), 4u);
  ASSERT_EQ(compact.pieceCount(), stored.pieceCount());
  ASSERT_EQ(compact.compactFieldCount(), 1u);
  EXPECT_NE(compact.compactField(0).mesh, nullptr);
  expectTheStoredPiecesAfterTheBox(stored, compact);
  EXPECT_THAT(loadError(mesh + "    storage: [compact]\n"),
              HasSubstr(at(8, 14) + "pieces[1] (mesh): storage: expected a string"));
}

// cell_materials: one material name per cell, north row first as the
// heights; the piece needs no 'material' then. Bad rows and names are
// named at their line.
TEST_F(TerrainFileTest, AHeightfieldTakesAMaterialPerCell) {
  const std::string two = "materials:\n  asphalt: {mu_max: 0.9}\n  gravel: {mu_max: 0.6}\n";
  const std::string field = two +
                            "pieces:\n"
                            "  - type: heightfield\n"
                            "    spacing: 0.5\n"
                            "    heights: [[0.5, 0.6, 0.4], [0.0, 0.1, 0.2], [0.3, 0.0, 0.1]]\n";
  for (const std::string storage : {"prisms", "compact"}) {
    const Terrain terrain =
        loadTerrain(write(storage + ".yaml", field + "    storage: " + storage +
                                                 "\n    cell_materials: [[gravel, asphalt], [asphalt, asphalt]]\n"));
    // The first row of cells is the north one (y in [0.5, 1]): cell (1, 0) is gravel.
    const PieceRange range{0, 8};
    Heightfield grid;
    grid.rows = grid.cols = 3;
    for (int r = 0; r < 2; ++r) {
      for (int c = 0; c < 2; ++c) {
        for (int k = 0; k < 2; ++k) {
          EXPECT_EQ(terrain.material(*cellPiece(range, grid, r, c, k)).mu_max, r == 1 && c == 0 ? 0.6 : 0.9)
              << storage << " cell (" << r << ", " << c << ")";
        }
      }
    }
  }
  EXPECT_THAT(loadError(field + "    cell_materials: [[gravel, asphalt]]\n"),
              HasSubstr(at(8, 21) + "pieces[0] (heightfield): cell_materials: expected 2 rows"));
  EXPECT_THAT(loadError(field + "    cell_materials: [[gravel, asphalt], [asphalt, sand]]\n"),
              HasSubstr(at(8, 51) + "pieces[0] (heightfield): cell_materials[1][1]: unknown material 'sand'"));
  EXPECT_THAT(loadError(field), HasSubstr("missing key 'material'"));
}

// holes: 1 for a hole, 0 for ground, per cell, north row first; the hole
// cell has no pieces, prisms or compact. Bad rows and entries are named
// at their line, a field of holes only as the validation names it.
TEST_F(TerrainFileTest, AHeightfieldTakesHoles) {
  const std::string field = std::string(kMaterials) +
                            "pieces:\n"
                            "  - type: heightfield\n"
                            "    material: ground\n"
                            "    spacing: 0.5\n"
                            "    heights: [[0.5, 0.6, 0.4], [0.0, 0.1, 0.2], [0.3, 0.0, 0.1]]\n";
  for (const std::string storage : {"prisms", "compact"}) {
    const Terrain terrain =
        loadTerrain(write(storage + ".yaml", field + "    storage: " + storage + "\n    holes: [[0, 0], [1, 0]]\n"));
    // The first row of cells is the north one: cell (0, 0) is the hole.
    EXPECT_EQ(terrain.pieceCount(), 6u) << storage;
    const Eigen::Vector3d above_hole(0.25, 0.25, 2.0), above_ground(0.75, 0.25, 2.0);
    std::vector<PieceId> found;
    terrain.overlapping({above_hole - Eigen::Vector3d(0.1, 0.1, 5.0), above_hole + Eigen::Vector3d(0.1, 0.1, 0)},
                        found);
    EXPECT_TRUE(found.empty()) << storage;
    terrain.overlapping({above_ground - Eigen::Vector3d(0.1, 0.1, 5.0), above_ground + Eigen::Vector3d(0.1, 0.1, 0)},
                        found);
    EXPECT_EQ(found.size(), 2u) << storage;
  }
  EXPECT_THAT(loadError(field + "    holes: [[0, 0]]\n"),
              HasSubstr(at(8, 12) + "pieces[0] (heightfield): holes: expected 2 rows"));
  EXPECT_THAT(loadError(field + "    holes: [[0, 0], [2, 0]]\n"),
              HasSubstr(at(8, 22) + "pieces[0] (heightfield): holes[1][0] = 2 (expected 0, ground, or 1, a hole)"));
  EXPECT_THAT(loadError(field + "    holes: [[1, 1], [1, 1]]\n"),
              HasSubstr("pieces[0] (heightfield): wtc::Heightfield: every one of the 4 cells is a hole"));
}

TEST_F(TerrainFileTest, ErrorsNameTheFileLineAndColumn) {
  // Case: YAML syntax.
  EXPECT_THAT(loadError(std::string(kMaterials) + "pieces:\n  - {type: box, size: [1, 2\n"),
              AllOf(HasSubstr((dir() / "terrain.yaml").string() + ":"), HasSubstr("YAML syntax error")));
  // Case: a misspelt key, at the key.
  EXPECT_THAT(loadError(std::string(kMaterials) + "pieces:\n  - type: ledge\n    heigth: 0.65\n"),
              HasSubstr(at(5, 5) + "pieces[0] (ledge): unknown key 'heigth'"));
  // Case: a value that is not a number, at the value.
  EXPECT_THAT(loadError(std::string(kMaterials) + "pieces:\n  - type: ledge\n    height: tall\n"),
              HasSubstr(at(5, 13) + "pieces[0] (ledge): height: 'tall' is not a number"));
  // Case: a builder's complaint, at the piece.
  EXPECT_THAT(loadError(std::string(kMaterials) + "pieces:\n  - type: ledge\n    height: -1\n"),
              HasSubstr(at(4, 5) + "pieces[0] (ledge): wtc::addLedge: height = -1 must be finite and >= 0 (m)"));
  EXPECT_THAT(loadError(std::string(kMaterials) + "pieces:\n  - {type: hull, points: [[0, 0, 0], [1, 0, 0]]}\n"),
              HasSubstr(at(4, 5) + "pieces[0] (hull): wtc::ConvexPolyhedron"));
  // Case: names that do not resolve.
  EXPECT_THAT(loadError(std::string(kMaterials) + "pieces:\n  - {type: box, material: grass, size: [1, 1, 1]}\n"),
              HasSubstr(at(4, 27) + "pieces[0] (box): unknown material 'grass'"));
  EXPECT_THAT(loadError(std::string(kMaterials) + "pieces:\n  - {type: cylinder}\n"),
              HasSubstr(at(4, 12) + "pieces[0] (cylinder): unknown piece type 'cylinder'"));
  EXPECT_THAT(loadError("materials:\n  a: {}\n  b: {}\npieces:\n  - {type: box, size: [1, 1, 1]}\n"),
              HasSubstr(at(5, 5) + "pieces[0] (box): missing key 'material' (the file defines 2 materials)"));
  // Case: a bad material, at the material.
  EXPECT_THAT(loadError("materials:\n  mud: {mu_max: 0.4, s1: -0.1}\npieces: []\n"),
              HasSubstr(at(2, 8) + "material 'mud': wtc::Material 'mud'"));
  // Case: structure.
  EXPECT_THAT(loadError("pieces: []\n"), HasSubstr(at(1, 1) + "missing key 'materials'"));
  EXPECT_THAT(loadError(std::string(kMaterials) + "pieces:\n  - {type: box, size: [1, 1, 1],\n"
                                                  "     rotation: {axis: [0, 0, 1], degrees: 5, radians: 1}}\n"),
              HasSubstr(at(5, 16) + "pieces[0] (box): rotation: give exactly one of 'degrees' and 'radians'"));
  EXPECT_THAT(loadError(std::string(kMaterials) + "pieces: []\n"), HasSubstr("the terrain has no pieces"));
  EXPECT_THAT(errorOf([&] { loadTerrain(dir() / "nowhere.yaml"); }),
              HasSubstr((dir() / "nowhere.yaml").string() + ": file not found"));
}

TEST_F(TerrainFileTest, ErrorsInReferencedFilesNameBothFiles) {
  // Case: a CSV with a bad value, referenced relative to the YAML file.
  write("data/ground.csv", "0, 0\n0, x\n");
  EXPECT_THAT(
      loadError(std::string(kMaterials) + "pieces:\n  - {type: heightfield, spacing: 1, file: data/ground.csv}\n"),
      AllOf(HasSubstr(at(4, 43) + "pieces[0] (heightfield): "),
            HasSubstr((dir() / "data" / "ground.csv").string() + ":2:4: 'x' is not a number")));
  // Case: a mesh that is not there, and one that is broken.
  EXPECT_THAT(loadError(std::string(kMaterials) + "pieces:\n  - {type: mesh, file: rock.obj}\n"),
              AllOf(HasSubstr(at(4, 24) + "pieces[0] (mesh): "),
                    HasSubstr((dir() / "rock.obj").string() + ": file not found")));
  write("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\n");
  EXPECT_THAT(loadError(std::string(kMaterials) + "pieces:\n  - {type: mesh, file: flat.obj}\n"),
              AllOf(HasSubstr(at(4, 24)), HasSubstr((dir() / "flat.obj").string() + ": point cloud: 3 vertices")));
}

// Sizes of 1e300 lost the rest of a piece to rounding and surfaced as
// "all vertices coincide"; they are refused with the value and the range.
TEST_F(TerrainFileTest, SizesBeyondThePhysicalRangeAreRefusedWithTheValue) {
  const std::string head = std::string(kMaterials) + "pieces:\n";
  const std::string beyond = " m is beyond the largest length a description may give, 1e+06 m (wtc::kMaxLengthM)";
  EXPECT_THAT(loadError(head + "  - {type: box, size: [1e300, 1, 1]}\n"),
              AllOf(HasSubstr(at(4, 5) + "pieces[0] (box): wtc::addBox: size.x = 1e+300" + beyond),
                    ::testing::Not(HasSubstr("coincide"))));
  EXPECT_THAT(loadError(head + "  - {type: slab, size: [60, 60], thickness: 1e300}\n"),
              HasSubstr("pieces[0] (slab): wtc::addSlab: thickness = 1e+300" + beyond));
  EXPECT_THAT(loadError(head + "  - {type: ledge, height: 1e300}\n"),
              HasSubstr("pieces[0] (ledge): wtc::addLedge: height = 1e+300" + beyond));
  EXPECT_THAT(loadError(head + "  - {type: box, size: [1, 1, 1], translation: [1e300, 0, 0]}\n"),
              HasSubstr("pieces[0] (box): wtc::addBox: pose_WL places it at (1e+300, 0, 0) m, beyond 1e+06 m of the "
                        "origin (wtc::kMaxLengthM)"));
  EXPECT_THAT(loadError(head + "  - {type: heightfield, spacing: 1, heights: [[0, 0], [0, 1e300]]}\n"),
              HasSubstr("pieces[0] (heightfield): wtc::Heightfield: height at (row 0, col 1) = 1e+300" + beyond));
  EXPECT_THAT(loadError(head + "  - {type: heightfield, spacing: 1e300, heights: [[0, 0], [0, 0]]}\n"),
              HasSubstr("wtc::Heightfield: spacing_x = 1e+300" + beyond));
}

// A mesh whose triangles all had zero area added nothing without a word
// (alone, the terrain then had "no pieces"); one with some is warned of.
TEST_F(TerrainFileTest, DegenerateMeshTrianglesAreWarnedOfAndAMeshOfNothingElseIsAnError) {
  // Case: two zero-area triangles (a repeated vertex, three collinear ones).
  const auto flat = write("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 4 4\n");
  EXPECT_THAT(loadError(std::string(kMaterials) + "pieces:\n  - {type: mesh, file: flat.obj}\n"),
              AllOf(HasSubstr(at(4, 24) + "pieces[0] (mesh): " + flat.string() +
                              ": all 2 of its 2 triangles are degenerate (zero area: collinear or repeated vertices), "
                              "so the mesh holds no ground"),
                    ::testing::Not(HasSubstr("no pieces"))));
  // Case: one of three skipped: loaded, and said in the report's warnings.
  write("some.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 3 4\nf 1 2 5\n");
  const auto yaml = write("terrain.yaml", std::string(kMaterials) +
                                              "pieces:\n  - {type: box, size: [1, 1, 1]}\n"
                                              "  - {type: mesh, file: some.obj}\n");
  TerrainBuilder builder;
  const TerrainFileReport report = addTerrainFile(builder, yaml);
  EXPECT_EQ(report.pieces.count, 3);
  EXPECT_EQ(report.degenerate_triangles_skipped, 1);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_EQ(report.warnings[0], at(5, 5) + "pieces[1] (mesh): " + (dir() / "some.obj").string() +
                                    ": 1 of 3 triangles are degenerate (zero area), skipped");
}

}  // namespace terrain_file_test
}  // namespace wtc::io

namespace wtc::io {
namespace terrain_file_test {

// A material's soil: a shipped one by name, a map of its fields over a
// shipped base, and a value out of range refused with the file, line and field.
TEST_F(TerrainFileTest, AMaterialTakesASoilByNameOrByItsFields) {
  const auto path = write("soil.yaml",
                          "materials:\n"
                          "  sand: {soil: toyoura_sand}\n"
                          "  loam: {soil: {base: lete_sand, name: wet_lete, cohesion: 2500, damping: 0}}\n"
                          "pieces:\n"
                          "  - {type: box, material: sand, size: [1, 1, 1]}\n");
  const Terrain terrain = loadTerrain(path);
  ASSERT_EQ(terrain.materials().size(), 2u);
  const Material& sand = terrain.materials()[0].name == "sand" ? terrain.materials()[0] : terrain.materials()[1];
  const Material& loam = terrain.materials()[0].name == "loam" ? terrain.materials()[0] : terrain.materials()[1];
  ASSERT_TRUE(sand.soil && loam.soil);
  EXPECT_EQ(sand.soil->k_phi, namedSoil("toyoura_sand")->k_phi);
  EXPECT_EQ(loam.soil->name, "wet_lete");
  EXPECT_EQ(loam.soil->cohesion, 2500.0);
  EXPECT_EQ(loam.soil->damping, 0.0);
  EXPECT_EQ(loam.soil->k_phi, namedSoil("lete_sand")->k_phi);

  EXPECT_THAT(loadError("materials:\n  sand: {soil: quicksand}\npieces:\n  - {type: box, size: [1, 1, 1]}\n"),
              AllOf(HasSubstr(at(2, 16)), HasSubstr("unknown soil 'quicksand'"), HasSubstr("toyoura_sand")));
  EXPECT_THAT(loadError("materials:\n  sand:\n    soil: {base: dry_sand, friction_angle_deg: -3}\n"
                        "pieces:\n  - {type: box, size: [1, 1, 1]}\n"),
              AllOf(HasSubstr(at(3, 11)), HasSubstr("friction_angle_deg = -3 must be in (0, 90) (deg)")));
  EXPECT_THAT(loadError("materials:\n  sand: {soil: {k_phi: 1e6, bekker: 2}}\npieces:\n  - {type: box, size: [1, 1, 1]}\n"),
              HasSubstr("bekker"));
}

}  // namespace terrain_file_test
}  // namespace wtc::io
