#include "wtc/terrain/triangle_mesh.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "wtc/base/error.hpp"
#include "wtc/geometry/point_query.hpp"
#include "wtc/terrain/terrain.hpp"

namespace wtc {
namespace triangle_mesh_test {

using ::testing::AllOf;
using ::testing::HasSubstr;

constexpr double kTolerance = 1e-12;  // m; the meshes are exact binary fractions

// The unit cube [0, 1]^3 as 12 triangles, counter-clockwise from outside.
TriangleMesh cube() {
  TriangleMesh mesh;
  mesh.name = "cube";
  for (int i = 0; i < 8; ++i) mesh.vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& q : quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[2], q[3]});
  }
  return mesh;
}

struct Built {
  MeshBuildReport report;
  Terrain terrain;
};

Built build(const TriangleMesh& mesh, const MeshExtrusionOptions& options) {
  TerrainBuilder builder;
  const MaterialId m = builder.addMaterial(Material{});
  MeshBuildReport report = addTriangleMesh(builder, mesh, m, options);
  return {report, std::move(builder).build()};
}

TEST(TriangleMeshTest, ExtrudedTriangleHangsBelowItsFaceByTheThickness) {
  const ConvexPolyhedron prism = makeExtrudedTriangle({0, 0, 0}, {2, 0, 0}, {0, 2, 1}, 0.25);
  const Eigen::Vector3d n = Eigen::Vector3d(0, -1, 2).normalized();  // (b - a) x (c - a), normalised
  EXPECT_TRUE(prism.faceNormal(0).isApprox(n, kTolerance));
  const Eigen::Vector3d on_face = Eigen::Vector3d(0.5, 0.5, 0.25);
  EXPECT_NEAR(queryPoint(prism, on_face + 0.1 * n).signed_distance, 0.1, kTolerance);
  EXPECT_NEAR(queryPoint(prism, on_face - 0.1 * n).signed_distance, -0.1, kTolerance);
  // Case: the far side of the skin is `thickness` below the face.
  EXPECT_NEAR(queryPoint(prism, on_face - 0.35 * n).signed_distance, 0.1, kTolerance);
}

TEST(TriangleMeshTest, OpenSurfaceGivesOnePrismPerTriangle) {
  TriangleMesh ramp;
  ramp.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5}, {0, 1, 0.5}};
  ramp.triangles = {{0, 1, 2}, {0, 2, 3}};
  const Built b = build(ramp, {.thickness = 0.1, .keep_convex_parts = true});
  EXPECT_EQ(b.report.triangles, 2);
  EXPECT_EQ(b.report.pieces.count, 2);
  EXPECT_EQ(b.report.convex_parts, 0);  // open: never one piece
  EXPECT_EQ(b.report.flipped_parts, 0);
  const Eigen::Vector3d n = Eigen::Vector3d(0, -0.5, 1).normalized();
  EXPECT_NEAR(queryPoint(b.terrain.piece(0), Eigen::Vector3d(0.7, 0.3, 0.15) + 0.05 * n).signed_distance, 0.05,
              kTolerance);
}

TEST(TriangleMeshTest, ClosedConvexPartStaysOnePieceWhenAsked) {
  const Built whole = build(cube(), {.thickness = 0.1, .keep_convex_parts = true});
  EXPECT_EQ(whole.report.pieces.count, 1);
  EXPECT_EQ(whole.report.convex_parts, 1);
  EXPECT_EQ(whole.terrain.piece(0).faceCount(), 6);  // coplanar triangles merged
  EXPECT_NEAR(queryPoint(whole.terrain.piece(0), {0.5, 0.5, 0.5}).signed_distance, -0.5, kTolerance);
  // Case: without the option, every triangle is a prism.
  const Built skins = build(cube(), {.thickness = 0.1, .keep_convex_parts = false});
  EXPECT_EQ(skins.report.pieces.count, 12);
  EXPECT_EQ(skins.report.convex_parts, 0);
}

TEST(TriangleMeshTest, ClosedNonConvexPartIsExtruded) {
  // Case: a cube with one top vertex pushed down makes a dent: closed, not convex.
  TriangleMesh dented = cube();
  dented.vertices[7].z() = 0.6;
  const Built b = build(dented, {.thickness = 0.05, .keep_convex_parts = true});
  EXPECT_EQ(b.report.convex_parts, 0);
  EXPECT_EQ(b.report.pieces.count, 12);
}

TEST(TriangleMeshTest, InsideOutClosedPartIsFlipped) {
  TriangleMesh inverted = cube();
  for (auto& t : inverted.triangles) std::swap(t[1], t[2]);
  const Built b = build(inverted, {.thickness = 0.1, .keep_convex_parts = false});
  EXPECT_EQ(b.report.flipped_parts, 1);
  // Case: after the flip, the skins lie inside the cube: the centre of the
  // top face seen from 0.2 m above is 0.2 m away.
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& piece : b.terrain.pieces()) {
    nearest = std::min(nearest, queryPoint(piece, {0.5, 0.5, 1.2}).signed_distance);
    EXPECT_GE(piece.bounds().min.z(), -kTolerance);  // nothing sticks out below
    EXPECT_LE(piece.bounds().max.z(), 1.0 + kTolerance);
  }
  EXPECT_NEAR(nearest, 0.2, kTolerance);
}

TEST(TriangleMeshTest, DegenerateTrianglesAreSkippedAndCounted) {
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {0, 0, 0}};
  mesh.triangles = {{0, 1, 2},   // good
                    {0, 1, 3},   // collinear
                    {0, 4, 1},   // two vertices at one position
                    {2, 2, 2}};  // a point
  const Built b = build(mesh, {});
  EXPECT_EQ(b.report.triangles, 4);
  EXPECT_EQ(b.report.degenerate_skipped, 3);
  EXPECT_EQ(b.report.pieces.count, 1);
}

TEST(TriangleMeshTest, BadInputIsNamedByPartTriangleAndVertex) {
  TerrainBuilder builder;
  const MaterialId m = builder.addMaterial(Material{});
  TriangleMesh mesh = cube();
  mesh.triangles[5][1] = 8;
  try {
    addTriangleMesh(builder, mesh, m);
    ADD_FAILURE() << "no error";
  } catch (const InvalidInputError& e) {
    EXPECT_THAT(e.what(), AllOf(HasSubstr("cube, triangle 5"), HasSubstr("vertex 8"), HasSubstr("8 vertices")));
  }
  mesh = cube();
  mesh.vertices[3].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(addTriangleMesh(builder, mesh, m), InvalidInputError);
  try {
    addTriangleMesh(builder, cube(), m, {.thickness = -0.1});
    ADD_FAILURE() << "no error";
  } catch (const InvalidInputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("thickness = -0.1"));
  }
  EXPECT_EQ(builder.pieceCount(), 0u);
}

}  // namespace triangle_mesh_test
}  // namespace wtc
