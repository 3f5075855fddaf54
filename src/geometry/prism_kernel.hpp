#pragma once
// The point query's kernel for the terrain builders' triangular prism
// (piece_kernel.hpp): vertices 0-2 the top triangle, 3-5 the bottom one,
// faces {0, 1, 2}, {3, 5, 4}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}
// (src/terrain/builder_support.cpp builds every prism from these lists): every heightfield cell
// and extruded mesh triangle, stored or formed.
//
// The arithmetic is the general query's; the topology is constant: a face's
// size and first face-edge, an edge's twin and a vertex's three neighbours
// come from the tables below instead of from the piece's lists (the general
// vertex region walks around the vertex through the twins, a search of the
// face starts per step; its answer does not depend on the order of the
// three dot products).
//
// A triangular prism in another labelling (Qhull's: ConvexPolyhedron::
// fromPoints keeps Qhull's order of vertices and faces, which the benchmark
// and test query sets are drawn in) keeps it: its kernel (kLabelledPrism)
// reads its face lists and twins from the piece as the general query does,
// and its vertex neighbours from a table stored with its topology when it is
// built, instead of the general walk around the vertex.
//
// A heightfield's prism also stands upright on a flat bottom: its side faces'
// normals have n_z = 0, its bottom's is (0, 0, -1), and the side planes of
// its vertical and bottom edges have zero components. For it the kernel
// drops those terms from the side-plane tests (kUprightPrism), exactly as
// the box kernel does (box_kernel.hpp says why that is exact; a comparison
// cannot tell a zero's sign). Its face values are the general ones, two
// faces per operation (PolyhedronLayout::planeBoundOf): as few instructions
// as the values without their zero terms, and no zero's sign to restore.
#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "feature_regions.hpp"
#include "polyhedron_layout.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"

