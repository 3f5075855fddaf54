// wtc::ConvexPolyhedron built by box() and fromPoints(): the stored piece is
// a valid convex polyhedron (planar, outward, counter-clockwise faces, closed,
// every input point inside, every vertex an input point), flat pieces have
// two opposite faces, degenerate input throws with a message that says why,
// and support() and planeBound() are what their names promise.
#include "wtc/geometry/convex_polyhedron.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <utility>
#include <vector>

#include "random_pieces.hpp"
#include "scenarios.hpp"
#include "wtc/base/error.hpp"

namespace convex_polyhedron_test {

using Eigen::Vector3d;
using testing::AllOf;
using testing::HasSubstr;
using testing::ThrowsMessage;
using wtc::ConvexPolyhedron;
using wtc::InvalidInputError;

// Geometric checks allow this fraction of the piece's size (dimensionless):
// the merge tolerance of the hull, tolerance::kHullMergeRelative.
constexpr double kTolerance = 1e-9;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Height of x over the plane of face f, from one of its vertices (m).
double heightAbove(const ConvexPolyhedron& poly, int f, const Vector3d& x) {
  return poly.faceNormal(f).dot(x - poly.vertex(poly.faceVertices(f)[0]));
}

// Every structural promise of the header, for any piece.
void expectValidPiece(const ConvexPolyhedron& poly, const std::vector<Vector3d>& input) {
  const double tolerance = kTolerance * poly.size();
  std::map<std::pair<int, int>, int> directed_edges;
  for (int f = 0; f < poly.faceCount(); ++f) {
    const auto face = poly.faceVertices(f);
    ASSERT_GE(face.size(), 3u) << "face " << f;
    EXPECT_NEAR(poly.faceNormal(f).norm(), 1.0, 1e-12) << "face " << f;
    EXPECT_NEAR(poly.faceNormal(f).dot(poly.vertex(face[0])), poly.faceOffset(f), tolerance);
    Vector3d area = Vector3d::Zero();  // Newell: counter-clockwise seen from outside
    for (std::size_t k = 0; k < face.size(); ++k) {
      const Vector3d a = poly.vertex(face[k]) - poly.vertex(face[0]);
      const Vector3d b = poly.vertex(face[(k + 1) % face.size()]) - poly.vertex(face[0]);
      area += a.cross(b);
      EXPECT_NEAR(heightAbove(poly, f, poly.vertex(face[k])), 0.0, tolerance) << "face " << f;
      ++directed_edges[{face[k], face[(k + 1) % face.size()]}];
    }
    // Counter-clockwise is a sign. The direction of a sliver facet's own
    // Newell normal is roundoff noise (2e-3 rad for the 1e-10 m^2 facet of
    // HullOfARotatedIntegerGridIsValid); planarity is checked by the vertex
    // heights above, to kTolerance.
    EXPECT_GT(area.dot(poly.faceNormal(f)), 0.0) << "face " << f << " is not CCW";
    for (int i = 0; i < poly.vertexCount(); ++i) {
      EXPECT_LE(heightAbove(poly, f, poly.vertex(i)), tolerance) << "vertex " << i << ", face " << f;
    }
    for (const Vector3d& x : input) EXPECT_LE(heightAbove(poly, f, x), tolerance) << "face " << f;
  }
  // Closed: every edge is crossed once each way (a flat piece's two faces
  // share their boundary the same way).
  for (const auto& [edge, count] : directed_edges) {
    EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second;
    EXPECT_EQ(directed_edges.count({edge.second, edge.first}), 1u);
  }
  if (!poly.isFlat()) {  // Euler: V - E + F = 2
    const int edges = static_cast<int>(directed_edges.size()) / 2;
    EXPECT_EQ(poly.vertexCount() - edges + poly.faceCount(), 2);
  }
  Vector3d sum = Vector3d::Zero();
  for (int i = 0; i < poly.vertexCount(); ++i) {
    const Vector3d v = poly.vertex(i);
    sum += v;
    EXPECT_TRUE((v.array() >= poly.bounds().min.array()).all() && (v.array() <= poly.bounds().max.array()).all());
    if (input.empty()) continue;
    double nearest = std::numeric_limits<double>::infinity();
    for (const Vector3d& x : input) nearest = std::min(nearest, (x - v).norm());
    EXPECT_LE(nearest, tolerance) << "vertex " << i << " is not an input point";
  }
  EXPECT_NEAR(poly.size(), poly.bounds().extent().norm(), 1e-15 * poly.size());
  EXPECT_LE((poly.centroid() - sum / poly.vertexCount()).norm(), 1e-12 * poly.size());
}

TEST(ConvexPolyhedronTest, BoxHasEightVerticesSixFacesAndItsBounds) {
  // Case: the 2 x 4 x 6 box centred at the origin.
  const ConvexPolyhedron poly = ConvexPolyhedron::box(Vector3d(-1, -2, -3), Vector3d(1, 2, 3));
  EXPECT_EQ(poly.vertexCount(), 8);
  EXPECT_EQ(poly.faceCount(), 6);
  EXPECT_FALSE(poly.isFlat());
  EXPECT_EQ(poly.bounds().min, Vector3d(-1, -2, -3));
  EXPECT_EQ(poly.bounds().max, Vector3d(1, 2, 3));
  EXPECT_DOUBLE_EQ(poly.size(), std::sqrt(56.0));
  for (int f = 0; f < 6; ++f) {
    const Vector3d n = poly.faceNormal(f);
    EXPECT_NEAR(n.cwiseAbs().maxCoeff(), 1.0, 1e-15) << "face " << f << " is not axis-aligned";
    EXPECT_DOUBLE_EQ(poly.faceOffset(f), n.cwiseAbs().dot(Vector3d(1, 2, 3)));
  }
  expectValidPiece(poly, {});
}

TEST(ConvexPolyhedronTest, BoxRejectsEmptyInvertedOrNonFiniteBounds) {
  // Case: min == max on one axis, min > max, a NaN corner.
  for (const auto& [min, max] :
       {std::pair{Vector3d(0, 0, 0), Vector3d(1, 0, 1)}, std::pair{Vector3d(0, 0, 0), Vector3d(1, -1, 1)},
        std::pair{Vector3d(0, kNaN, 0), Vector3d(1, 1, 1)}}) {
    EXPECT_THAT([&] { ConvexPolyhedron::box(min, max); },
                ThrowsMessage<InvalidInputError>(HasSubstr(wtc::formatVector(min))));
  }
}

TEST(ConvexPolyhedronTest, HullOfCubeCornersAndInnerPointsHasSixQuadFaces) {
  // Case: cube corners, face centres, edge midpoints and the centre: the
  // coplanar triangles merge into six quadrilaterals.
  std::vector<Vector3d> points;
  for (int i = 0; i < 27; ++i) points.emplace_back(i % 3 - 1, i / 3 % 3 - 1, i / 9 - 1);
  const ConvexPolyhedron poly = ConvexPolyhedron::fromPoints(points);
  EXPECT_EQ(poly.vertexCount(), 8);
  ASSERT_EQ(poly.faceCount(), 6);
  for (int f = 0; f < 6; ++f) EXPECT_EQ(poly.faceVertices(f).size(), 4u) << "face " << f;
  expectValidPiece(poly, points);
}

TEST(ConvexPolyhedronTest, RandomHullsAreValidConvexPolyhedra) {
  // Case: 300 random pieces of every kind (hulls, boxes, prisms, flat).
  wtc::test::RandomPieces random(41);
  for (int i = 0; i < 300; ++i) {
    const wtc::test::RandomPiece piece = random.any();
    SCOPED_TRACE("piece " + std::to_string(i) + ": " + piece.kind);
    expectValidPiece(piece.poly, piece.points);
  }
}

TEST(ConvexPolyhedronTest, HullOfARotatedIntegerGridIsValid) {
  // Case: eight points of a rotated integer grid (spacing 94 m): nearly
  // collinear triples, for which Qhull returns a facet of area ~1e-10 m^2
  // whose normal cannot be recomputed from its own vertices.
  const std::vector<Vector3d> points = {{-5205.4216433032816, 302.24384028763433, 8151.7340592584005},
                                        {-5139.9440054508923, 472.95336771716978, 8109.9006471513467},
                                        {-5283.0433131397558, 370.38256743077682, 8308.294234327197},
                                        {-5125.3516726018652, 333.03997391399389, 8402.7292670024272},
                                        {-5250.3044942135612, 455.73733114554454, 8287.3775282736715},
                                        {-5126.5758230343363, 283.57254352924286, 8198.9515755960147},
                                        {-5217.5656752873656, 541.09209486031227, 8266.4608222201441},
                                        {-5059.874034749475, 503.74950134352935, 8360.8958548953724}};
  const ConvexPolyhedron poly = ConvexPolyhedron::fromPoints(points);
  expectValidPiece(poly, points);
}

TEST(ConvexPolyhedronTest, TetrahedronWithAShortEdgeIsValid) {
  // Case: two vertices 4.6e-8 m apart (13x the merge tolerance of this 3.5 m
  // piece), so kept: two faces are needles 2.8 m long and 4.6e-8 m wide.
  const std::vector<Vector3d> points = {{1.0000002971574162, 1.0000001239272898, -0.99999986274295372},
                                        {1.0000001536357752, -0.99999969904891883, 0.99999990876132772},
                                        {1.0000001504100746, -0.99999968747644075, 0.99999995303368938},
                                        {-1.000000312321156, 1.0000001565663525, 0.9999999789649634}};
  const ConvexPolyhedron poly = ConvexPolyhedron::fromPoints(points);
  EXPECT_EQ(poly.vertexCount(), 4);
  expectValidPiece(poly, points);
}

TEST(ConvexPolyhedronTest, FlatPieceHasTwoOppositeFaces) {
  // Case: a square with its centre and edge midpoints, in a tilted plane.
  std::vector<Vector3d> points;
  for (int i = 0; i < 9; ++i) points.emplace_back(i % 3 - 1, i / 3 - 1, 0.5 * (i % 3 - 1));
  const ConvexPolyhedron poly = ConvexPolyhedron::fromPoints(points);
  ASSERT_TRUE(poly.isFlat());
  ASSERT_EQ(poly.faceCount(), 2);
  EXPECT_EQ(poly.vertexCount(), 4);
  EXPECT_NEAR(poly.faceNormal(0).dot(poly.faceNormal(1)), -1.0, 1e-15);
  EXPECT_EQ(poly.faceVertices(0).size(), 4u);
  EXPECT_EQ(poly.faceVertices(1).size(), 4u);
  expectValidPiece(poly, points);
}

TEST(ConvexPolyhedronTest, FewerThanThreeNonCollinearPointsThrow) {
  // Case: no points, one point, a repeated point, two points, collinear
  // points (exactly, and to 1e-12 of their length).
  EXPECT_THAT([] { ConvexPolyhedron::fromPoints({}); }, ThrowsMessage<InvalidInputError>(HasSubstr("empty")));
  const Vector3d a(1, 2, 3);
  const Vector3d b(4, 6, 3);
  for (const std::vector<Vector3d>& points : {std::vector<Vector3d>{a},
                                              {a, a, a, a},
                                              {a, b},
                                              {a, b, 0.5 * (a + b)},
                                              {a, b, a + 0.25 * (b - a), a + 0.75 * (b - a) + Vector3d(0, 0, 5e-12)}}) {
    EXPECT_THAT([&] { ConvexPolyhedron::fromPoints(points); },
                ThrowsMessage<InvalidInputError>(HasSubstr("non-collinear")))
        << points.size() << " points";
  }
}

TEST(ConvexPolyhedronTest, NonFinitePointThrowsNamingItsIndex) {
  // Case: the fourth of five points is NaN.
  std::vector<Vector3d> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, kNaN}, {0, 0, 1}};
  EXPECT_THAT([&] { ConvexPolyhedron::fromPoints(points); },
              ThrowsMessage<InvalidInputError>(AllOf(HasSubstr("point 3"), HasSubstr("nan"))));
}

