// wtc::ConvexPolyhedron::fromMesh, the trusted fast path of the terrain
// builders: valid meshes give the same piece as the other factories; bad
// ones (non-finite vertex, bad index, short face, non-planar face, non-convex,
// open or inward mesh) throw InvalidInputError naming the face or vertex.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <vector>

#include "brute_force.hpp"
#include "query_checks.hpp"
#include "random_pieces.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"
#include "wtc/base/error.hpp"
#include "wtc/geometry/point_query.hpp"

namespace convex_polyhedron_from_mesh_test {

using Eigen::Vector3d;
using testing::AllOf;
using testing::ContainsRegex;
using testing::HasSubstr;
using testing::ThrowsMessage;
using wtc::ConvexPolyhedron;
using wtc::InvalidInputError;
using Faces = std::vector<std::vector<int>>;

// Error allowed on query results, relative to the piece's size.
constexpr double kTolerance = 1e-9;

// The unit cube [0, 1]^3; vertex i has coordinates (i & 1, i & 2, i & 4).
std::vector<Vector3d> cubeVertices() {
  std::vector<Vector3d> v;
  for (int i = 0; i < 8; ++i) v.emplace_back(i & 1 ? 1 : 0, i & 2 ? 1 : 0, i & 4 ? 1 : 0);
  return v;
}
// Its faces, counter-clockwise seen from outside: -x, +x, -y, +y, -z, +z.
Faces cubeFaces() { return {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}}; }

TEST(ConvexPolyhedronFromMeshTest, CubeMeshQueriesLikeTheBoxFactory) {
  // Case: the cube as a mesh and as box(): same planes, same answers.
  const ConvexPolyhedron mesh = ConvexPolyhedron::fromMesh(cubeVertices(), cubeFaces());
  const ConvexPolyhedron box = ConvexPolyhedron::box(Vector3d::Zero(), Vector3d::Ones());
  EXPECT_EQ(mesh.vertexCount(), 8);
  EXPECT_EQ(mesh.faceCount(), 6);
  EXPECT_FALSE(mesh.isFlat());
  const wtc::testing::BruteForceOracle oracle(mesh);
  wtc::test::RandomPieces random(51);
  for (int i = 0; i < 1000; ++i) {
    const Vector3d p = random.query(mesh);
    const wtc::PointQuery got = wtc::queryPoint(mesh, p);
    EXPECT_TRUE(wtc::test::agreesWithOracle(mesh, oracle, p, got, kTolerance * mesh.size()));
    EXPECT_NEAR(got.signed_distance, wtc::queryPoint(box, p).signed_distance, kTolerance * mesh.size());
  }
}

TEST(ConvexPolyhedronFromMeshTest, PrismWithTriangleAndQuadFacesIsAccepted) {
  // Case: a heightfield cell: ground triangle 3-4-5 over the base 0-1-2.
  const std::vector<Vector3d> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1.2}, {1, 0, 0.9}, {0, 1, 1.0}};
  const Faces faces = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
  const ConvexPolyhedron poly = ConvexPolyhedron::fromMesh(v, faces);
  EXPECT_EQ(poly.faceCount(), 5);
  const wtc::testing::BruteForceOracle oracle(poly);
  wtc::test::RandomPieces random(52);
  for (int i = 0; i < 1000; ++i) {
    const Vector3d p = random.query(poly);
    EXPECT_TRUE(wtc::test::agreesWithOracle(poly, oracle, p, wtc::queryPoint(poly, p), kTolerance * poly.size()));
  }
}

TEST(ConvexPolyhedronFromMeshTest, PolygonGivenFromBothSidesIsFlat) {
  // Case: the square z = 0 as two faces of opposite orientation.
  const std::vector<Vector3d> v = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const ConvexPolyhedron poly = ConvexPolyhedron::fromMesh(v, {{0, 1, 2, 3}, {3, 2, 1, 0}});
  EXPECT_TRUE(poly.isFlat());
  EXPECT_NEAR(wtc::queryPoint(poly, Vector3d(0.5, 0.5, -2)).signed_distance, 2.0, kTolerance * poly.size());
}

