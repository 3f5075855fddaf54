#include "brute_force.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

namespace wtc::testing {
namespace {

// Extended precision for the oracle (see the header).
using Real = long double;
using Vec = Eigen::Matrix<Real, 3, 1>;

// Ericson 5.1.2: the point of segment ab closest to p. t is clamped to
// [0, 1]; a zero-length segment is its own closest point.
Vec closestOnSegment(const Vec& p, const Vec& a, const Vec& b) {
  const Vec ab = b - a;
  const Real length2 = ab.squaredNorm();
  if (length2 == 0) return a;
  const Real t = std::clamp((p - a).dot(ab) / length2, Real(0), Real(1));
  return a + t * ab;
}

// Ericson 5.1.5, first method: the projection of p on the triangle's plane if
// it falls inside the triangle, otherwise the closest boundary point. The
// inside test uses the edge functions n . (edge x (p - start)), which are
// products of small and large vectors only (Ericson's d1*d4 - d3*d2 form
// cancels catastrophically for far points). Zero-area triangles have no
// interior and reduce to their edges.
Vec closestOnTriangle(const Vec& p, const Vec& a, const Vec& b, const Vec& c) {
  const Vec n = (b - a).cross(c - a);
  const Real n2 = n.squaredNorm();
  if (n2 > 0) {
    const Real ea = n.dot((c - b).cross(p - b));  // opposite a
    const Real eb = n.dot((a - c).cross(p - c));  // opposite b
    const Real ec = n.dot((b - a).cross(p - a));  // opposite c
    if (ea >= 0 && eb >= 0 && ec >= 0) {
      // Barycentric coordinates of the projection; they sum to 1 exactly
      // in exact arithmetic, so normalise by their sum.
      const Real sum = ea + eb + ec;
      if (sum > 0) return (ea * a + eb * b + ec * c) / sum;
    }
  }
  Vec best = closestOnSegment(p, a, b);
  for (const Vec& candidate : {closestOnSegment(p, b, c), closestOnSegment(p, c, a)}) {
    if ((candidate - p).squaredNorm() < (best - p).squaredNorm()) best = candidate;
  }
  return best;
}

}  // namespace

// Named, not in the anonymous namespace: BruteForceOracle::Faces, a member of
// a class with linkage, holds it.
struct OracleFace {
  std::vector<Vec> vertices;  // relative to the reference point
  Vec normal;                 // unit, outward (Newell)
  Real offset = 0;            // max over the face's vertices of normal . v
};

namespace {

struct Nearest {
  Vec point = Vec::Zero();
  Real distance2 = std::numeric_limits<Real>::infinity();
  int face = -1;
};

// The closest point over every fan triangle of every face.
Nearest nearestOnSurface(const std::vector<OracleFace>& faces, const Vec& q) {
  Nearest nearest;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const std::vector<Vec>& v = faces[f].vertices;
    for (std::size_t k = 1; k + 1 < v.size(); ++k) {
      const Vec candidate = closestOnTriangle(q, v[0], v[k], v[k + 1]);
      const Real distance2 = (candidate - q).squaredNorm();
      if (distance2 < nearest.distance2) {
        nearest = {candidate, distance2, static_cast<int>(f)};
      }
    }
  }
  return nearest;
}

}  // namespace

struct BruteForceOracle::Faces {
  // Any point of the piece serves as the reference: in long double the
  // subtraction loses nothing that matters. Vertex 0 depends on the least of
  // the piece's own machinery.
  Vec reference;
  bool flat = false;
  std::vector<OracleFace> faces;
};

BruteForceOracle::BruteForceOracle(const ConvexPolyhedron& poly) : faces_(std::make_unique<Faces>()) {
  faces_->reference = poly.vertex(0).cast<Real>();
  faces_->flat = poly.isFlat();
  faces_->faces.resize(poly.faceCount());
  for (int f = 0; f < poly.faceCount(); ++f) {
    OracleFace& face = faces_->faces[f];
    for (const std::int32_t i : poly.faceVertices(f)) {
      face.vertices.push_back(poly.vertex(i).cast<Real>() - faces_->reference);
    }
    // Newell's method: the area vector of a planar polygon is the sum of its
    // fan triangles' cross products; robust for nearly collinear vertices.
    Vec area = Vec::Zero();
    const Vec& v0 = face.vertices.front();
    for (std::size_t k = 1; k + 1 < face.vertices.size(); ++k) {
      area += (face.vertices[k] - v0).cross(face.vertices[k + 1] - v0);
    }
    face.normal = area.normalized();
    face.offset = -std::numeric_limits<Real>::infinity();
    for (const Vec& v : face.vertices) face.offset = std::max(face.offset, face.normal.dot(v));
  }
}

BruteForceOracle::~BruteForceOracle() = default;
BruteForceOracle::BruteForceOracle(BruteForceOracle&&) noexcept = default;
BruteForceOracle& BruteForceOracle::operator=(BruteForceOracle&&) noexcept = default;

BruteForceResult BruteForceOracle::query(const Eigen::Vector3d& p) const {
  const std::vector<OracleFace>& faces = faces_->faces;
  const Vec q = p.cast<Real>() - faces_->reference;
  BruteForceResult result;
  if (!faces_->flat) {
    Real max_height = -std::numeric_limits<Real>::infinity();
    int max_face = -1;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const Real height = faces[f].normal.dot(q) - faces[f].offset;
      if (height > max_height) {
        max_height = height;
        max_face = static_cast<int>(f);
      }
    }
    if (max_height < 0) {
      const Vec projected = q - max_height * faces[max_face].normal;
      result.signed_distance = static_cast<double>(max_height);
      result.closest_point = (projected + faces_->reference).cast<double>();
      result.face = max_face;
      result.inside = true;
      return result;
    }
  }
  const Nearest nearest = nearestOnSurface(faces, q);
  result.signed_distance = static_cast<double>(std::sqrt(nearest.distance2));
  result.closest_point = (nearest.point + faces_->reference).cast<double>();
  result.face = nearest.face;
  return result;
}

double BruteForceOracle::surfaceDistance(const Eigen::Vector3d& p) const {
  const Nearest nearest = nearestOnSurface(faces_->faces, p.cast<Real>() - faces_->reference);
  return static_cast<double>(std::sqrt(nearest.distance2));
}

BruteForceResult bruteForceQuery(const ConvexPolyhedron& poly, const Eigen::Vector3d& p) {
  return BruteForceOracle(poly).query(p);
}

}  // namespace wtc::testing