TEST(ConvexPolyhedronTest, SupportReturnsAVertexFurthestAlongTheDirection) {
  // Case: random directions on every catalogue piece (hull64 hill-climbs)
  // and random pieces, with no hint and with a random hint.
  wtc::test::RandomPieces random(42);
  std::vector<ConvexPolyhedron> pieces;
  for (const wtc::testing::ShapeId shape : wtc::testing::kAllShapes) pieces.push_back(wtc::testing::makeShape(shape));
  for (int i = 0; i < 50; ++i) pieces.push_back(random.hull(random.uniformInt(40, 100)).poly);
  for (const ConvexPolyhedron& poly : pieces) {
    for (int k = 0; k < 200; ++k) {
      const Vector3d dir = random.onUnitSphere();
      double best = -std::numeric_limits<double>::infinity();
      for (int i = 0; i < poly.vertexCount(); ++i) best = std::max(best, dir.dot(poly.vertex(i) - poly.origin()));
      for (const int hint : {-1, random.uniformInt(0, poly.vertexCount() - 1)}) {
        const int found = poly.support(dir, hint);
        ASSERT_GE(found, 0);
        ASSERT_LT(found, poly.vertexCount());
        EXPECT_GE(dir.dot(poly.vertex(found) - poly.origin()), best - 1e-12 * poly.size())
            << poly.vertexCount() << " vertices, hint " << hint;
      }
    }
  }
}

