#include "scenarios.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include "wtc/base/error.hpp"

namespace wtc::testing {
namespace {

constexpr std::array<const char*, 4> kShapeNames = {"box", "prism", "hull20", "hull64"};
constexpr std::array<const char*, 6> kSetNames = {"mixed", "inside", "face", "edge", "near", "far"};

// Face points are pulled this fraction toward the face's vertex average, so
// they lie strictly inside the face (dimensionless).
constexpr double kFaceShrink = 0.98;
// Edge points stay this fraction of the edge length away from its ends.
constexpr double kEdgeMargin = 0.02;
// Normal-cone weights are drawn from [kConeWeightMin, 1 + kConeWeightMin]: strictly
// positive, so the direction is strictly inside the cone.
constexpr double kConeWeightMin = 0.05;
// Inside points are at least this far below every face plane (x size).
constexpr double kInsideMarginRelative = 1e-9;

// Uniform doubles from a portable engine: the top 53 bits of mt19937_64.
class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }  // [0, 1)
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  int index(int n) { return std::min(n - 1, static_cast<int>(uniform() * n)); }
  // Uniform on the unit sphere, by rejection from the cube.
  Eigen::Vector3d direction() {
    while (true) {
      const Eigen::Vector3d v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      const double n2 = v.squaredNorm();
      if (n2 > 1e-6 && n2 <= 1.0) return v / std::sqrt(n2);
    }
  }

 private:
  std::mt19937_64 engine_;
};

// Surface features of a piece with their outward normal cones, read through
// the public accessors only (independent of the query kernel).
class Surface {
 public:
  explicit Surface(const ConvexPolyhedron& poly) : poly_(poly) {
    std::map<std::pair<int, int>, std::vector<int>> edge_faces;
    vertex_faces_.resize(poly.vertexCount());
    double total = 0.0;
    for (int f = 0; f < poly.faceCount(); ++f) {
      const auto face = poly.faceVertices(f);
      const int n = static_cast<int>(face.size());
      for (int k = 0; k < n; ++k) {
        const int a = face[k];
        const int b = face[(k + 1) % n];
        edge_faces[{std::min(a, b), std::max(a, b)}].push_back(f);
        vertex_faces_[a].push_back(f);
      }
      // Fan triangles, weighted by area for uniform sampling of the surface.
      for (int k = 1; k + 1 < n; ++k) {
        const Eigen::Vector3d a = poly.vertex(face[0]);
        const double area = 0.5 * (poly.vertex(face[k]) - a).cross(poly.vertex(face[k + 1]) - a).norm();
        total += area;
        triangles_.push_back({f, k, total});
      }
    }
    for (auto& [edge, faces] : edge_faces) edges_.push_back({edge.first, edge.second, faces});
  }

  // A uniform point of the surface and its face; `shrink` < 1 pulls it into
  // the face's interior.
  std::pair<Eigen::Vector3d, int> facePoint(Random& random, double shrink) const {
    const double pick = random.uniform() * triangles_.back().cumulative_area;
    const auto it = std::upper_bound(triangles_.begin(), triangles_.end(), pick,
                                     [](double x, const Triangle& t) { return x < t.cumulative_area; });
    const Triangle& t = it == triangles_.end() ? triangles_.back() : *it;
    const auto face = poly_.faceVertices(t.face);
    double u = random.uniform();
    double v = random.uniform();
    if (u + v > 1.0) {  // fold the square onto the triangle
      u = 1.0 - u;
      v = 1.0 - v;
    }
    const Eigen::Vector3d a = poly_.vertex(face[0]);
    const Eigen::Vector3d x = a + u * (poly_.vertex(face[t.corner]) - a) + v * (poly_.vertex(face[t.corner + 1]) - a);
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    for (int i : face) center += poly_.vertex(i);
    center /= static_cast<double>(face.size());
    return {center + shrink * (x - center), t.face};
  }

