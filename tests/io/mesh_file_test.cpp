// Mesh import through assimp: real files made by other tools (Debian's
// assimp-testmodels), counted against triangle counts read independently
// from the files themselves, and broken files written by the tests.
#include "wtc/io/mesh_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "temp_dir.hpp"
#include "wtc/base/error.hpp"
#include "wtc/geometry/point_query.hpp"
#include "wtc/terrain/terrain.hpp"

namespace wtc::io {
namespace mesh_file_test {

using ::testing::AllOf;
using testing::errorOf;
using ::testing::HasSubstr;
using testing::samplesDir;

// The sample meshes hold decimal coordinates read as floats by assimp
// (relative error 6e-8); 1e-6 m covers them.
constexpr double kTolerance = 1e-6;

const std::filesystem::path kModels = WTC_ASSIMP_MODELS_DIR;

std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Triangle counts straight from the files.
std::int64_t binaryStlTriangles(const std::filesystem::path& path) {
  const std::string bytes = slurp(path);
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);  // little-endian count after the 80-byte header
  return count;
}
std::int64_t countOccurrences(const std::filesystem::path& path, const std::string& word) {
  const std::string text = slurp(path);
  std::int64_t n = 0;
  for (std::size_t pos = text.find(word); pos != std::string::npos; pos = text.find(word, pos + 1)) ++n;
  return n;
}
// OBJ: every "f" line with n vertices is n - 2 triangles.
std::int64_t objTriangles(const std::filesystem::path& path) {
  std::istringstream lines(slurp(path));
  std::int64_t n = 0;
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string tag, vertex;
    words >> tag;
    if (tag != "f") continue;
    int corners = 0;
    while (words >> vertex) ++corners;
    n += corners - 2;
  }
  return n;
}

// Reads `path`, builds it, and checks pieces = triangles - degenerate, with
// the degenerate (exactly zero-area) triangles counted here too.
struct Imported {
  MeshFileContents contents;
  MeshBuildReport report;
};
Imported importAndCheck(const std::filesystem::path& path, const MeshFileOptions& options = {}) {
  Imported out{readMeshFile(path, options), {}};
  std::int64_t zero_area = 0;
  for (const auto& part : out.contents.parts) {
    for (const auto& t : part.triangles) {
      const Eigen::Vector3d& a = part.vertices[t[0]];
      zero_area += (part.vertices[t[1]] - a).cross(part.vertices[t[2]] - a).norm() == 0.0;
    }
  }
  TerrainBuilder builder;
  out.report = addMeshFile(builder, path, builder.addMaterial(Material{}), options);
  EXPECT_EQ(out.report.triangles, out.contents.triangleCount()) << path;
  if (!options.extrusion.keep_convex_parts) {
    EXPECT_EQ(out.report.pieces.count + out.report.degenerate_skipped, out.report.triangles) << path;
    EXPECT_EQ(out.report.degenerate_skipped, zero_area) << path;
  }
  EXPECT_EQ(builder.pieceCount(), static_cast<std::size_t>(out.report.pieces.count)) << path;
  return out;
}

class MeshFileTest : public testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    if (!std::filesystem::is_directory(kModels)) {
      GTEST_SKIP() << kModels << " not found (Debian package assimp-testmodels)";
    }
  }
};

TEST_F(MeshFileTest, BinaryAndTextStlOfOneModelGiveTheSamePieces) {
  const auto binary = kModels / "STL" / "Spider_binary.stl";
  const auto text = kModels / "STL" / "Spider_ascii.stl";
  const Imported b = importAndCheck(binary);
  const Imported t = importAndCheck(text);
  EXPECT_EQ(b.report.triangles, binaryStlTriangles(binary));
  EXPECT_EQ(t.report.triangles, countOccurrences(text, "endfacet"));
  EXPECT_EQ(b.report.triangles, 1368);
  EXPECT_EQ(b.report.pieces.count, t.report.pieces.count);
  EXPECT_GT(b.report.pieces.count, 1300);  // a few zero-area triangles in this model
}