TEST(ConvexPolyhedronTest, PlaneBoundIsTheLargestFaceHeight) {
  // Case: random points around random pieces.
  wtc::test::RandomPieces random(43);
  for (int i = 0; i < 100; ++i) {
    const ConvexPolyhedron poly = random.any().poly;
    for (int k = 0; k < 50; ++k) {
      const Vector3d p = random.query(poly);
      double largest = -std::numeric_limits<double>::infinity();
      for (int f = 0; f < poly.faceCount(); ++f) largest = std::max(largest, heightAbove(poly, f, p));
      int face = -1;
      const double bound = poly.planeBound(p, &face);
      EXPECT_NEAR(bound, largest, kTolerance * poly.size());
      ASSERT_GE(face, 0);
      EXPECT_NEAR(heightAbove(poly, face, p), bound, kTolerance * poly.size());
    }
  }
}

TEST(ConvexPolyhedronTest, MemoryBytesCountsTheHeap) {
  // Case: the 64-vertex hull holds at least its coordinates and planes.
  const ConvexPolyhedron poly = wtc::testing::makeShape(wtc::testing::ShapeId::kHull64);
  const std::size_t numbers = 3 * poly.vertexCount() + 4 * poly.faceCount();
  EXPECT_GE(poly.memoryBytes(), sizeof(ConvexPolyhedron) + numbers * sizeof(double));
}