  // A point of an edge interior or a vertex, and a unit direction strictly
  // inside that feature's normal cone.
  std::pair<Eigen::Vector3d, Eigen::Vector3d> edgeOrVertexPoint(Random& random) const {
    Eigen::Vector3d x;
    const std::vector<int>* faces;
    if (random.uniform() < 0.5) {
      const Edge& e = edges_[random.index(static_cast<int>(edges_.size()))];
      const double t = random.uniform(kEdgeMargin, 1.0 - kEdgeMargin);
      x = poly_.vertex(e.a) + t * (poly_.vertex(e.b) - poly_.vertex(e.a));
      faces = &e.faces;
    } else {
      const int i = random.index(poly_.vertexCount());
      x = poly_.vertex(i);
      faces = &vertex_faces_[i];
    }
    Eigen::Vector3d m = Eigen::Vector3d::Zero();
    for (int f : *faces) m += random.uniform(kConeWeightMin, 1.0 + kConeWeightMin) * poly_.faceNormal(f);
    return {x, m.normalized()};
  }

  // max_i (n_i . p - d_i): negative strictly inside.
  double planeDistance(const Eigen::Vector3d& p) const {
    double worst = -std::numeric_limits<double>::infinity();
    for (int f = 0; f < poly_.faceCount(); ++f) {
      worst = std::max(worst, poly_.faceNormal(f).dot(p) - poly_.faceOffset(f));
    }
    return worst;
  }

 private:
  struct Triangle {
    int face;
    int corner;  // fan triangle (0, corner, corner + 1) of the face
    double cumulative_area;
  };
  struct Edge {
    int a;
    int b;
    std::vector<int> faces;
  };
  const ConvexPolyhedron& poly_;
  std::vector<Triangle> triangles_;
  std::vector<Edge> edges_;
  std::vector<std::vector<int>> vertex_faces_;
};

// A heightfield cell as a terrain builder makes it: one ground triangle of a
// 0.4 m grid (heights 0.12, 0.05, 0.21 m) extruded down to a flat base at
// z = -0.3 m. Top tilted, sides vertical, so two side edges are acute.
// Its corners: the top triangle (0-2), then the base below it (3-5).
std::array<Eigen::Vector3d, 6> prismCorners() {
  const Eigen::Vector3d origin(3.2, -1.6, 0.0);
  const double cell = 0.4;
  const double base = -0.3;
  const std::array<Eigen::Vector3d, 3> top = {Eigen::Vector3d(0.0, 0.0, 0.12), Eigen::Vector3d(cell, 0.0, 0.05),
                                              Eigen::Vector3d(0.0, cell, 0.21)};
  std::array<Eigen::Vector3d, 6> corners;
  for (int i = 0; i < 3; ++i) {
    corners[i] = origin + top[i];
    corners[i + 3] = origin + Eigen::Vector3d(top[i].x(), top[i].y(), base);
  }
  return corners;
}

ConvexPolyhedron makePrism() {
  const std::array<Eigen::Vector3d, 6> c = prismCorners();
  // Top and base corner by corner: the order Qhull has always been given.
  return ConvexPolyhedron::fromPoints({c[0], c[3], c[1], c[4], c[2], c[5]});
}

}  // namespace

const char* toString(ShapeId shape) { return kShapeNames.at(static_cast<std::size_t>(shape)); }
const char* toString(QuerySetId set) { return kSetNames.at(static_cast<std::size_t>(set)); }

std::optional<ShapeId> shapeFromString(std::string_view name) {
  for (ShapeId s : kAllShapes) {
    if (name == toString(s)) return s;
  }
  return std::nullopt;
}

std::optional<QuerySetId> querySetFromString(std::string_view name) {
  for (QuerySetId s : kAllQuerySets) {
    if (name == toString(s)) return s;
  }
  return std::nullopt;
}

ConvexPolyhedron makeEllipsoidHull(int vertex_count, std::uint64_t seed) {
  if (vertex_count < 4) {
    throw InvalidInputError("wtc::testing::makeEllipsoidHull: vertex_count = " + std::to_string(vertex_count) +
                            " is below 4");
  }
  const Eigen::Vector3d semi_axes(0.5, 0.35, 0.2);  // m
  const Eigen::Vector3d center(-2.0, 1.5, 0.1);     // m
  const Eigen::Matrix3d rotation =
      (Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  constexpr double kJitter = 0.03;  // radial, dimensionless
  Random random(seed);
  auto sample = [&] {
    const double radius = 1.0 + kJitter * random.uniform(-1.0, 1.0);
    return Eigen::Vector3d(center + rotation * semi_axes.cwiseProduct(radius * random.direction()));
  };
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < vertex_count; ++i) points.push_back(sample());
  // Hull vertices of S + {q} are among those of S plus q: one point raises
  // the count by at most one, so it reaches vertex_count exactly.
  for (int attempt = 0; attempt < 100 * vertex_count; ++attempt) {
    ConvexPolyhedron hull = ConvexPolyhedron::fromPoints(points);
    if (hull.vertexCount() == vertex_count) return hull;
    points.push_back(sample());
  }
  throw std::logic_error("wtc::testing::makeEllipsoidHull: no hull with " + std::to_string(vertex_count) +
                         " vertices from seed " + std::to_string(seed));
}