namespace wtc::detail {

/// The prism's faces, flat (face f is kPrismList[kPrismStart[f]] up to
/// kPrismStart[f + 1]), counter-clockwise from outside.
inline constexpr std::int32_t kPrismStart[6] = {0, 3, 6, 10, 14, 18};
inline constexpr std::int32_t kPrismList[18] = {0, 1, 2, 3, 5, 4, 0, 3, 4, 1, 1, 4, 5, 2, 2, 5, 3, 0};
inline constexpr int kPrismFaceCount = 5;
inline constexpr int kPrismFaceEdges = 18;
inline constexpr int kPrismVertexCount = 6;
/// A prism's stored arrays at their constant places.
using PrismLayout = PolyhedronLayout::Fixed<kPrismVertexCount, kPrismFaceCount>;
/// A prism's topology at its constant places (any labelling: 5 faces, 18 face-edges).
using PrismTopology = PolyhedronLayout::FixedTopology<kPrismFaceCount, kPrismFaceEdges>;

/// The vertex face-edge e starts at (edge k of a face runs from vertex k - 1
/// to vertex k, cyclically).
constexpr std::int32_t prismEdgeFrom(int e) {
  int f = 0;
  while (kPrismStart[f + 1] <= e) ++f;
  return kPrismList[e == kPrismStart[f] ? kPrismStart[f + 1] - 1 : e - 1];
}

/// Face-edge twins: the same edge, run the other way, in the other face.
inline constexpr std::array<std::int32_t, kPrismFaceEdges> kPrismTwin = [] {
  std::array<std::int32_t, kPrismFaceEdges> twin{};
  for (int e = 0; e < kPrismFaceEdges; ++e) {
    for (int g = 0; g < kPrismFaceEdges; ++g) {
      if (prismEdgeFrom(g) == kPrismList[e] && kPrismList[g] == prismEdgeFrom(e)) twin[e] = g;
    }
  }
  return twin;
}();

/// Each vertex's three neighbours: the vertices that precede it in its faces.
inline constexpr std::array<std::array<std::int32_t, 3>, 6> kPrismNeighbours = [] {
  std::array<std::array<std::int32_t, 3>, 6> around{};
  std::array<int, 6> count{};
  for (int e = 0; e < kPrismFaceEdges; ++e) {
    const std::int32_t at = kPrismList[e];
    around[at][count[at]++] = prismEdgeFrom(e);
  }
  return around;
}();

/// classify for the prism: faces 0 and 1 are triangles, 2 to 4 quads.
inline FaceRegion prismClassify(const ConvexPolyhedron& poly, const Eigen::Vector3d& q, int face) {
  const std::int32_t start = kPrismStart[face];
  const double* side = PrismLayout(poly).sides(start);  // faceEdgePlanes(face)
  if (face < 2) return regionOfMask(kPrismList + start, start, 3, crossedEdges<3>(side, q));
  return regionOfMask(kPrismList + start, start, 4, crossedEdges<4>(side, q));
}

/// edgeRegion for the prism: the twin's side plane from the table.
inline bool prismEdgeRegion(const ConvexPolyhedron& poly, const Eigen::Vector3d& q, const FaceRegion& region,
                            Eigen::Vector3d* closest) {
  if (region.only_edge < 0) return false;
  const double* twin = PrismLayout(poly).sides(kPrismTwin[region.only_edge]);
  return edgeRegionBeyond(poly, q, region, twin, closest);
}

/// vertexRegion for the prism: the vertex's three edges from the table.
inline bool prismVertexRegion(const ConvexPolyhedron& poly, const Eigen::Vector3d& q, const FaceRegion& region,
                              Eigen::Vector3d* closest) {
  if (region.into_vertex < 0) return false;
  const std::int32_t at = region.seed[0];
  const PrismLayout layout(poly);
  const Eigen::Vector3d a = layout.vertex(at);
  const Eigen::Vector3d d = q - a;
  for (const std::int32_t c : kPrismNeighbours[at]) {
    if (d.dot(layout.vertex(c) - a) > 0.0) return false;
  }
  *closest = a;
  return true;
}

/// classify for a prism in its own labelling (kLabelledPrism): a face of 3
/// or 4 edges, its lists read from the piece.
inline FaceRegion labelledPrismClassify(const ConvexPolyhedron& poly, const Eigen::Vector3d& q, int face) {
  const PrismTopology topology(poly);
  const std::int32_t start = topology.start(face);
  const int size = topology.start(face + 1) - start;
  const double* side = PrismLayout(poly).sides(start);  // faceEdgePlanes(face)
  const std::uint32_t mask = size == 3 ? crossedEdges<3>(side, q) : crossedEdges<4>(side, q);
  return regionOfMask(topology.list(start), start, size, mask);
}

/// edgeRegion for a prism in its own labelling: the twin's side plane at
/// its constant place.
inline bool labelledPrismEdgeRegion(const ConvexPolyhedron& poly, const Eigen::Vector3d& q, const FaceRegion& region,
                                    Eigen::Vector3d* closest) {
  if (region.only_edge < 0) return false;
  const double* twin = PrismLayout(poly).sides(PrismTopology(poly).twin(region.only_edge));
  return edgeRegionBeyond(poly, q, region, twin, closest);
}

/// vertexRegion for a prism in its own labelling: the vertex's three
/// neighbours stored with the piece (storeKernelData, piece_kernel.hpp).
inline bool labelledPrismVertexRegion(const ConvexPolyhedron& poly, const Eigen::Vector3d& q, const FaceRegion& region,
                                      Eigen::Vector3d* closest) {
  if (region.into_vertex < 0) return false;
  const std::int32_t at = region.seed[0];
  const std::int32_t* around = PrismTopology(poly).kernelData() + 3 * at;
  const PrismLayout layout(poly);
  const Eigen::Vector3d a = layout.vertex(at);
  const Eigen::Vector3d d = q - a;
  for (int k = 0; k < 3; ++k) {
    if (d.dot(layout.vertex(around[k]) - a) > 0.0) return false;
  }
  *closest = a;
  return true;
}

/// classify for an upright prism: each side plane by the terms it keeps:
/// all three on the top's edges; x and y on the bottom's edges and on the
/// vertical edges (their s is horizontal); z alone on a side face's bottom
/// edge (its s is vertical). A side face's edges run top, vertical, bottom,
/// vertical.
inline FaceRegion uprightPrismClassify(const ConvexPolyhedron& poly, const Eigen::Vector3d& q, int face) {
  const std::int32_t start = kPrismStart[face];
  const double* s = PrismLayout(poly).sides(start);  // faceEdgePlanes(face)
  auto xyz = [&](int k) { return s[4 * k] * q.x() + s[4 * k + 1] * q.y() + s[4 * k + 2] * q.z() < s[4 * k + 3]; };
  auto xy = [&](int k) { return s[4 * k] * q.x() + s[4 * k + 1] * q.y() < s[4 * k + 3]; };
  auto z = [&](int k) { return s[4 * k + 2] * q.z() < s[4 * k + 3]; };
  std::uint32_t mask = 0;
  if (face == 0) {
    mask = crossedEdges<3>(s, q);
    return regionOfMask(kPrismList + start, start, 3, mask);
  }
  if (face == 1) {
    mask = static_cast<std::uint32_t>(xy(0)) | static_cast<std::uint32_t>(xy(1)) << 1 |
           static_cast<std::uint32_t>(xy(2)) << 2;
    return regionOfMask(kPrismList + start, start, 3, mask);
  }
  mask = static_cast<std::uint32_t>(xyz(0)) | static_cast<std::uint32_t>(xy(1)) << 1 |
         static_cast<std::uint32_t>(z(2)) << 2 | static_cast<std::uint32_t>(xy(3)) << 3;
  return regionOfMask(kPrismList + start, start, 4, mask);
}

}  // namespace wtc::detail
