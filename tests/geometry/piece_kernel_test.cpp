// The query kernels chosen per piece (src/geometry/piece_kernel.hpp): which
// pieces get one, and that a kernel answers every query exactly as the
// general query does, bit for bit (every field, the cache, every status).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "geometry/piece_kernel.hpp"
#include "geometry/polyhedron_layout.hpp"
#include "query_checks.hpp"
#include "random_pieces.hpp"
#include "scenarios.hpp"
#include "wtc/base/error.hpp"
#include "wtc/geometry/point_query.hpp"

namespace {

using Eigen::Vector3d;
using testing::AnyOf;
using testing::Eq;
using wtc::ConvexPolyhedron;
using wtc::PointQuery;
using wtc::QueryCache;
using wtc::QueryOptions;
using wtc::detail::PieceKernel;
using wtc::detail::PolyhedronLayout;

// Random pieces per kernel test and points per piece (Jolt's seed x cases).
constexpr int kPieces = 400;
constexpr int kPointsPerPiece = 400;

PieceKernel kernelOf(const ConvexPolyhedron& poly) { return static_cast<PieceKernel>(PolyhedronLayout::kernel(poly)); }

// The box faces of ConvexPolyhedron::box, for pieces built through fromMesh.
const std::vector<std::vector<int>> kBoxFaces = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                                 {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};

// The terrain builders' prism faces (src/terrain/builder_support.cpp):
// vertices 0-2 the top, 3-5 the bottom.
const std::vector<std::vector<int>> kPrismFaces = {{0, 1, 2}, {3, 5, 4}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}};

// A random heightfield cell or extruded mesh triangle: top corners at a
// random scale and place, the bottom straight down (a heightfield, a flat
// cell one time in four) or along the top's normal (an extrusion).
std::vector<Vector3d> randomPrism(wtc::test::RandomPieces& random) {
  const double cell = std::pow(10.0, random.uniform(-2, 1));
  const Vector3d at(random.uniform(-1e4, 1e4), random.uniform(-1e4, 1e4), random.uniform(-100, 100));
  const bool flat = random.uniformInt(0, 3) == 0;
  auto height = [&] { return flat ? 0.0 : cell * random.uniform(-1, 1); };
  std::vector<Vector3d> v = {at + Vector3d(0, 0, height()), at + Vector3d(cell, 0, height()),
                             at + Vector3d(0, cell, height())};
  if (random.uniformInt(0, 1) == 0) {  // the cell's other triangle
    v[0] = at + Vector3d(cell, 0, height());
    v[1] = at + Vector3d(cell, cell, height());
  }
  if (random.uniformInt(0, 1) == 0) {
    const double floor = at.z() - 2 * cell;
    for (int i = 0; i < 3; ++i) v.push_back(Vector3d(v[i].x(), v[i].y(), floor));
  } else {
    const Vector3d n = (v[1] - v[0]).cross(v[2] - v[0]).normalized();
    const double thickness = cell * random.uniform(0.05, 1.0);
    for (int i = 0; i < 3; ++i) v.push_back(v[i] - thickness * n);
  }
  return v;
}

std::vector<Vector3d> boxCorners(const Vector3d& min, const Vector3d& max) {
  std::vector<Vector3d> v(8);
  for (int i = 0; i < 8; ++i)
    v[i] = {(i & 1) ? max.x() : min.x(), (i & 2) ? max.y() : min.y(), (i & 4) ? max.z() : min.z()};
  return v;
}

// Every bit of two answers, and of the caches they left.
testing::AssertionResult sameBits(const PointQuery& a, const PointQuery& b, const QueryCache* ca,
                                  const QueryCache* cb) {
  auto bits = [](const PointQuery& q) {
    std::vector<unsigned char> out(sizeof(double) * 10 + sizeof(int) + 1);
    unsigned char* o = out.data();
    auto put = [&](const void* p, std::size_t n) {
      std::memcpy(o, p, n);
      o += n;
    };
    put(&q.signed_distance, sizeof(double));
    put(q.closest_point.data(), 3 * sizeof(double));
    put(q.direction.data(), 3 * sizeof(double));
    put(q.normal.data(), 3 * sizeof(double));
    put(&q.iterations, sizeof(int));
    put(&q.status, 1);
    return out;
  };
  if (bits(a) != bits(b)) {
    return testing::AssertionFailure() << "kernel: " << wtc::test::describe(a)
                                       << "\ngeneral: " << wtc::test::describe(b);
  }
  if (ca != nullptr && (ca->count != cb->count || std::memcmp(ca->vertex, cb->vertex, sizeof ca->vertex) != 0)) {
    return testing::AssertionFailure() << "caches differ: count " << ca->count << " and " << cb->count;
  }
  return testing::AssertionSuccess();
}

