#pragma once
// A convex piece of ground: an immutable description, built once and queried
// millions of times.
//
// Layout, for speed and precision:
// - Vertices and face planes are stored relative to a local origin (the
//   centre of the bounding box). A 1 mm feature 1e6 m from the world origin
//   keeps all its significant digits: only the query point is translated,
//   once per query.
// - Coordinates are structure-of-arrays (all x, then all y, then all z) in
//   one allocation, so the support scan and the face-plane scan are straight
//   loops over contiguous doubles that the compiler vectorises. Topology
//   (face vertex lists, vertex adjacency) follows the numbers in the same
//   block: one allocation per piece. A terrain moves its pieces' blocks
//   into one arena of its own (docs/terrain.md); a copy of any piece owns
//   its block, and is independent of the piece and terrain it came from.
// - Face planes are unit normals n_i with offsets d_i = max_v n_i . v over all
//   vertices, so every vertex satisfies n_i . v <= d_i exactly: the bound
//   max_i (n_i . p - d_i) is a true lower bound on the distance outside and
//   the exact signed distance inside, even for merged, nearly coplanar faces.
//
// Flat pieces. Three or more coplanar points (thickness below
// tolerance::kFlatRelative x size) make a valid flat piece: a convex polygon
// with two faces of opposite normals. Its signed distance is never negative;
// a point on the polygon is at distance 0. Fewer than three non-collinear
// points is an InvalidInputError: a segment or a point is not ground.
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "wtc/geometry/aabb.hpp"

namespace wtc {

class ConvexPolyhedron;
namespace detail {
struct PolyhedronLayout;  // the query kernels' view of the stored layout (src/geometry/polyhedron_layout.hpp)
}  // namespace detail

class ConvexPolyhedron {
 public:
  ConvexPolyhedron(const ConvexPolyhedron& other);
  ConvexPolyhedron(ConvexPolyhedron&& other) noexcept;
  ConvexPolyhedron& operator=(const ConvexPolyhedron& other);
  ConvexPolyhedron& operator=(ConvexPolyhedron&& other) noexcept;
  ~ConvexPolyhedron();

  /// The convex hull of `points` (Qhull). Duplicate and nearly duplicate
  /// points (closer than tolerance::kHullMergeRelative x size) and points
  /// inside the hull or on its faces are dropped; coplanar triangles merge
  /// into one polygonal face. Throws InvalidInputError for an empty set, a
  /// non-finite point (named by index) or fewer than three non-collinear
  /// points.
  static ConvexPolyhedron fromPoints(const std::vector<Eigen::Vector3d>& points);

  /// A trusted vertex and face list: each face lists its vertex indices
  /// counter-clockwise seen from outside. No hull is computed (this is the
  /// fast path the terrain builders use), but the input is still checked:
  /// finite vertices, valid indices, faces of >= 3 vertices, a closed
  /// surface (every edge shared by two faces in opposite directions),
  /// outward planar faces and convexity (every vertex on or below every face plane, within
  /// tolerance::kHullMergeRelative x size). Violations throw
  /// InvalidInputError naming the face or vertex.
  static ConvexPolyhedron fromMesh(const std::vector<Eigen::Vector3d>& vertices,
                                   const std::vector<std::vector<int>>& faces);

  /// An axis-aligned box [min, max] (m). Throws unless min < max.
  static ConvexPolyhedron box(const Eigen::Vector3d& min, const Eigen::Vector3d& max);

  int vertexCount() const { return vertex_count_; }
  int faceCount() const { return face_count_; }
  bool isFlat() const { return flat_; }

  /// Vertex i in the world frame (m).
  Eigen::Vector3d vertex(int i) const { return origin_ + Eigen::Vector3d(vx()[i], vy()[i], vz()[i]); }
  /// Outward unit normal of face f.
  Eigen::Vector3d faceNormal(int f) const { return {nx()[f], ny()[f], nz()[f]}; }
  /// Offset of face f in the world frame: n . x = offset on the plane (m).
  double faceOffset(int f) const { return pd()[f] + faceNormal(f).dot(origin_); }
  /// Vertex indices of face f, counter-clockwise seen from outside.
  std::span<const std::int32_t> faceVertices(int f) const;

