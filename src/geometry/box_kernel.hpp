#pragma once
// The point query's kernel for an axis-aligned box (piece_kernel.hpp):
// ConvexPolyhedron::box's layout, faces -x, +x, -y, +y, -z, +z, vertex i
// with bit 0 for x, 1 for y, 2 for z.
//
// Why dropping the zero terms is exact: the general face value is
// ((n_x q_x + n_y q_y) + n_z q_z) - d; a term 0 * q is +-0, and x + (+-0) is
// x for x != 0. Where the kept product is itself a zero, the sum is a zero of
// either sign; a comparison cannot tell the two zeros apart, and a zero minus
// d (d != 0, checked when the kernel is chosen) is -d either way. So:
// - face values +-q_axis - d: one subtraction each instead of three
//   products and three sums;
// - an edge's side plane has one non-zero component: one product per
//   crossed-edge test;
// - vertex a's neighbours are a ^ 1, a ^ 2, a ^ 4: the vertex region tests
//   them directly, the same three dot products the general walk around the
//   vertex takes (the answer does not depend on their order), without the
//   walk's topology lookups.
#include <cstdint>

#include <Eigen/Core>

#include "feature_regions.hpp"
#include "polyhedron_layout.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"

namespace wtc::detail {

/// The face lists of ConvexPolyhedron::box, counter-clockwise from outside:
/// -x, +x, -y, +y, -z, +z.
inline constexpr int kBoxFaces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                        {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};

/// A box's stored arrays at their constant places (8 vertices, 6 faces).
using BoxLayout = PolyhedronLayout::Fixed<8, 6>;

/// The axis of the one non-zero component of the side plane of edge k of
/// box face f: neither the face's axis nor the edge's (s = n x (b - a)).
constexpr int boxSideAxis(int f, int k) {
  const int changed = kBoxFaces[f][(k + 3) % 4] ^ kBoxFaces[f][k];  // one bit: the edge's axis
  const int edge_axis = changed == 1 ? 0 : changed == 2 ? 1 : 2;
  return 3 - f / 2 - edge_axis;
}

/// The plane bound of an axis-aligned box: the general scan's values and
/// choice (the first face of the largest value).
inline double boxPlaneBound(const ConvexPolyhedron& poly, const Eigen::Vector3d& q, int* face) {
  const double* d = BoxLayout(poly).pd();
  const double value[6] = {-q.x() - d[0], q.x() - d[1], -q.y() - d[2], q.y() - d[3], -q.z() - d[4], q.z() - d[5]};
  return PolyhedronLayout::firstLargest<6>(value, face);
}

/// classify for an axis-aligned box: each side plane s . q < s . a by its
/// one non-zero product.
inline FaceRegion boxClassify(const ConvexPolyhedron& poly, const Eigen::Vector3d& q, int face) {
  static constexpr std::uint8_t kAxis[6][4] = {
      {boxSideAxis(0, 0), boxSideAxis(0, 1), boxSideAxis(0, 2), boxSideAxis(0, 3)},
      {boxSideAxis(1, 0), boxSideAxis(1, 1), boxSideAxis(1, 2), boxSideAxis(1, 3)},
      {boxSideAxis(2, 0), boxSideAxis(2, 1), boxSideAxis(2, 2), boxSideAxis(2, 3)},
      {boxSideAxis(3, 0), boxSideAxis(3, 1), boxSideAxis(3, 2), boxSideAxis(3, 3)},
      {boxSideAxis(4, 0), boxSideAxis(4, 1), boxSideAxis(4, 2), boxSideAxis(4, 3)},
      {boxSideAxis(5, 0), boxSideAxis(5, 1), boxSideAxis(5, 2), boxSideAxis(5, 3)}};
  const double* side = BoxLayout(poly).sides(4 * face);  // faceEdgePlanes(face): 4 edges a face
  const std::uint8_t* axis = kAxis[face];
  std::uint32_t mask = 0;
#pragma GCC unroll 4
  for (int k = 0; k < 4; ++k, side += 4) {
    const bool beyond = side[axis[k]] * q[axis[k]] < side[3];
    mask |= static_cast<std::uint32_t>(beyond) << k;
  }
  return regionOfMask(kBoxFaces[face], 4 * face, 4, mask);  // the lists isAxisBox checked
}

/// vertexRegion for an axis-aligned box: vertex a's three edges lead to
/// a ^ 1, a ^ 2 and a ^ 4.
inline bool boxVertexRegion(const ConvexPolyhedron& poly, const Eigen::Vector3d& q, const FaceRegion& region,
                            Eigen::Vector3d* closest) {
  if (region.into_vertex < 0) return false;
  const int at = region.seed[0];
  const BoxLayout layout(poly);
  const Eigen::Vector3d a = layout.vertex(at);
  const Eigen::Vector3d d = q - a;
  if (d.dot(layout.vertex(at ^ 1) - a) > 0.0) return false;
  if (d.dot(layout.vertex(at ^ 2) - a) > 0.0) return false;
  if (d.dot(layout.vertex(at ^ 4) - a) > 0.0) return false;
  *closest = a;
  return true;
}

}  // namespace wtc::detail