// Points that meet every decision of the query on its boundary: vertices,
// edge and face points, their neighbouring doubles, coordinates on the
// bounding box's planes and at the local origin, and random points in and
// around the piece.
std::vector<Vector3d> hardPoints(const ConvexPolyhedron& poly, wtc::test::RandomPieces& random) {
  std::vector<Vector3d> points = {poly.origin(), Vector3d::Zero(), Vector3d(-0.0, -0.0, -0.0)};
  for (int i = 0; i < poly.vertexCount(); ++i) {
    const Vector3d v = poly.vertex(i);
    points.push_back(v);
    for (int k = 0; k < 3; ++k) {
      for (double toward : {-1e300, 1e300}) {
        Vector3d w = v;
        w[k] = std::nextafter(v[k], toward);
        points.push_back(w);
      }
      Vector3d w = v;
      w[k] = poly.origin()[k];
      points.push_back(w);
    }
    for (int j = 0; j < poly.vertexCount(); ++j) points.push_back(0.5 * (v + poly.vertex(j)));
  }
  const wtc::Aabb& box = poly.bounds();
  while (static_cast<int>(points.size()) < kPointsPerPiece) {
    Vector3d p = box.center() + 1.5 * box.extent().cwiseProduct(Vector3d(random.uniform(-1, 1), random.uniform(-1, 1),
                                                                         random.uniform(-1, 1)));
    for (int k = 0; k < 3; ++k) {
      const int snap = random.uniformInt(0, 4);
      if (snap == 0) p[k] = box.min[k];
      if (snap == 1) p[k] = box.max[k];
      if (snap == 2) p[k] = poly.origin()[k];
    }
    points.push_back(random.uniformInt(0, 1) == 0 ? p : random.query(poly));
  }
  return points;
}

// The kernel's answers against the general query's on the same piece, for
// the option sets a wheel, the benchmark and the tests use, with and
// without a cache carried from point to point.
void expectSameAsGeneral(const ConvexPolyhedron& poly, wtc::test::RandomPieces& random) {
  ConvexPolyhedron general = poly;
  PolyhedronLayout::useGeneralKernel(general);
  const std::vector<Vector3d> points = hardPoints(poly, random);
  const QueryOptions options[] = {{},
                                  {.max_distance = 0.19 * poly.size()},
                                  {.feature_regions = false},
                                  {.relative_tolerance = 1e-3},
                                  {.max_iterations = 1}};
  for (const QueryOptions& o : options) {
    QueryCache cache_kernel;
    QueryCache cache_general;
    for (const Vector3d& p : points) {
      ASSERT_TRUE(sameBits(wtc::queryPoint(poly, p, o), wtc::queryPoint(general, p, o), nullptr, nullptr))
          << "p = " << wtc::formatVector(p);
      const PointQuery a = wtc::queryPoint(poly, p, o, cache_kernel);
      const PointQuery b = wtc::queryPoint(general, p, o, cache_general);
      ASSERT_TRUE(sameBits(a, b, &cache_kernel, &cache_general)) << "p = " << wtc::formatVector(p) << " (cached)";
    }
  }
}

TEST(PieceKernelTest, AxisAlignedBoxesGetTheBoxKernel) {
  // Case: ConvexPolyhedron::box, the same box through fromMesh with box()'s
  // faces, and the benchmark's box.
  EXPECT_EQ(kernelOf(ConvexPolyhedron::box(Vector3d(-1, -2, -3), Vector3d(4, 5, 6))), PieceKernel::kAxisBox);
  EXPECT_EQ(kernelOf(ConvexPolyhedron::fromMesh(boxCorners(Vector3d(1e3, 2e3, -1), Vector3d(1e3 + 0.5, 2e3 + 0.25, 0)),
                                                kBoxFaces)),
            PieceKernel::kAxisBox);
  EXPECT_EQ(kernelOf(wtc::testing::makeShape(wtc::testing::ShapeId::kBox)), PieceKernel::kAxisBox);
}

