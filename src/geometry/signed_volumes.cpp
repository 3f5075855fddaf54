#include "signed_volumes.hpp"

#include "wtc/base/tolerances.hpp"

#include <cmath>
#include <limits>

namespace wtc::detail {
namespace {

using Eigen::Vector3d;

// A candidate sub-simplex: which of the input vertices it keeps and its
// closest point to the origin.
struct Candidate {
  Vector3d v;
  int keep[3];
  int count;
};

Candidate vertexCandidate(const Vector3d* p, int i) { return {p[i], {i, 0, 0}, 1}; }

// Segment [p[i], p[j]]: the origin's projection on the line, clamped.
Candidate segment(const Vector3d* p, int i, int j) {
  const Vector3d t = p[j] - p[i];
  const double tt = t.squaredNorm();
  const double along = -p[i].dot(t);  // = tt x barycentric weight of p[j]
  if (!(along > 0.0)) return vertexCandidate(p, i);
  if (!(along < tt)) return vertexCandidate(p, j);
  return {p[i] + (along / tt) * t, {i, j, 0}, 2};
}

Candidate better(const Candidate& a, const Candidate& b) { return b.v.squaredNorm() < a.v.squaredNorm() ? b : a; }

// A signed measure below this fraction of the sum of its parts' magnitudes
// has no reliable sign (dimensionless): a flat tetrahedron (four coplanar
// vertices of one face) or a sliver triangle. Then every sub-simplex is
// searched, which is always correct (each candidate is a point of the
// simplex), only slower.
constexpr double kDegenerateRelative = 1e3 * tolerance::kRoundoff;

// Triangle p[i], p[j], p[k].
Candidate triangle(const Vector3d* p, int i, int j, int k) {
  const Vector3d e1 = p[j] - p[i];
  const Vector3d e2 = p[k] - p[i];
  const Vector3d n = e1.cross(e2);
  const double nn = n.squaredNorm();
  if (nn > kDegenerateRelative * e1.squaredNorm() * e2.squaredNorm()) {
    // Projection of the origin on the plane; signed areas of the three
    // sub-triangles against n are its barycentric weights times |n|^2.
    const Vector3d p0 = (n.dot(p[i]) / nn) * n;
    const double wi = (p[j] - p0).cross(p[k] - p0).dot(n);
    const double wj = (p[k] - p0).cross(p[i] - p0).dot(n);
    const double wk = (p[i] - p0).cross(p[j] - p0).dot(n);
    if (wi > 0.0 && wj > 0.0 && wk > 0.0) return {p0, {i, j, k}, 3};
    Candidate best{Vector3d::Constant(std::numeric_limits<double>::infinity()), {0, 0, 0}, 0};
    if (!(wi > 0.0)) best = better(best, segment(p, j, k));
    if (!(wj > 0.0)) best = better(best, segment(p, k, i));
    if (!(wk > 0.0)) best = better(best, segment(p, i, j));
    return best;
  }
  return better(better(segment(p, i, j), segment(p, j, k)), segment(p, k, i));
}

// Signed volume of the tetrahedron (a, b, c, d).
double volume(const Vector3d& a, const Vector3d& b, const Vector3d& c, const Vector3d& d) {
  return (b - a).dot((c - a).cross(d - a));
}

Candidate tetrahedron(const Vector3d* p, bool* enclosed) {
  const Vector3d o = Vector3d::Zero();
  // w[m]: volume with the origin in place of vertex m; their sum is the
  // tetrahedron's volume (Montanari's cofactor expansion of det M).
  const double w[4] = {volume(o, p[1], p[2], p[3]), volume(p[0], o, p[2], p[3]), volume(p[0], p[1], o, p[3]),
                       volume(p[0], p[1], p[2], o)};
  double total = w[0] + w[1] + w[2] + w[3];
  if (std::abs(total) <= kDegenerateRelative * (std::abs(w[0]) + std::abs(w[1]) + std::abs(w[2]) + std::abs(w[3]))) {
    total = 0.0;  // flat: no sign matches, all four faces are searched
  }
  auto same_sign = [total](double x) { return total > 0.0 ? x > 0.0 : (total < 0.0 && x < 0.0); };
  if (same_sign(w[0]) && same_sign(w[1]) && same_sign(w[2]) && same_sign(w[3])) {
    *enclosed = true;
    return {o, {0, 1, 2}, 4};
  }
  static constexpr int kOpposite[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  Candidate best{Vector3d::Constant(std::numeric_limits<double>::infinity()), {0, 0, 0}, 0};
  for (int m = 0; m < 4; ++m) {
    if (!same_sign(w[m])) best = better(best, triangle(p, kOpposite[m][0], kOpposite[m][1], kOpposite[m][2]));
  }
  return best;
}

}  // namespace

Vector3d closestToOrigin(Simplex& s) {
  Candidate c;
  bool enclosed = false;
  switch (s.count) {
    case 1:
      return s.point[0];
    case 2:
      c = segment(s.point, 0, 1);
      break;
    case 3:
      c = triangle(s.point, 0, 1, 2);
      break;
    default:
      c = tetrahedron(s.point, &enclosed);
      if (enclosed) return Vector3d::Zero();
      break;
  }
  if (c.count == s.count) return c.v;  // nothing dropped; keep the order
  // Compact the kept vertices (at most 3) through temporaries: keep[] need
  // not be ascending.
  Vector3d point[3];
  std::int32_t vertex[3];
  for (int m = 0; m < c.count; ++m) {
    point[m] = s.point[c.keep[m]];
    vertex[m] = s.vertex[c.keep[m]];
  }
  for (int m = 0; m < c.count; ++m) {
    s.point[m] = point[m];
    s.vertex[m] = vertex[m];
  }
  s.count = c.count;
  return c.v;
}

}  // namespace wtc::detail