TEST(ConvexPolyhedronFromMeshTest, RejectsANonFiniteVertexNamingIt) {
  // Case: vertex 2 has an infinite coordinate.
  std::vector<Vector3d> v = cubeVertices();
  v[2].y() = std::numeric_limits<double>::infinity();
  EXPECT_THAT([&] { ConvexPolyhedron::fromMesh(v, cubeFaces()); },
              ThrowsMessage<InvalidInputError>(AllOf(HasSubstr("vertex 2"), HasSubstr("inf"))));
}

TEST(ConvexPolyhedronFromMeshTest, RejectsABadIndexNamingTheFace) {
  // Case: face 3 refers to vertex 8 of 8; face 0 to vertex -1.
  Faces faces = cubeFaces();
  faces[3][2] = 8;
  EXPECT_THAT([&] { ConvexPolyhedron::fromMesh(cubeVertices(), faces); },
              ThrowsMessage<InvalidInputError>(AllOf(HasSubstr("face 3"), HasSubstr("8"))));
  faces = cubeFaces();
  faces[0][1] = -1;
  EXPECT_THAT([&] { ConvexPolyhedron::fromMesh(cubeVertices(), faces); },
              ThrowsMessage<InvalidInputError>(AllOf(HasSubstr("face 0"), HasSubstr("-1"))));
}

TEST(ConvexPolyhedronFromMeshTest, RejectsAFaceOfTwoVerticesNamingIt) {
  // Case: face 4 lists only two vertices.
  Faces faces = cubeFaces();
  faces[4] = {0, 2};
  EXPECT_THAT([&] { ConvexPolyhedron::fromMesh(cubeVertices(), faces); },
              ThrowsMessage<InvalidInputError>(HasSubstr("face 4")));
}

TEST(ConvexPolyhedronFromMeshTest, RejectsANonPlanarFaceNamingIt) {
  // Case: the +z face's corner 7 lifted by 1e-3 m (the tolerance is 1.7e-9 m);
  // faces 1 (+x), 3 (+y) and 5 (+z) hold vertex 7, so one of them is named.
  std::vector<Vector3d> v = cubeVertices();
  v[7].z() += 1e-3;
  EXPECT_THAT([&] { ConvexPolyhedron::fromMesh(v, cubeFaces()); },
              ThrowsMessage<InvalidInputError>(ContainsRegex("face [135][^0-9]")));
}

TEST(ConvexPolyhedronFromMeshTest, RejectsANonConvexMeshNamingAFace) {
  // Case: the cube, triangulated, with corner 7 pushed in to the centre of
  // the cube: every face is a planar triangle, but the piece has a dimple.
  std::vector<Vector3d> v = cubeVertices();
  v[7] = Vector3d(0.6, 0.6, 0.6);
  Faces triangles;
  for (const std::vector<int>& quad : cubeFaces()) {
    triangles.push_back({quad[0], quad[1], quad[2]});
    triangles.push_back({quad[0], quad[2], quad[3]});
  }
  EXPECT_THAT([&] { ConvexPolyhedron::fromMesh(v, triangles); },
              ThrowsMessage<InvalidInputError>(ContainsRegex("face [0-9]+")));
}

TEST(ConvexPolyhedronFromMeshTest, RejectsAnOpenMesh) {
  // Case: the cube without its +z face. Every remaining face is planar,
  // outward and convex, but the piece is not closed: accepted, it would
  // report a point 2 m above the cube as inside.
  Faces faces = cubeFaces();
  faces.pop_back();
  EXPECT_THROW(ConvexPolyhedron::fromMesh(cubeVertices(), faces), InvalidInputError);
}

TEST(ConvexPolyhedronFromMeshTest, RejectsInwardFacesNamingTheFirst) {
  // Case: every face listed clockwise seen from outside.
  Faces faces = cubeFaces();
  for (std::vector<int>& face : faces) std::reverse(face.begin(), face.end());
  EXPECT_THAT([&] { ConvexPolyhedron::fromMesh(cubeVertices(), faces); },
              ThrowsMessage<InvalidInputError>(HasSubstr("face 0")));
}

}  // namespace convex_polyhedron_from_mesh_test