TEST(PieceKernelTest, BuildersPrismsGetThePrismKernel) {
  // Case: a heightfield cell through fromMesh with the builders' faces, and
  // a prism formed from another's topology (the compact terrains' way).
  wtc::test::RandomPieces random(7);
  const std::vector<Vector3d> cell = {{0, 0, 1.2}, {0.5, 0, 1.1}, {0, 0.5, 1.3},
                                      {0, 0, -1},  {0.5, 0, -1},  {0, 0.5, -1}};
  const ConvexPolyhedron prism = ConvexPolyhedron::fromMesh(cell, kPrismFaces);
  EXPECT_EQ(kernelOf(prism), PieceKernel::kUprightPrism);
  std::vector<Vector3d> tilted = cell;
  tilted[5].x() = 0.01;  // a side no longer vertical
  EXPECT_EQ(kernelOf(PolyhedronLayout::sameTopologyAs(prism, tilted, kPrismFaces)), PieceKernel::kPrism);
  std::vector<Vector3d> raised = cell;
  raised[4].z() = -0.9;  // the bottom no longer flat
  EXPECT_EQ(kernelOf(ConvexPolyhedron::fromMesh(raised, kPrismFaces)), PieceKernel::kPrism);
  EXPECT_THAT(kernelOf(PolyhedronLayout::sameTopologyAs(prism, randomPrism(random), kPrismFaces)),
              AnyOf(Eq(PieceKernel::kPrism), Eq(PieceKernel::kUprightPrism)));
}

TEST(PieceKernelTest, OtherPiecesGetTheGeneralKernel) {
  // Case: a rotated box, a box whose faces are listed from another corner
  // (the kernel reads box()'s face order), a prism and the hulls.
  std::vector<Vector3d> rotated = boxCorners(Vector3d(0, 0, 0), Vector3d(1, 2, 3));
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.3, Vector3d::UnitZ()).toRotationMatrix();
  for (Vector3d& v : rotated) v = turn * v;
  EXPECT_EQ(kernelOf(ConvexPolyhedron::fromMesh(rotated, kBoxFaces)), PieceKernel::kGeneral);
  std::vector<std::vector<int>> shifted = kBoxFaces;
  std::rotate(shifted[0].begin(), shifted[0].begin() + 1, shifted[0].end());
  EXPECT_EQ(kernelOf(ConvexPolyhedron::fromMesh(boxCorners(Vector3d(0, 0, 0), Vector3d(1, 2, 3)), shifted)),
            PieceKernel::kGeneral);
  // Case: the hulls (Qhull's prisms have their own kernel, below).
  for (auto shape : {wtc::testing::ShapeId::kHull20, wtc::testing::ShapeId::kHull64}) {
    EXPECT_EQ(kernelOf(wtc::testing::makeShape(shape)), PieceKernel::kGeneral) << wtc::testing::toString(shape);
  }
}

// A random triangular prism's six corners, turned and placed at random,
// for fromPoints (Qhull labels them as it finds them): a heightfield cell or
// an extruded triangle (randomPrism), or a prism whose ends are not parallel.
std::vector<Vector3d> randomTurnedPrism(wtc::test::RandomPieces& random) {
  std::vector<Vector3d> v = randomPrism(random);
  const bool vertical_sides = v[3].x() == v[0].x() && v[3].y() == v[0].y();
  if (vertical_sides && random.uniformInt(0, 2) == 0) {
    const double cell = (v[1] - v[0]).norm();
    for (int i = 3; i < 6; ++i) v[i].z() -= cell * random.uniform(0.0, 0.5);  // a slanted bottom
  }
  if (random.uniformInt(0, 3) != 0) {  // else left as it stands: vertical sides, flat bottom
    const Vector3d axis = Vector3d(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)).normalized();
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(random.uniform(-3.1, 3.1), axis).toRotationMatrix();
    const Vector3d about = v[0];
    for (Vector3d& p : v) p = about + turn * (p - about);
  }
  return v;
}

TEST(PieceKernelTest, QhullPrismsGetTheLabelledPrismKernel) {
  // Case: the benchmark's prism (Qhull's order of vertices and faces), a
  // turned one, and pieces of 6 vertices and 5 faces that are not prisms
  // (a pyramid on a quad with one corner cut: faces of 3, 4 and 5 edges).
  wtc::test::RandomPieces random(11);
  EXPECT_EQ(kernelOf(wtc::testing::makeShape(wtc::testing::ShapeId::kPrism)), PieceKernel::kLabelledPrism);
  const std::vector<Vector3d> cell = {{0, 0, 1.2}, {0.5, 0, 1.1}, {0, 0.5, 1.3},
                                      {0, 0, -1},  {0.5, 0, -1},  {0, 0.5, -1}};
  EXPECT_EQ(kernelOf(ConvexPolyhedron::fromPoints(cell)), PieceKernel::kLabelledPrism);
  const ConvexPolyhedron cut =
      ConvexPolyhedron::fromPoints({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}, {0.1, 0, 0.1}});
  EXPECT_EQ(cut.vertexCount(), 6);
  EXPECT_NE(kernelOf(cut), PieceKernel::kLabelledPrism);
  // Case: the builders' prism keeps its own kernels; a box is not a prism.
  EXPECT_NE(kernelOf(ConvexPolyhedron::fromMesh(randomPrism(random), kPrismFaces)), PieceKernel::kLabelledPrism);
  EXPECT_EQ(kernelOf(ConvexPolyhedron::fromPoints(boxCorners(Vector3d(0, 0, 0), Vector3d(1, 2, 3)))),
            PieceKernel::kGeneral);
}