// Everything a user reads of a piece, compared to the bit: a copy is the
// same piece.
void expectSamePiece(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  ASSERT_EQ(a.vertexCount(), b.vertexCount());
  ASSERT_EQ(a.faceCount(), b.faceCount());
  EXPECT_EQ(a.origin(), b.origin());
  EXPECT_EQ(a.bounds().min, b.bounds().min);
  EXPECT_EQ(a.bounds().max, b.bounds().max);
  for (int i = 0; i < a.vertexCount(); ++i) EXPECT_EQ(a.vertexLocal(i), b.vertexLocal(i)) << "vertex " << i;
  for (int f = 0; f < a.faceCount(); ++f) {
    EXPECT_EQ(a.faceNormal(f), b.faceNormal(f)) << "face " << f;
    EXPECT_EQ(a.faceOffsetLocal(f), b.faceOffsetLocal(f)) << "face " << f;
    const auto fa = a.faceVertices(f), fb = b.faceVertices(f);
    EXPECT_TRUE(std::equal(fa.begin(), fa.end(), fb.begin(), fb.end())) << "face " << f;
  }
  const Vector3d p = a.bounds().max + Vector3d(0.3, -0.2, 0.7);
  EXPECT_EQ(a.planeBound(p), b.planeBound(p));
  EXPECT_EQ(a.support(p), b.support(p));
}

TEST(ConvexPolyhedronTest, CopiesAndMovesAreIndependentPieces) {
  const std::vector<Vector3d> cloud = {Vector3d(0, 0, 0), Vector3d(2, 0, 0), Vector3d(0, 3, 0),
                                       Vector3d(0, 0, 1), Vector3d(1, 1, 2), Vector3d(2, 2, 0.5)};
  const ConvexPolyhedron reference = ConvexPolyhedron::fromPoints(cloud);
  // Case: a copy outlives its original (its own block, not the original's).
  auto original = std::make_unique<ConvexPolyhedron>(ConvexPolyhedron::fromPoints(cloud));
  const ConvexPolyhedron copy = *original;
  original.reset();
  std::vector<ConvexPolyhedron> churn;  // reuse the freed memory
  for (int k = 0; k < 8; ++k) churn.push_back(ConvexPolyhedron::box(Vector3d::Constant(k), Vector3d::Constant(k + 5)));
  expectSamePiece(copy, reference);
  // Case: copy-assignment into a piece with a larger block, and with a smaller one.
  ConvexPolyhedron larger = wtc::testing::makeShape(wtc::testing::ShapeId::kHull64);
  larger = reference;
  expectSamePiece(larger, reference);
  ConvexPolyhedron smaller = ConvexPolyhedron::fromPoints({Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0)});
  smaller = wtc::testing::makeShape(wtc::testing::ShapeId::kHull64);
  expectSamePiece(smaller, wtc::testing::makeShape(wtc::testing::ShapeId::kHull64));
  // Case: self-assignment keeps the piece.
  ConvexPolyhedron self = reference;
  const ConvexPolyhedron& alias = self;
  self = alias;
  expectSamePiece(self, reference);
  // Case: a move takes the piece and leaves the source empty but usable.
  ConvexPolyhedron source = reference;
  ConvexPolyhedron moved = std::move(source);
  expectSamePiece(moved, reference);
  EXPECT_EQ(source.vertexCount(), 0);  // NOLINT(bugprone-use-after-move): the moved-from state is specified here
  source = churn[3];
  expectSamePiece(source, churn[3]);
  ConvexPolyhedron target = churn[1];
  target = std::move(moved);
  expectSamePiece(target, reference);
  // Case: copies in a growing vector (moved on every reallocation) stay intact.
  std::vector<ConvexPolyhedron> grown;
  for (int k = 0; k < 100; ++k) grown.push_back(k % 2 == 0 ? reference : churn[k % 8]);
  for (int k = 0; k < 100; ++k) expectSamePiece(grown[k], k % 2 == 0 ? reference : churn[k % 8]);
}

}  // namespace convex_polyhedron_test