ConvexPolyhedron makeShape(ShapeId shape) {
  switch (shape) {
    case ShapeId::kBox:
      return ConvexPolyhedron::box({-0.3, -0.3, -0.4}, {0.7, 0.3, 0.0});
    case ShapeId::kPrism:
      return makePrism();
    case ShapeId::kHull20:
      return makeEllipsoidHull(20, kDefaultSeed);
    case ShapeId::kHull64:
      return makeEllipsoidHull(64, kDefaultSeed);
  }
  throw std::logic_error("wtc::testing::makeShape: unknown shape id");
}

ConvexPolyhedron makeBuildersCell() {
  const std::array<Eigen::Vector3d, 6> c = prismCorners();
  return ConvexPolyhedron::fromMesh({c.begin(), c.end()},
                                    {{0, 1, 2}, {3, 5, 4}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}});
}

std::vector<Eigen::Vector3d> makeQuerySet(const ConvexPolyhedron& poly, QuerySetId set, int count, std::uint64_t seed) {
  const std::string where = std::string("wtc::testing::makeQuerySet(") + toString(set) + "): ";
  if (count < 0) throw InvalidInputError(where + "count = " + std::to_string(count) + " is negative");
  if (poly.isFlat() && (set == QuerySetId::kInside || set == QuerySetId::kEdge)) {
    throw InvalidInputError(where + "needs a solid piece, got a flat one");
  }
  // Each set draws from its own stream, so sets of one seed are independent.
  Random random(seed + 0x9E3779B97F4A7C15ull * (1 + static_cast<std::uint64_t>(set)));
  const Surface surface(poly);
  const double size = poly.size();
  const Aabb& box = poly.bounds();
  auto offset = [&] { return size * random.uniform(kOffsetMinRelative, kOffsetMaxRelative); };

  std::vector<Eigen::Vector3d> points;
  points.reserve(count);
  while (static_cast<int>(points.size()) < count) {
    switch (set) {
      case QuerySetId::kMixed: {
        const Eigen::Vector3d u(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
        points.push_back(box.center() + box.extent().cwiseProduct(u));
        break;
      }
      case QuerySetId::kInside: {
        const Eigen::Vector3d u(random.uniform(), random.uniform(), random.uniform());
        const Eigen::Vector3d p = box.min + box.extent().cwiseProduct(u);
        if (surface.planeDistance(p) < -kInsideMarginRelative * size) points.push_back(p);
        break;
      }
      case QuerySetId::kFace: {
        const auto [x, f] = surface.facePoint(random, kFaceShrink);
        points.push_back(x + offset() * poly.faceNormal(f));
        break;
      }
      case QuerySetId::kEdge: {
        const auto [x, m] = surface.edgeOrVertexPoint(random);
        points.push_back(x + offset() * m);
        break;
      }
      case QuerySetId::kNear: {
        // Two thirds from faces, either side; one third outside edges and vertices.
        if (random.uniform() < 2.0 / 3.0) {
          const auto [x, f] = surface.facePoint(random, 1.0);
          points.push_back(x + random.uniform(-kNearBand, kNearBand) * poly.faceNormal(f));
        } else {
          const auto [x, m] = surface.edgeOrVertexPoint(random);
          points.push_back(x + random.uniform(0.0, kNearBand) * m);
        }
        break;
      }
      case QuerySetId::kFar: {
        const double r = size * kFarMinRelative * std::pow(kFarMaxRelative / kFarMinRelative, random.uniform());
        points.push_back(poly.centroid() + r * random.direction());
        break;
      }
    }
  }
  return points;
}

}  // namespace wtc::testing