TEST_F(MeshFileTest, ObjPlyAndGltfBoxesGiveTwelvePrismsOrOneConvexPiece) {
  const auto obj = kModels / "OBJ" / "box.obj";
  const auto ply = kModels / "PLY" / "cube.ply";
  const auto ply_binary = kModels / "PLY" / "cube_binary.ply";
  const auto gltf = kModels / "glTF2" / "BoxTextured-glTF" / "BoxTextured.gltf";
  const auto glb = kModels / "glTF2" / "BoxTextured-glTF-Binary" / "BoxTextured.glb";
  EXPECT_EQ(objTriangles(obj), 12);
  for (const auto& path : {obj, ply, ply_binary, gltf, glb}) {
    SCOPED_TRACE(path.string());
    const Imported skins = importAndCheck(path);
    EXPECT_EQ(skins.report.triangles, 12);
    EXPECT_EQ(skins.report.pieces.count, 12);
    MeshFileOptions whole;
    whole.extrusion.keep_convex_parts = true;
    const Imported one = importAndCheck(path, whole);
    EXPECT_EQ(one.report.pieces.count, 1);
    EXPECT_EQ(one.report.convex_parts, 1);
  }
}

TEST_F(MeshFileTest, LargerModelsFromOtherTools) {
  // Case: a 3D-scanned figure (PLY), a sphere with a hole (STL: open, so
  // never one piece), a polygon that assimp must triangulate (OBJ).
  const Imported wuson = importAndCheck(kModels / "PLY" / "Wuson.ply");
  EXPECT_EQ(wuson.report.triangles, 3732);
  const Imported sphere = importAndCheck(kModels / "STL" / "sphereWithHole.stl");
  EXPECT_EQ(sphere.report.triangles, countOccurrences(kModels / "STL" / "sphereWithHole.stl", "endfacet"));
  const auto concave = kModels / "OBJ" / "concave_polygon.obj";
  const Imported polygon = importAndCheck(concave);
  EXPECT_EQ(polygon.report.triangles, objTriangles(concave));
}

TEST_F(MeshFileTest, PointsAndLinesAreIgnoredAndCounted) {
  const Imported mixed = importAndCheck(kModels / "OBJ" / "testmixed.obj");
  EXPECT_EQ(mixed.report.triangles, 12);
  EXPECT_GT(mixed.contents.ignored_points, 0);
  EXPECT_GT(mixed.contents.ignored_lines, 0);
}

TEST_F(MeshFileTest, ScaleAndPosePlaceTheFile) {
  MeshFileOptions options;
  options.scale = 2.0;
  options.pose_WM =
      Eigen::Translation3d(10.0, 0.0, 1.0) * Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ());
  options.extrusion.thickness = 0.2;
  const MeshFileContents contents = readMeshFile(samplesDir() / "ramp.obj", options);
  ASSERT_EQ(contents.parts.size(), 1u);
  // ramp.obj's (6, 1, 0.5359) -> scaled (12, 2, 1.0718) -> rotated (-2, 12, 1.0718) -> moved.
  bool found = false;
  for (const auto& v : contents.parts[0].vertices)
    found |= (v - Eigen::Vector3d(8.0, 12.0, 2.0718)).norm() < kTolerance;
  EXPECT_TRUE(found);
  // Case: the prisms hang 0.2 m below the flat top of the ramp.
  TerrainBuilder builder;
  const MeshBuildReport report = addMeshFile(builder, samplesDir() / "ramp.obj", builder.addMaterial({}), options);
  const Terrain terrain = std::move(builder).build();
  const PieceId top = report.pieces.end() - 1;
  EXPECT_NEAR(queryPoint(terrain.piece(top), {9.0, 9.0, 2.0718 + 0.3}).signed_distance, 0.3, kTolerance);
  EXPECT_NEAR(terrain.piece(top).bounds().min.z(), 2.0718 - 0.2, kTolerance);
}

TEST_F(MeshFileTest, RecordedBadFilesGiveErrorsWithThePath) {
  // Files of the assimp test suite made to fail, and point clouds
  // (invalid/OutOfMemory.off: DeclaredCountsBeyondTheFileSizeAreRefusedBeforeAssimpReads).
  const std::pair<std::filesystem::path, const char*> cases[] = {
      {kModels / "OBJ" / "point_cloud.obj", "point cloud: 3 vertices and no faces"},
      {kModels / "PLY" / "points.ply", "point cloud: 4 vertices and no faces"},
      {kModels / "OBJ" / "testpoints.obj", "no triangles, only 24 points and 0 lines"},
      {kModels / "OBJ" / "testline.obj", "no triangles, only 0 points and 18 lines"},
      {kModels / "invalid" / "empty.obj", "cannot read the mesh file: "},
      {kModels / "invalid" / "malformed.obj", "cannot read the mesh file: OBJ: Invalid face index"},
      {kModels / "glTF2" / "TestNoRootNode" / "SceneWithoutNodes.gltf", "empty scene"},
      {kModels / "glTF2" / "MissingBin" / "BoxTextured.gltf", "BoxTextured0.bin"},
      {kModels / "glTF2" / "BoxWithInfinites-glTF-Binary" / "BoxWithInfinites.glb", "is not finite"},
  };
  for (const auto& [path, expected] : cases) {
    TerrainBuilder builder;
    EXPECT_THAT(errorOf([&] { addMeshFile(builder, path, builder.addMaterial({})); }),
                AllOf(HasSubstr(path.string()), HasSubstr(expected)));
    EXPECT_EQ(builder.pieceCount(), 0u) << path;
  }
}