TEST(PieceKernelTest, LabelledPrismKernelAnswersAsTheGeneralQueryBitForBit) {
  // Case: random prisms through fromPoints (Qhull's labels: every order of
  // vertices, faces and first vertices it produces), upright, extruded,
  // slanted and turned, each queried as the boxes are.
  wtc::test::RandomPieces random(20261128);
  int prisms = 0;
  for (int i = 0; i < kPieces; ++i) {
    const ConvexPolyhedron poly = ConvexPolyhedron::fromPoints(randomTurnedPrism(random));
    // Qhull keeps a quad that is planar only to roundoff as two triangles
    // now and then: not a prism's faces.
    if (poly.faceCount() != 5) continue;
    ASSERT_EQ(kernelOf(poly), PieceKernel::kLabelledPrism) << "prism " << i;
    ++prisms;
    expectSameAsGeneral(poly, random);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(prisms, kPieces / 4);  // about a third come out as prisms
  expectSameAsGeneral(wtc::testing::makeShape(wtc::testing::ShapeId::kPrism), random);
}

TEST(PieceKernelTest, BoxKernelAnswersAsTheGeneralQueryBitForBit) {
  // Case: random axis-aligned boxes (scales 1e-3 to 1e3 m, up to 1e5 m from
  // the origin, extents 100:1), each queried at vertices, edges, faces,
  // their neighbouring doubles and random points, five option sets, with and
  // without a cache.
  wtc::test::RandomPieces random(20261126);
  int boxes = 0;
  for (int i = 0; i < kPieces; ++i) {
    const double scale = std::pow(10.0, random.uniform(-3, 3));
    const Vector3d min =
        scale * Vector3d(random.uniform(-100, 100), random.uniform(-100, 100), random.uniform(-100, 100));
    const Vector3d extent =
        scale * Vector3d(std::pow(10.0, random.uniform(-1, 1)), std::pow(10.0, random.uniform(-1, 1)),
                         std::pow(10.0, random.uniform(-1, 1)));
    const ConvexPolyhedron poly = ConvexPolyhedron::box(min, min + extent);
    ASSERT_EQ(kernelOf(poly), PieceKernel::kAxisBox)
        << "box " << wtc::formatVector(min) << " + " << wtc::formatVector(extent);
    ++boxes;
    expectSameAsGeneral(poly, random);
    if (HasFatalFailure()) return;
  }
  EXPECT_EQ(boxes, kPieces);
  expectSameAsGeneral(wtc::testing::makeShape(wtc::testing::ShapeId::kBox), random);
}

TEST(PieceKernelTest, PrismKernelAnswersAsTheGeneralQueryBitForBit) {
  // Case: random heightfield cells and extruded triangles (cells 1 cm to
  // 10 m, up to 1e4 m from the origin, flat and tilted tops, bottoms straight
  // down or along the normal), built through fromMesh and formed from a
  // reference's topology, each queried as the boxes are.
  wtc::test::RandomPieces random(20261127);
  const ConvexPolyhedron reference = ConvexPolyhedron::fromMesh(randomPrism(random), kPrismFaces);
  int upright = 0;
  int tilted = 0;
  for (int i = 0; i < kPieces; ++i) {
    const std::vector<Vector3d> corners = randomPrism(random);
    const ConvexPolyhedron poly = i % 2 == 0 ? ConvexPolyhedron::fromMesh(corners, kPrismFaces)
                                             : PolyhedronLayout::sameTopologyAs(reference, corners, kPrismFaces);
    ASSERT_THAT(kernelOf(poly), AnyOf(Eq(PieceKernel::kPrism), Eq(PieceKernel::kUprightPrism))) << "prism " << i;
    ++(kernelOf(poly) == PieceKernel::kUprightPrism ? upright : tilted);
    expectSameAsGeneral(poly, random);
    if (HasFatalFailure()) return;
  }
  // Both prism kernels were held to the general query, each many times.
  EXPECT_GT(upright, kPieces / 4);
  EXPECT_GT(tilted, kPieces / 4);
}

}  // namespace
