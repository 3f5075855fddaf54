#include "random_pieces.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <sstream>

#include "wtc/base/error.hpp"

namespace wtc::test {

using Eigen::Vector3d;

Vector3d RandomPieces::onUnitSphere() {
  std::normal_distribution<> normal;
  Vector3d v;
  do {
    v = {normal(engine_), normal(engine_), normal(engine_)};
  } while (v.norm() < 1e-6);
  return v.normalized();
}

Vector3d RandomPieces::inUnitBall() { return onUnitSphere() * std::cbrt(uniform(0.0, 1.0)); }

Eigen::Matrix3d RandomPieces::rotation() {
  std::normal_distribution<> normal;
  Eigen::Quaterniond q(normal(engine_), normal(engine_), normal(engine_), normal(engine_));
  return q.normalized().toRotationMatrix();
}

std::vector<Vector3d> RandomPieces::place(std::vector<Vector3d> points, std::string& kind) {
  const double scale = std::pow(10.0, uniform(-3.0, 3.0));
  const Eigen::Matrix3d rotation_WL = rotation();
  const Vector3d p_WO = scale * Vector3d(uniform(-100, 100), uniform(-100, 100), uniform(-100, 100));
  for (Vector3d& p : points) p = rotation_WL * (scale * p) + p_WO;
  std::ostringstream out;
  out << kind << ", scale " << scale << " m";
  kind = out.str();
  return points;
}

// fromPoints on generated points; should it throw, the points go into the
// message so that the failure can be reproduced outside the random run.
RandomPiece hullOf(std::vector<Vector3d> points, std::string kind) {
  try {
    ConvexPolyhedron poly = ConvexPolyhedron::fromPoints(points);
    return {std::move(poly), std::move(kind), std::move(points)};
  } catch (const InvalidInputError& error) {
    std::ostringstream out;
    out.precision(17);
    out << error.what() << "\n  fromPoints input (" << kind << "): {";
    for (std::size_t i = 0; i < points.size(); ++i) {
      out << (i ? ", " : "") << "{" << points[i].x() << ", " << points[i].y() << ", " << points[i].z() << "}";
    }
    out << "}";
    throw InvalidInputError(out.str());
  }
}

RandomPiece RandomPieces::hull(int count) {
  std::vector<Vector3d> points;
  std::string kind;
  const int distribution = uniformInt(0, 4);
  if (distribution == 0 || (distribution == 4 && count < 8)) {
    kind = "ball";
    for (int i = 0; i < count; ++i) points.push_back(inUnitBall());
  } else if (distribution == 1) {
    kind = "sphere";
    for (int i = 0; i < count; ++i) points.push_back(onUnitSphere());
  } else if (distribution == 2) {
    kind = "ellipsoid";
    const Vector3d axes(1.0, uniform(0.01, 1.0), uniform(0.01, 1.0));
    for (int i = 0; i < count; ++i) points.push_back(inUnitBall().cwiseProduct(axes));
  } else if (distribution == 3) {
    // Integer grid: many exactly coplanar and duplicate points. The first
    // four span a tetrahedron so that the set is never degenerate.
    kind = "grid";
    points = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2}};
    for (int i = 4; i < count; ++i) {
      points.emplace_back(uniformInt(0, 2), uniformInt(0, 2), uniformInt(0, 2));
    }
  } else {
    kind = "cube corners and face points";
    for (int i = 0; i < 8; ++i) points.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    for (int i = 8; i < count; ++i) {
      Vector3d p(uniform(0, 1), uniform(0, 1), uniform(0, 1));
      p[uniformInt(0, 2)] = uniformInt(0, 1);  // on a face of the cube
      points.push_back(p);
    }
  }
  kind = "hull of " + std::to_string(count) + " points (" + kind + ")";
  points = place(std::move(points), kind);
  return hullOf(std::move(points), std::move(kind));
}

RandomPiece RandomPieces::box() {
  const Vector3d extent(std::pow(10.0, uniform(-1, 1)), std::pow(10.0, uniform(-1, 1)), std::pow(10.0, uniform(-1, 1)));
  std::string kind = "box";
  if (uniformInt(0, 1) == 0) {
    const double scale = std::pow(10.0, uniform(-3.0, 3.0));
    const Vector3d min = scale * Vector3d(uniform(-100, 100), uniform(-100, 100), uniform(-100, 100));
    return {ConvexPolyhedron::box(min, min + scale * extent),
            kind + ", axis-aligned, scale " + std::to_string(scale) + " m",
            {}};
  }
  std::vector<Vector3d> corners;
  for (int i = 0; i < 8; ++i) {
    corners.emplace_back((i & 1) * extent.x(), ((i >> 1) & 1) * extent.y(), ((i >> 2) & 1) * extent.z());
  }
  corners = place(std::move(corners), kind);
  return hullOf(std::move(corners), kind + ", rotated");
}