TEST_F(MeshFileTest, BrokenFilesWrittenHereGiveErrorsWithThePath) {
  const std::string stl = slurp(kModels / "STL" / "Spider_binary.stl");
  const std::string glb = slurp(kModels / "glTF2" / "BoxTextured-glTF-Binary" / "BoxTextured.glb");
  const std::string ply = slurp(kModels / "PLY" / "cube_binary.ply");
  const std::pair<std::filesystem::path, const char*> cases[] = {
      {write("truncated.stl", stl.substr(0, 300)), "cannot read the mesh file: "},
      {write("truncated.glb", glb.substr(0, glb.size() / 2)), "cannot read the mesh file: "},
      {write("truncated.ply", ply.substr(0, 400)), "cannot read the mesh file: "},
      {write("empty.stl", ""), "cannot read the mesh file: "},
      {write("garbage.stl", std::string("\x13\x37 not a mesh at all \x01\xfe", 24)), "cannot read the mesh file: "},
      {write("garbage.obj", "this is\nnot an OBJ file\n"), "empty scene"},
      // assimp 5.2 loops forever on these (found by wtc_fuzz_mesh_ply): refused first.
      {write("no_end_header.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"),
       "PLY header has no end_header line"},
      // wtc_fuzz_mesh_ply (-O1 build): end_header inside a line; assimp 5.2 hung on it.
      {write("end_header_inside_a_line.ply",
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float32 x\nproperty float32 y\nproperty float32 z\n"
             "element face 1 index\npropertyend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
       "PLY header has no end_header line"},
      {write("control_bytes.ply", std::string("ply\nformat ascii 1.0\nelement verte\x03\0\0\0\x03\x07 4\n", 40)),
       "PLY header holds a byte that is not printable ASCII (3)"},
      {write("high_bytes.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float \xff\xff\nend_header\n0\n"),
       "PLY header holds a byte that is not printable ASCII (255)"},
      {write("glued_end.ply",
             "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\x10"
             "5\n"),
       "PLY header: end_header must end its line"},
      {write("bad_number.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0\n"),
       "cannot read the mesh file: "},
      {write("unknown.xyz123", "1 2 3\n"), "cannot read the mesh file: "},
      {dir() / "missing.obj", "file not found"},
      {dir(), "not a regular file (a directory)"},
  };
  for (const auto& [path, expected] : cases) {
    TerrainBuilder builder;
    EXPECT_THAT(errorOf([&] { addMeshFile(builder, path, builder.addMaterial({})); }),
                AllOf(HasSubstr(path.string() + ": "), HasSubstr(expected)));
  }
}

// Headers whose counts cannot fit in the file. Before the check assimp
// allocated for them: ~16 GB for OutOfMemory.off (its OFF reader wraps the
// count to 32 bits), ~6 GB for the 88-byte STL (its size test wraps too).
TEST_F(MeshFileTest, DeclaredCountsBeyondTheFileSizeAreRefusedBeforeAssimpReads) {
  std::string stl(80, ' ');
  const std::uint32_t wrapping_count = 85899346;  // 84 + 50 n = 2^32 + 88, i.e. 88 in 32 bits
  stl.append(reinterpret_cast<const char*>(&wrapping_count), 4);
  stl.append(4, '\0');
  const std::pair<std::filesystem::path, const char*> cases[] = {
      {kModels / "invalid" / "OutOfMemory.off", "OFF header declares 353535235358 vertices and 6 faces"},
      {write("huge.off", "OFF\n# comment\n1000000000 1 0\n0 0 0\n3 0 0 0\n"),
       "OFF header declares 1000000000 vertices and 1 faces"},
      {write("huge_n.off", "nOFF 3\n4 2000000000 0\n"), "OFF header declares 4 vertices and 2000000000 faces"},
      // The count glued to the keyword (found by wtc_fuzz_mesh_off: assimp read
      // it and asked for 43 GB).
      {write("glued.off", "OFF3585235358 6 0\n-0.5 -0.5 0.5\n0.5 -0 0.5\n"),
       "OFF header declares 3585235358 vertices and 6 faces"},
      // No keyword at all: assimp's OFF reader, chosen by the extension, reads
      // the counts from the first line (also found by wtc_fuzz_mesh_off).
      {write("bare.off", "3535235358 6 0\n-0.5 0.5\n"), "OFF header declares 3535235358 vertices and 6 faces"},
      // Keyword letters that do not spell OFF, then the count (wtc_fuzz_mesh_off).
      {write("letters.off", "ST353523355 85\n"), "OFF header declares 353523355 vertices and 85 faces"},
      {write("huge.ply",
             "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\n"
             "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
             "end_header\n"),
       "binary PLY header declares 4000000000 'vertex', 1 'face'"},
      {write("huge_ascii.ply",
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
             "property float z\nelement face 99999999999999999999999\n"
             "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
       "ASCII PLY header declares 3 'vertex', more than 1.8e19 'face'"},
      {write("wrapping.stl", stl), "binary STL header declares 85899346 triangles, which needs at least 4294967384"},
  };
  for (const auto& [path, expected] : cases) {
    TerrainBuilder builder;
    EXPECT_THAT(errorOf([&] { addMeshFile(builder, path, builder.addMaterial({})); }),
                AllOf(HasSubstr(path.string() + ": "), HasSubstr(expected), HasSubstr("but the file has only")));
  }
  // Honest headers of each format still read.
  for (const auto& path :
       {kModels / "OFF" / "Cube.off", kModels / "OFF" / "Wuson.off", kModels / "PLY" / "cube.ply",
        kModels / "PLY" / "cube_binary.ply", kModels / "PLY" / "Wuson.ply", kModels / "STL" / "Spider_binary.stl"}) {
    EXPECT_GT(readMeshFile(path).triangleCount(), 0) << path;
  }
}

// OFF face lines assimp 5.2 trusts: with any of these its reader touched
// memory it does not own (a SEGV under ASan, found by wtc_fuzz_mesh_off;
// the first case is its input, fuzz/corpus/mesh_off/regression-zero-vertex-face.off).
TEST_F(MeshFileTest, OffFacesThatAssimpWouldOverrunAreRefusedByLine) {
  const std::string vertices = "OFF\n3 2\n0.1 0.2 0.3\n0.2 0.3 0.4\n0.3 0.4 0.5\n";
  const std::pair<std::filesystem::path, const char*> cases[] = {
      {write("zero.off", vertices + "0\n0\r20\n4\n"),
       ":6:1: face 0: a face needs a vertex count of at least 1 first on its line"},
      {write("short.off", vertices + "3 0 1 2\n4 0 1\n"), ":7:1: face 1: declares 4 vertices but its line lists 2"},
      {write("range.off", vertices + "3 0 1 2\n3 0 1 3\n"),
       ":7:1: face 1: vertex index 3 is out of range (the file declares 3 vertices)"},
  };
  for (const auto& [path, expected] : cases) {
    EXPECT_THAT(errorOf([&] { readMeshFile(path); }), AllOf(HasSubstr(path.string() + ":"), HasSubstr(expected)));
  }
  EXPECT_EQ(readMeshFile(write("good.off", vertices + "3 0 1 2\n3 0 2 1\n")).triangleCount(), 2);
}

TEST_F(MeshFileTest, BadOptionsAreRejected) {
  MeshFileOptions options;
  options.scale = 0.0;
  EXPECT_THAT(errorOf([&] { readMeshFile(samplesDir() / "ramp.obj", options); }), HasSubstr("scale = 0"));
  options.scale = 1.0;
  options.pose_WM.linear() *= -1.0;  // a mirror, not a placement
  EXPECT_THAT(errorOf([&] { readMeshFile(samplesDir() / "ramp.obj", options); }),
              HasSubstr("pose_WM must be a finite rigid transform"));
}

}  // namespace mesh_file_test
}  // namespace wtc::io
