#pragma once
// The closest point of a triangle to a point, in closed form (internal to
// wtc::core), with the feature it lies on: the face, an edge or a vertex.
//
// Ericson, Real-Time Collision Detection (2005), section 5.1.5: the point's
// Voronoi region is found from the signs of six dot products and two
// cross-product terms, then the point is projected on that feature. About
// forty flops, no loop: how a compact heightfield's surface triangle is
// answered (src/contact/field_surface.hpp) instead of the modified GJK on
// its prism.
#include <cstdint>

#include <Eigen/Core>

namespace wtc::detail {

/// The feature of triangle (a, b, c) a closest point lies on.
enum class TriangleFeature : std::uint8_t { kFace, kVertexA, kVertexB, kVertexC, kEdgeAB, kEdgeBC, kEdgeCA };

struct TriangleClosestPoint {
  Eigen::Vector3d point;
  TriangleFeature feature = TriangleFeature::kFace;
};

// Always inlined: the search answers dozens a step, a cell's two triangles
// together (they share a corner and the diagonal), with no call for each
// and the sums the two have in common free to be shared (docs/terrain.md).
[[gnu::always_inline]] inline TriangleClosestPoint closestOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                                                     const Eigen::Vector3d& b,
                                                                     const Eigen::Vector3d& c) {
  using F = TriangleFeature;
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {a, F::kVertexA};
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {b, F::kVertexB};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return {a + (d1 / (d1 - d3)) * ab, F::kEdgeAB};
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {c, F::kVertexC};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return {a + (d2 / (d2 - d6)) * ac, F::kEdgeCA};
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    return {b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b), F::kEdgeBC};
  }
  const double denom = 1.0 / (va + vb + vc);
  return {a + ab * (vb * denom) + ac * (vc * denom), F::kFace};
}

}  // namespace wtc::detail