RandomPiece RandomPieces::prism() {
  const double cx = uniform(-0.5, 1.0);
  const double cy = uniform(0.3, 1.0);
  std::vector<Vector3d> points = {{0, 0, 0}, {1, 0, 0}, {cx, cy, 0}};
  for (int i = 0; i < 3; ++i) {
    points.push_back(points[i] + Vector3d(0, 0, 1.0 + uniform(-0.5, 0.5)));
  }
  std::string kind = "prism";
  points = place(std::move(points), kind);
  return hullOf(std::move(points), std::move(kind));
}

RandomPiece RandomPieces::flatPolygon(int count) {
  const double aspect = uniform(0.05, 1.0);
  std::vector<Vector3d> points;
  for (int i = 0; i < count; ++i) {
    const double angle = uniform(0.0, 2.0 * M_PI);
    const double radius = i < 3 ? 1.0 : uniform(0.5, 1.0);
    points.emplace_back(radius * std::cos(angle), aspect * radius * std::sin(angle), 0.0);
  }
  std::string kind = "flat polygon of " + std::to_string(count) + " points";
  points = place(std::move(points), kind);
  return hullOf(std::move(points), std::move(kind));
}

RandomPiece RandomPieces::any() {
  const int pick = uniformInt(0, 19);
  if (pick < 12) return hull(uniformInt(4, 100));
  if (pick < 15) return box();
  if (pick < 18) return prism();
  return flatPolygon(uniformInt(3, 20));
}

Vector3d RandomPieces::pointOnFace(const ConvexPolyhedron& poly, int face) {
  const auto vertices = poly.faceVertices(face);
  Vector3d sum = Vector3d::Zero();
  double weight_sum = 0.0;
  std::exponential_distribution<> weight;
  for (const std::int32_t i : vertices) {
    const double w = weight(engine_);
    sum += w * poly.vertex(i);
    weight_sum += w;
  }
  return sum / weight_sum;
}

Vector3d RandomPieces::query(const ConvexPolyhedron& poly) {
  const double size = poly.size();
  const int face = uniformInt(0, poly.faceCount() - 1);
  const auto face_vertices = poly.faceVertices(face);
  const int k = uniformInt(0, static_cast<int>(face_vertices.size()) - 1);
  const Vector3d a = poly.vertex(face_vertices[k]);
  const Vector3d b = poly.vertex(face_vertices[(k + 1) % face_vertices.size()]);
  const Vector3d on_edge = a + uniform(0, 1) * (b - a);
  const double hair = size * std::pow(10.0, uniform(-12, -1));
  switch (uniformInt(0, 8)) {
    case 0:  // uniform in a box twice the piece's size
      return poly.bounds().center() +
             poly.bounds().extent().cwiseProduct(Vector3d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)));
    case 1:  // on a face
      return pointOnFace(poly, face);
    case 2:  // a hair off a face, either side
      return pointOnFace(poly, face) + hair * (uniformInt(0, 1) ? 1 : -1) * poly.faceNormal(face);
    case 3:  // exactly a vertex
      return a;
    case 4:  // on an edge
      return on_edge;
    case 5:  // a hair off an edge, any direction
      return on_edge + hair * onUnitSphere();
    case 6: {  // inside: a convex combination of vertices
      Vector3d p = Vector3d::Zero();
      double total = 0.0;
      for (int i = 0; i < 4; ++i) {
        const double w = uniform(0, 1);
        p += w * poly.vertex(uniformInt(0, poly.vertexCount() - 1));
        total += w;
      }
      return p / total;
    }
    case 7:  // far away
      return poly.bounds().center() + size * std::pow(10.0, uniform(1, 3)) * onUnitSphere();
    default:  // near the surface, within 1 mm-equivalent of the piece's size
      return pointOnFace(poly, face) + size * 1e-3 * inUnitBall();
  }
}

std::string describe(const ConvexPolyhedron& poly) {
  std::ostringstream out;
  out.precision(17);
  out << (poly.isFlat() ? "flat " : "") << "piece of size " << poly.size() << " m:\n  vertices {";
  for (int i = 0; i < poly.vertexCount(); ++i) {
    const Vector3d v = poly.vertex(i);
    out << (i ? ", " : "") << "{" << v.x() << ", " << v.y() << ", " << v.z() << "}";
  }
  out << "}\n  faces {";
  for (int f = 0; f < poly.faceCount(); ++f) {
    out << (f ? ", " : "") << "{";
    const auto vertices = poly.faceVertices(f);
    for (std::size_t k = 0; k < vertices.size(); ++k) out << (k ? ", " : "") << vertices[k];
    out << "}";
  }
  out << "}";
  return out.str();
}

}  // namespace wtc::test