  const Aabb& bounds() const { return bounds_; }
  /// Characteristic size (m): the bounding-box diagonal. Relative tolerances
  /// are multiples of it.
  double size() const { return size_; }
  /// The vertex average, an interior point for solid pieces (world, m).
  Eigen::Vector3d centroid() const { return origin_ + centroid_local_; }

  /// Index of a vertex maximising dir . v. `hint` (a previous answer, or -1)
  /// seeds the hill climb used on large pieces.
  int support(const Eigen::Vector3d& dir, int hint = -1) const;

  /// max_i (n_i . p - d_i) over the faces (m) and the face attaining it: a
  /// lower bound on the distance from p when positive, the exact signed
  /// distance when p is inside.
  double planeBound(const Eigen::Vector3d& p, int* face = nullptr) const;

  /// Bytes of this piece: the object and its numbers and topology, in its
  /// own block or in a terrain's arena (which shares one topology among
  /// many pieces: Terrain::pieceMemoryBytes counts the arena itself).
  std::size_t memoryBytes() const;

  // The local frame: coordinates relative to origin() (an engine adapter
  // builds its own shape of the piece in it, to the same roundoff).
  const Eigen::Vector3d& origin() const { return origin_; }
  const Eigen::Vector3d& centroidLocal() const { return centroid_local_; }
  Eigen::Vector3d vertexLocal(int i) const { return {vx()[i], vy()[i], vz()[i]}; }
  /// d_f of face f's plane n_f . x = d_f in the local frame (m).
  double faceOffsetLocal(int f) const { return pd()[f]; }

 private:
  // The stored layout, for the query kernels (src/geometry/polyhedron_layout.hpp).
  friend struct detail::PolyhedronLayout;
  const double* vx() const { return numbers_; }
  const double* vy() const { return vx() + vertex_count_; }
  const double* vz() const { return vy() + vertex_count_; }
  const double* nx() const { return vz() + vertex_count_; }
  const double* ny() const { return nx() + face_count_; }
  const double* nz() const { return ny() + face_count_; }
  const double* pd() const { return nz() + face_count_; }
  /// Side planes of face f's edges, 4 doubles each (s, s . a), in the order
  /// of faceVertices(f): edge k runs from vertex k - 1 (cyclically) to k.
  const double* faceEdgePlanes(int f) const { return pd() + face_count_ + 4 * topology_[f]; }
  /// Index of the first face-edge of face f among all face-edges (edge k of
  /// f is faceEdgeStart(f) + k); side planes are at 4 x that index.
  std::int32_t faceEdgeStart(int f) const { return topology_[f]; }
  /// The same edge in the neighbouring face, as a face-edge index.
  std::int32_t faceEdgeTwin(std::int32_t face_edge) const {
    return topology_[face_count_ + 1 + topology_[face_count_] + face_edge];
  }
  /// The face a face-edge belongs to.
  int faceOfEdge(std::int32_t face_edge) const;
  /// The next face-edge of the same face (it starts where `face_edge` ends).
  std::int32_t faceEdgeNext(std::int32_t face_edge) const;
  /// The vertex a face-edge ends at.
  std::int32_t faceEdgeEnd(std::int32_t face_edge) const { return topology_[face_count_ + 1 + face_edge]; }
  /// Side plane of a face-edge by index (4 doubles: s, s . a).
  const double* faceEdgePlane(std::int32_t face_edge) const { return pd() + face_count_ + 4 * face_edge; }
  int supportLocal(const Eigen::Vector3d& dir, int hint) const;
  double planeBoundLocal(const Eigen::Vector3d& q, int* face) const;

