#pragma once
// The stored layout of a ConvexPolyhedron as the query kernels read it
// (point_query.cpp, feature_regions.cpp) and the compact builders fill it
// (formed prisms): structure-of-arrays coordinates in the piece's local
// frame and the face-edge topology (convex_polyhedron.hpp has the layout).
// Internal to wtc::core.
#include <cstdint>
#include <span>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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
  /// Appends `count` entries of kernel data to the topology being built in
  /// `topology` (the piece's view, before its block is made: assembleInto),
  /// after the twins (the piece has no adjacency lists there: a small
  /// piece); a kLabelledPrism keeps vertex i's three neighbours at 3 i
  /// (FixedTopology::kernelData).
  static void appendKernelData(P& p, std::vector<std::int32_t>& topology, const std::int32_t* data, int count) {
    topology.insert(topology.end(), data, data + count);
    p.topology_ = topology.data();
    p.topology_count_ = static_cast<std::int32_t>(topology.size());
  }
  static bool hasAdjacency(const P& p) { return p.has_adjacency_; }
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
  /// A piece with no vertices, owning nothing: a place a piece is made into
  /// later (a terrain's pending prisms, a scratch piece).
  static P empty() { return P{}; }
  /// Makes `p` the piece `shape` is, its numbers and topology the copies at
  /// `numbers` and `topology` that outlive it (a terrain's arena), owning no
  /// block.
  static void adoptShape(P& p, const P& shape, const double* numbers, const std::int32_t* topology) {
    p.releaseBlock();
    p.copyShape(shape);
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
  /// max_i (n_i . q - d_i) and its face over exactly N faces: the same
  /// values and choice as ConvexPolyhedron::planeBoundLocal's scan. Two faces
  /// per SSE2 operation: a packed product or sum rounds each lane as the
  /// scalar one does, in the same order ((n_x q_x + n_y q_y) + n_z q_z) - d,
  /// so every value is the scan's to the bit. For odd N the last pair's
  /// second lane reads the next array's first number (nx is followed by ny,
  /// ..., pd by the side planes) and is not used.
  template <int N>
  static double planeBoundOf(const P& p, const Eigen::Vector3d& q, int* face) {
    return planeBoundAt<N>(p.nx(), q, face);
  }
  /// planeBoundOf from the face arrays [nx | ny | nz | pd] of N faces each
  /// at `normals` (for a kernel: at a constant offset, Fixed::nx).
  template <int N>
  static double planeBoundAt(const double* normals, const Eigen::Vector3d& q, int* face) {
    static_assert(N >= 2 && N <= 8);
    const double* a = normals;
    const double* b = a + N;
    const double* c = b + N;
    const double* d = c + N;
    double value[N + 1];
#if defined(__SSE2__)
    const __m128d qx = _mm_set1_pd(q.x());
    const __m128d qy = _mm_set1_pd(q.y());
    const __m128d qz = _mm_set1_pd(q.z());
#pragma GCC unroll 4
    for (int f = 0; f < N; f += 2) {
      const __m128d xy = _mm_add_pd(_mm_mul_pd(_mm_loadu_pd(a + f), qx), _mm_mul_pd(_mm_loadu_pd(b + f), qy));
      _mm_storeu_pd(value + f, _mm_sub_pd(_mm_add_pd(xy, _mm_mul_pd(_mm_loadu_pd(c + f), qz)), _mm_loadu_pd(d + f)));
    }
#else
    for (int f = 0; f < N; ++f) value[f] = a[f] * q.x() + b[f] * q.y() + c[f] * q.z() - d[f];
#endif
    int best = 0;
    const double best_value = firstLargest<N>(value, &best);
    if (face != nullptr) *face = best;
    return best_value;
  }

  /// The largest of the first N values and the first of them that has it:
  /// the scan planeBoundOf makes, over values a kernel computed its own way
  /// (box_kernel.hpp, prism_kernel.hpp). Branch-free, as in supportLocal.
  template <int N>
  static double firstLargest(const double* value, int* face) {
    int best = 0;
    double best_value = value[0];
#pragma GCC unroll 8
    for (int f = 1; f < N; ++f) {
      const bool better = value[f] > best_value;
      best = better ? f : best;
      best_value = better ? value[f] : best_value;
    }
    *face = best;
    return best_value;
  }

  /// A kernel's view of a piece of V vertices and F faces (counts its kind
  /// fixes): the stored arrays at constant offsets from the one allocation,
  /// without reading the counts.
  template <int V, int F>
  struct Fixed {
    explicit Fixed(const P& p) : numbers(p.numbers_) {}
    const double* nx() const { return numbers + 3 * V; }
    const double* pd() const { return numbers + 3 * V + 3 * F; }
    /// Side planes of the face-edges from face-edge `e` on (faceEdgePlane).
    const double* sides(std::int32_t e) const { return numbers + 3 * V + 4 * F + 4 * e; }
    Eigen::Vector3d vertex(int i) const { return {numbers[i], numbers[V + i], numbers[2 * V + i]}; }
    const double* numbers;
  };

  /// The topology of a piece of F faces and E face-edges (counts its kind
  /// fixes), at constant offsets: [face starts (F + 1) | face lists (E) |
  /// twins (E) | kernel data].
  template <int F, int E>
  struct FixedTopology {
    explicit FixedTopology(const P& p) : topology(p.topology_) {}
    std::int32_t start(int f) const { return topology[f]; }
    const std::int32_t* list(std::int32_t start) const { return topology + F + 1 + start; }
    std::int32_t twin(std::int32_t e) const { return topology[F + 1 + E + e]; }
    const std::int32_t* kernelData() const { return topology + F + 1 + 2 * E; }
    const std::int32_t* topology;
  };

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
