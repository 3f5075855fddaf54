#pragma once
// The stored layout of a ConvexPolyhedron as the query kernels read it
// (point_query.cpp, feature_regions.cpp) and the compact builders fill it
// (formed prisms): structure-of-arrays coordinates in the piece's local
// frame and the face-edge topology (convex_polyhedron.hpp has the layout).
// Internal to wtc::core.
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "wtc/geometry/convex_polyhedron.hpp"

namespace wtc::detail {

struct PolyhedronLayout {
  using P = ConvexPolyhedron;
  static const double* vx(const P& p) { return p.vx(); }
  static const double* vy(const P& p) { return p.vy(); }
  static const double* vz(const P& p) { return p.vz(); }
  static const double* nx(const P& p) { return p.nx(); }
  static const double* ny(const P& p) { return p.ny(); }
  static const double* nz(const P& p) { return p.nz(); }
  static const double* pd(const P& p) { return p.pd(); }
  static const double* faceEdgePlanes(const P& p, int f) { return p.faceEdgePlanes(f); }
  static std::int32_t faceEdgeStart(const P& p, int f) { return p.faceEdgeStart(f); }
  static std::int32_t faceEdgeTwin(const P& p, std::int32_t e) { return p.faceEdgeTwin(e); }
  static int faceOfEdge(const P& p, std::int32_t e) { return p.faceOfEdge(e); }
  /// ConvexPolyhedron::faceEdgeNext, inline: the vertex-region walk takes
  /// it once per edge around the vertex.
  static std::int32_t faceEdgeNext(const P& p, std::int32_t e) {
    const std::int32_t* start = p.topology_;
    if (p.face_count_ > kScanFaces) return p.faceEdgeNext(e);
    int f = 0;
    while (start[f + 1] <= e) ++f;
    return e + 1 < start[f + 1] ? e + 1 : start[f];
  }
  // Up to this many faces faceOfEdge scans the face starts (as
  // ConvexPolyhedron::faceOfEdge does).
  static constexpr int kScanFaces = 16;
  /// Face f's vertex indices (faceVertices(f).data()) and their count,
  /// inline for the query kernels.
  static const std::int32_t* faceVertexList(const P& p, int f) {
    return p.topology_ + p.face_count_ + 1 + p.topology_[f];
  }
  static int faceSize(const P& p, int f) { return p.topology_[f + 1] - p.topology_[f]; }
  static std::int32_t faceEdgeEnd(const P& p, std::int32_t e) { return p.faceEdgeEnd(e); }
  static const double* faceEdgePlane(const P& p, std::int32_t e) { return p.faceEdgePlane(e); }
  /// The piece's numbers and topology, as stored (a terrain's arena copies
  /// them: terrain/piece_arena.hpp).
  static std::span<const double> numbers(const P& p) {
    return {p.numbers_, static_cast<std::size_t>(p.number_count_)};
  }
  static std::span<const std::int32_t> topology(const P& p) {
    return {p.topology_, static_cast<std::size_t>(p.topology_count_)};
  }
  /// Points `p` at copies of its own numbers and topology that outlive it
  /// (a terrain's arena), freeing its block.
  static void useStorage(P& p, const double* numbers, const std::int32_t* topology) {
    p.releaseBlock();
    p.numbers_ = numbers;
    p.topology_ = topology;
  }
  /// The piece's query kernel (detail::PieceKernel), chosen when it was built.
  static std::uint8_t kernel(const P& p) { return p.kernel_; }
  /// The same piece answered by the general query: for the tests that hold
  /// a kernel's answers to the general ones, bit for bit.
  static void useGeneralKernel(P& p) { p.kernel_ = 0; }
  static int supportLocal(const P& p, const Eigen::Vector3d& dir, int hint) { return p.supportLocal(dir, hint); }
  /// The face-plane bound, inline for the pieces a terrain forms (a
  /// heightfield prism or an extruded triangle has 5 faces, a box 6): the
  /// query's first step, on its critical path.
  static double planeBoundLocal(const P& p, const Eigen::Vector3d& q, int* face) {
    switch (p.face_count_) {
      case 5:
        return planeBoundOf<5>(p, q, face);
      case 6:
        return planeBoundOf<6>(p, q, face);
      default:
        return p.planeBoundLocal(q, face);
    }
  }
  /// max_i (n_i . q - d_i) and its face over exactly N faces, unrolled: the
  /// same scan and arithmetic as ConvexPolyhedron::planeBoundLocal's.
  template <int N>
  static double planeBoundOf(const P& p, const Eigen::Vector3d& q, int* face) {
    const double* a = p.nx();
    const double* b = p.ny();
    const double* c = p.nz();
    const double* d = p.pd();
    int best = 0;
    double best_value = a[0] * q.x() + b[0] * q.y() + c[0] * q.z() - d[0];
#pragma GCC unroll 8
    for (int f = 1; f < N; ++f) {
      const double value = a[f] * q.x() + b[f] * q.y() + c[f] * q.z() - d[f];
      const bool better = value > best_value;  // branch-free, as in supportLocal
      best = better ? f : best;
      best_value = better ? value : best_value;
    }
    if (face != nullptr) *face = best;
    return best_value;
  }

  /// The largest of N face values and the first face that has it: the
  /// scan planeBoundOf makes, over values a kernel computed its own way
  /// (box_kernel.hpp, prism_kernel.hpp).
  template <int N>
  static double firstLargest(const double (&value)[N], int* face) {
    int best = 0;
    double best_value = value[0];
#pragma GCC unroll 8
    for (int f = 1; f < N; ++f) {
      const bool better = value[f] > best_value;  // branch-free, as in planeBoundOf
      best = better ? f : best;
      best_value = better ? value[f] : best_value;
    }
    *face = best;
    return best_value;
  }

  /// A piece with the same face list as `like` (and as many vertices), built
  /// from `vertices` with like's topology copied instead of matched anew: the
  /// same piece, bit for bit, as fromMesh(vertices, faces) would build (for
  /// pieces formed by the million: compact heightfields and meshes). The
  /// caller vouches that the faces are planar (fromMesh checks it; zero
  /// areas and a missing volume are still refused).
  static ConvexPolyhedron sameTopologyAs(const ConvexPolyhedron& like, const std::vector<Eigen::Vector3d>& vertices,
                                         const std::vector<std::vector<int>>& faces);
  /// The same piece made into `into`, reusing its buffers (no allocation when
  /// `into` had as many vertices, faces and face edges).
  static void sameTopologyInto(ConvexPolyhedron& into, const ConvexPolyhedron& like,
                               const std::vector<Eigen::Vector3d>& vertices,
                               const std::vector<std::vector<int>>& faces);
};

}  // namespace wtc::detail