  ConvexPolyhedron() = default;
  // Builds the stored layout from a validated, outward-oriented face list.
  // `hull_normals` (from Qhull) replace the face normals computed from the
  // vertices, and the planarity check, for hull output.
  // `topology`, when given, is the face lists and twins (and adjacency)
  // of this very face list, copied instead of computed.
  static ConvexPolyhedron assemble(const std::vector<Eigen::Vector3d>& vertices,
                                   const std::vector<std::vector<int>>& faces, bool flat,
                                   const std::vector<Eigen::Vector3d>* hull_normals,
                                   const ConvexPolyhedron* topology_of = nullptr);
  // assemble's piece made into `poly`, every member overwritten, its
  // block reused when large enough.
  static void assembleInto(ConvexPolyhedron& poly, const std::vector<Eigen::Vector3d>& vertices,
                           const std::vector<std::vector<int>>& faces, bool flat,
                           const std::vector<Eigen::Vector3d>* hull_normals, const ConvexPolyhedron* topology_of);
  // assembleInto's topology of a new face list, into `topo`: the face
  // offsets and lists (before the numbers, which read them), then the twins
  // and, for large pieces, the adjacency (after the numbers' checks, so that
  // a bad face is reported before a bad edge, as it always was).
  // assembleInto's work, in the scratch `numbers` and `topology`.
  static void assembleScratch(ConvexPolyhedron& poly, const std::vector<Eigen::Vector3d>& vertices,
                              const std::vector<std::vector<int>>& faces, bool flat,
                              const std::vector<Eigen::Vector3d>* hull_normals, const ConvexPolyhedron* topology_of,
                              std::vector<double>& numbers, std::vector<std::int32_t>& topology);
  static void faceLists(std::vector<std::int32_t>& topo, const std::vector<std::vector<int>>& faces);
  static void twinsAndAdjacency(const ConvexPolyhedron& poly, std::vector<std::int32_t>& topo,
                                const std::vector<std::vector<int>>& faces);
  // Points the piece at `numbers` and `topology` (number_count_ and
  // topology_count_ of each), copied into its own block (reused when large
  // enough).
  void copyIntoBlock(const double* numbers, const std::int32_t* topology);
  // Makes the owned block hold number_count_ doubles and topology_count_
  // integers (reused when large enough) and points the views at it.
  void reserveBlock();
  // Frees the owned block, if any; the views are left to the caller.
  void releaseBlock() noexcept;
  // Copies every member but the storage (views and block) from `other`: the
  // copies' and moves' common part.
  void copyShape(const ConvexPolyhedron& other) noexcept;
  // Takes `other`'s views and block, leaving it an empty piece.
  void takeStorage(ConvexPolyhedron& other) noexcept;
  // Vertices up to which assembleInto keeps its scratch on the stack.
  static constexpr int kStackVertices = 16;
  int hillClimb(const Eigen::Vector3d& dir, int start) const;
  std::span<const std::int32_t> vertexNeighbors(int i) const;

  Eigen::Vector3d origin_{Eigen::Vector3d::Zero()};
  Eigen::Vector3d centroid_local_{Eigen::Vector3d::Zero()};
  Aabb bounds_;
  double size_ = 0.0;
  std::int32_t vertex_count_ = 0;
  std::int32_t face_count_ = 0;
  bool flat_ = false;
  bool has_adjacency_ = false;
  // The query kernel that fits this piece, chosen when it is built
  // (detail::PieceKernel, src/geometry/piece_kernel.hpp); 0: the general one.
  // In the padding after the flags: no byte more per piece.
  std::uint8_t kernel_ = 0;
  // [vx vy vz | nx ny nz d | face-edge side planes (sx sy sz s.a)...],
  // local frame; number_count_ doubles.
  const double* numbers_ = nullptr;
  // [face_start (F+1) | face vertices | face-edge twins | adjacency start
  // (V+1) | neighbours]; adjacency only for pieces that hill-climb; a Qhull
  // prism's kernel keeps its neighbours there (piece_kernel.hpp);
  // topology_count_ integers.
  const std::int32_t* topology_ = nullptr;
  std::int32_t number_count_ = 0;
  std::int32_t topology_count_ = 0;
  // The block this piece owns (its numbers, then its topology), block_bytes_
  // long; null when its numbers and topology live in a terrain's arena
  // (detail::PieceArena), which outlives it.
  void* block_ = nullptr;
  std::size_t block_bytes_ = 0;
};

}  // namespace wtc
