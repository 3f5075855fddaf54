#include "wtc/geometry/convex_polyhedron.hpp"

#include "base/cache_line.hpp"

#include "piece_kernel.hpp"
#include "polyhedron_layout.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <new>
#include <limits>
#include <numeric>
#include <set>
#include <string>

#include "wtc/base/error.hpp"
#include "wtc/base/tolerances.hpp"

namespace wtc {
namespace {

[[noreturn]] void fail(const std::string& what) { throw InvalidInputError("wtc::ConvexPolyhedron::fromMesh: " + what); }

// Newell's method: the area-weighted normal of a polygon, robust for
// polygons that are planar only to roundoff (merged hull facets).
Eigen::Vector3d newellNormal(const Eigen::Vector3d* local, const std::int32_t* face, int size) {
  // Edge vectors from the first vertex: no cancellation from large
  // coordinates.
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  const Eigen::Vector3d& first = local[face[0]];
  for (int k = 1; k + 1 < size; ++k) {
    n += (local[face[k]] - first).cross(local[face[k + 1]] - first);
  }
  return n;
}

// Twin of each face-edge (edge k of a face runs from its vertex k - 1 to
// vertex k): the same edge run the other way in the neighbouring face. A
// closed, consistently oriented surface has exactly one twin for every
// edge and no edge twice in one direction; anything else is named. Small
// pieces (terrain prisms: 18 face-edges) are matched by one pass over the
// pairs in stack buffers, larger ones by sorting.
void matchTwins(const std::vector<std::vector<int>>& faces, std::int32_t* twins) {
  struct Directed {
    std::int32_t from, to, face;
  };
  constexpr std::size_t kScanEdges = 64;
  std::size_t total = 0;
  for (const auto& face : faces) total += face.size();
  Directed small[kScanEdges];
  std::vector<Directed> large;
  Directed* edges = small;
  if (total > kScanEdges) {
    large.resize(total);
    edges = large.data();
  }
  std::size_t index = 0;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto& face = faces[f];
    for (std::size_t k = 0; k < face.size(); ++k) {
      edges[index++] = {face[(k + face.size() - 1) % face.size()], face[k], static_cast<std::int32_t>(f)};
    }
  }
  auto name = [](const Directed& e) {
    return "edge (" + std::to_string(e.from) + ", " + std::to_string(e.to) + ") of face " + std::to_string(e.face);
  };
  auto key = [](const Directed& e) { return std::pair{e.from, e.to}; };
  std::vector<std::int32_t> order;  // large pieces: edge indices sorted by (from, to)
  if (total > kScanEdges) {
    order.resize(total);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](std::int32_t x, std::int32_t y) { return key(edges[x]) < key(edges[y]); });
  }
  if (total <= kScanEdges) {
    // One pass over the pairs: each edge's first twin (the lowest index run
    // the other way) and whether any other edge runs the same way; then the
    // checks in edge order, so the first bad edge is named as before.
    std::int32_t first_twin[kScanEdges];
    bool repeated[kScanEdges] = {};
    std::fill_n(first_twin, total, -1);
    for (std::size_t i = 0; i < total; ++i) {
      for (std::size_t j = i + 1; j < total; ++j) {
        if (edges[j].from == edges[i].from && edges[j].to == edges[i].to) {
          repeated[i] = repeated[j] = true;
        } else if (edges[j].from == edges[i].to && edges[j].to == edges[i].from) {
          if (first_twin[i] < 0) first_twin[i] = static_cast<std::int32_t>(j);
          if (first_twin[j] < 0) first_twin[j] = static_cast<std::int32_t>(i);
        }
      }
    }
    for (std::size_t i = 0; i < total; ++i) {
      if (repeated[i]) {
        fail(name(edges[i]) + " is used twice in the same direction: faces overlap or are inconsistently oriented");
      }
      // An edge from a vertex to itself is its own opposite (the sorted
      // search below finds it so).
      if (first_twin[i] < 0 && edges[i].from == edges[i].to) first_twin[i] = static_cast<std::int32_t>(i);
      if (first_twin[i] < 0) fail(name(edges[i]) + " has no opposite edge: the mesh is not closed");
      twins[i] = first_twin[i];
    }
    return;
  }
  auto find = [&](std::int32_t from, std::int32_t to, std::size_t skip) -> std::int64_t {
    auto it = std::lower_bound(
        order.begin(), order.end(), std::pair{from, to},
        [&](std::int32_t x, const std::pair<std::int32_t, std::int32_t>& k) { return key(edges[x]) < k; });
    for (; it != order.end() && key(edges[*it]) == std::pair{from, to}; ++it) {
      if (static_cast<std::size_t>(*it) != skip) return *it;
    }
    return -1;
  };
  for (std::size_t i = 0; i < total; ++i) {
    if (find(edges[i].from, edges[i].to, i) >= 0) {
      fail(name(edges[i]) + " is used twice in the same direction: faces overlap or are inconsistently oriented");
    }
    const std::int64_t twin = find(edges[i].to, edges[i].from, total);
    if (twin < 0) fail(name(edges[i]) + " has no opposite edge: the mesh is not closed");
    twins[i] = static_cast<std::int32_t>(twin);
  }
}

}  // namespace

ConvexPolyhedron ConvexPolyhedron::fromMesh(const std::vector<Eigen::Vector3d>& vertices,
                                            const std::vector<std::vector<int>>& faces) {
  if (vertices.size() < 3) {
    fail("needs at least 3 vertices, got " + std::to_string(vertices.size()));
  }
  if (vertices.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max() / 4)) {
    fail("too many vertices: " + std::to_string(vertices.size()));
  }
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (!isFinite(vertices[i])) {
      fail("vertex " + std::to_string(i) + " = " + formatVector(vertices[i]) + " is not finite");
    }
  }
  if (faces.size() < 2) fail("needs at least 2 faces, got " + std::to_string(faces.size()));
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (faces[f].size() < 3) {
      fail("face " + std::to_string(f) + " has " + std::to_string(faces[f].size()) +
           " vertices; a face needs at least 3");
    }
    for (int i : faces[f]) {
      if (i < 0 || static_cast<std::size_t>(i) >= vertices.size()) {
        fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(i) + ", but there are " +
             std::to_string(vertices.size()) + " vertices");
      }
    }
  }
  // A two-faced mesh is a flat polygon given from both sides.
  const bool flat = faces.size() == 2;
  return assemble(vertices, faces, flat, nullptr);
}

ConvexPolyhedron ConvexPolyhedron::box(const Eigen::Vector3d& min, const Eigen::Vector3d& max) {
  if (!isFinite(min) || !isFinite(max) || !(min.array() < max.array()).all()) {
    throw InvalidInputError("wtc::ConvexPolyhedron::box: needs finite min < max on every axis, got min = " +
                            formatVector(min) + ", max = " + formatVector(max));
  }
  std::vector<Eigen::Vector3d> v(8);
  for (int i = 0; i < 8; ++i) {
    v[i] = {(i & 1) ? max.x() : min.x(), (i & 2) ? max.y() : min.y(), (i & 4) ? max.z() : min.z()};
  }
  // Counter-clockwise seen from outside: -x, +x, -y, +y, -z, +z.
  const std::vector<std::vector<int>> faces = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                               {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  return assemble(v, faces, false, nullptr);
}

ConvexPolyhedron detail::PolyhedronLayout::sameTopologyAs(const ConvexPolyhedron& like,
                                                          const std::vector<Eigen::Vector3d>& vertices,
                                                          const std::vector<std::vector<int>>& faces) {
  ConvexPolyhedron poly = ConvexPolyhedron::assemble(vertices, faces, like.flat_, nullptr, &like);
  poly.kernel_ = static_cast<std::uint8_t>(kernelForTopologyOf(poly, static_cast<PieceKernel>(like.kernel_)));
  return poly;
}

void detail::PolyhedronLayout::sameTopologyInto(ConvexPolyhedron& into, const ConvexPolyhedron& like,
                                                const std::vector<Eigen::Vector3d>& vertices,
                                                const std::vector<std::vector<int>>& faces) {
  ConvexPolyhedron::assembleInto(into, vertices, faces, like.flat_, nullptr, &like);
  into.kernel_ = static_cast<std::uint8_t>(kernelForTopologyOf(into, static_cast<PieceKernel>(like.kernel_)));
}

ConvexPolyhedron ConvexPolyhedron::assemble(const std::vector<Eigen::Vector3d>& vertices,
                                            const std::vector<std::vector<int>>& faces, bool flat,
                                            const std::vector<Eigen::Vector3d>* hull_normals,
                                            const ConvexPolyhedron* topology_of) {
  ConvexPolyhedron poly;
  assembleInto(poly, vertices, faces, flat, hull_normals, topology_of);
  return poly;
}

void ConvexPolyhedron::assembleInto(ConvexPolyhedron& poly, const std::vector<Eigen::Vector3d>& vertices,
                                    const std::vector<std::vector<int>>& faces, bool flat,
                                    const std::vector<Eigen::Vector3d>* hull_normals,
                                    const ConvexPolyhedron* topology_of) {
  // A new face list's numbers and topology are made in per-thread scratch,
  // the piece's views pointing there, and copied into its block once
  // complete (their sizes are known only then); a copied topology's are
  // made in the block itself. A piece left half made by an error has no
  // numbers (its block, if any, is kept).
  thread_local std::vector<double> numbers;
  thread_local std::vector<std::int32_t> topology;
  poly.numbers_ = nullptr;
  poly.topology_ = nullptr;
  poly.number_count_ = poly.topology_count_ = 0;
  try {
    assembleScratch(poly, vertices, faces, flat, hull_normals, topology_of, numbers, topology);
  } catch (...) {
    poly.numbers_ = nullptr;
    poly.topology_ = nullptr;
    poly.number_count_ = poly.topology_count_ = 0;
    throw;
  }
  if (topology_of == nullptr) poly.copyIntoBlock(numbers.data(), topology.data());
}

void ConvexPolyhedron::assembleScratch(ConvexPolyhedron& poly, const std::vector<Eigen::Vector3d>& vertices,
                                       const std::vector<std::vector<int>>& faces, bool flat,
                                       const std::vector<Eigen::Vector3d>* hull_normals,
                                       const ConvexPolyhedron* topology_of, std::vector<double>& numbers,
                                       std::vector<std::int32_t>& topology) {
  poly.bounds_ = Aabb::of(vertices);
  poly.origin_ = poly.bounds_.center();
  poly.size_ = poly.bounds_.extent().norm();
  if (!(poly.size_ > 0.0) || !std::isfinite(poly.size_)) {
    fail("all vertices coincide at " + formatVector(vertices.front()));
  }
  const int nv = static_cast<int>(vertices.size());
  const int nf = static_cast<int>(faces.size());
  poly.vertex_count_ = nv;
  poly.face_count_ = nf;
  poly.flat_ = flat;
  poly.has_adjacency_ = nv >= tolerance::kHillClimbMinVertices;

  // Topology first: the face lists the numbers below are computed from, read
  // flat (offsets, then indices) rather than through the nested vectors.
  // A copied topology is this very face list (the caller's word).
  const std::int32_t* face_start = nullptr;
  if (topology_of != nullptr) {
    face_start = topology_of->topology_;
  } else {
    faceLists(topology, faces);
    face_start = topology.data();
  }
  const std::int32_t* face_list = face_start + nf + 1;
  const auto face_edges = static_cast<std::size_t>(face_start[nf]);
  const std::size_t number_count =
      3 * static_cast<std::size_t>(nv) + 4 * static_cast<std::size_t>(nf) + 4 * face_edges;
  double* num = nullptr;
  if (topology_of != nullptr) {
    // Every size is known: straight into the piece's block.
    poly.number_count_ = static_cast<std::int32_t>(number_count);
    poly.topology_count_ = topology_of->topology_count_;
    poly.reserveBlock();
    num = static_cast<double*>(poly.block_);
    std::memcpy(num + number_count, face_start,
                static_cast<std::size_t>(poly.topology_count_) * sizeof(std::int32_t));
  } else {
    numbers.resize(number_count);
    num = numbers.data();
    poly.numbers_ = num;
    poly.number_count_ = static_cast<std::int32_t>(number_count);
    poly.topology_ = topology.data();
    poly.topology_count_ = static_cast<std::int32_t>(topology.size());
  }

  // Scratch for the local vertices: on the stack for the small pieces that
  // heightfields and meshes form by the million, else one list per thread.
  std::array<Eigen::Vector3d, kStackVertices> small;
  thread_local std::vector<Eigen::Vector3d> large;
  Eigen::Vector3d* local = small.data();
  if (nv > kStackVertices) {
    large.resize(nv);
    local = large.data();
  }
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int i = 0; i < nv; ++i) {
    local[i] = vertices[i] - poly.origin_;
    sum += local[i];
  }
  poly.centroid_local_ = sum / nv;

  for (int i = 0; i < nv; ++i) {
    num[i] = local[i].x();
    num[nv + i] = local[i].y();
    num[2 * nv + i] = local[i].z();
  }
  const double planar_tol = tolerance::kHullMergeRelative * poly.size_;
  // Planarity is checked on a new face list; Qhull's facets are planar by
  // its hyperplanes, and a copied topology's caller vouches for its faces
  // (prisms formed from checked corners: triangles and the vertical or
  // parallel quads between them). Zero area and volume are always checked.
  const bool check_planar = hull_normals == nullptr && topology_of == nullptr;
  double* n_out = num + 3 * nv;
  for (int f = 0; f < nf; ++f) {
    const std::int32_t* face = face_list + face_start[f];
    const int face_size = face_start[f + 1] - face_start[f];
    Eigen::Vector3d n;
    if (hull_normals != nullptr) {
      // Qhull's hyperplane: robust where a sliver facet's vertices are not.
      n = (*hull_normals)[f].normalized();
    } else {
      const Eigen::Vector3d area = newellNormal(local, face, face_size);
      const double twice_area = area.norm();
      if (!(twice_area > planar_tol * planar_tol)) {
        fail("face " + std::to_string(f) + " has zero area (its vertices are collinear or coincide)");
      }
      n = area / twice_area;
    }
    // d = max over ALL vertices keeps every vertex inside every plane, so the
    // plane bound stays a true lower bound (see the header's design note).
    double d = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < nv; ++i) d = std::max(d, n.dot(local[i]));
    double face_min = d;
    if (check_planar) {
      for (int k = 0; k < face_size; ++k) face_min = std::min(face_min, n.dot(local[face[k]]));
    }
    if (d - face_min > planar_tol) {
      fail("face " + std::to_string(f) + " is not planar, or the mesh is not convex or not oriented " +
           "outward: a vertex lies " + formatNumber(d - face_min) + " m above the face's plane (tolerance " +
           formatNumber(planar_tol) + " m)");
    }
    n_out[f] = n.x();
    n_out[nf + f] = n.y();
    n_out[2 * nf + f] = n.z();
    n_out[3 * nf + f] = d;
  }
  // Side planes of the face edges, in face order: edge k of face f runs from
  // vertex k - 1 (cyclically) to vertex k; s = n x (b - a) points into the
  // face, so s . q >= s . a when q projects onto the face's side of the edge.
  double* side = n_out + 4 * nf;
  for (int f = 0; f < nf; ++f) {
    const Eigen::Vector3d n(n_out[f], n_out[nf + f], n_out[2 * nf + f]);
    const std::int32_t* face = face_list + face_start[f];
    const int face_size = face_start[f + 1] - face_start[f];
    for (int k = 0; k < face_size; ++k) {
      const Eigen::Vector3d& a = local[face[k == 0 ? face_size - 1 : k - 1]];
      const Eigen::Vector3d s_in = n.cross(local[face[k]] - a);
      side[0] = s_in.x();
      side[1] = s_in.y();
      side[2] = s_in.z();
      side[3] = s_in.dot(a);
      side += 4;
    }
  }
  if (!flat && poly.planeBoundLocal(poly.centroid_local_, nullptr) >= -planar_tol) {
    fail("the faces do not enclose a volume (the centroid is not strictly inside every face plane)");
  }
  if (topology_of == nullptr) {
    twinsAndAdjacency(poly, topology, faces);
    poly.topology_ = topology.data();
    poly.topology_count_ = static_cast<std::int32_t>(topology.size());
  }
  // A copied topology's kernel is its caller's to choose (sameTopologyAs).
  poly.kernel_ = topology_of == nullptr ? static_cast<std::uint8_t>(detail::kernelFor(poly)) : 0;
  if (topology_of == nullptr) detail::storeKernelData(poly, topology);
}

void ConvexPolyhedron::faceLists(std::vector<std::int32_t>& topo, const std::vector<std::vector<int>>& faces) {
  std::size_t face_edges = 0;
  for (const auto& face : faces) face_edges += face.size();
  topo.clear();
  topo.reserve(1 + faces.size() + 2 * face_edges);  // offsets, face lists, twins: one allocation
  topo.push_back(0);
  std::size_t total = 0;
  for (const auto& face : faces) topo.push_back(static_cast<std::int32_t>(total += face.size()));
  for (const auto& face : faces) topo.insert(topo.end(), face.begin(), face.end());
}

void ConvexPolyhedron::twinsAndAdjacency(const ConvexPolyhedron& poly, std::vector<std::int32_t>& topo,
                                         const std::vector<std::vector<int>>& faces) {
  const std::size_t twins_at = topo.size();
  const auto total = static_cast<std::size_t>(topo[poly.face_count_]);
  topo.resize(twins_at + total);
  matchTwins(faces, topo.data() + twins_at);
  if (poly.has_adjacency_) {
    std::vector<std::set<int>> neighbors(poly.vertex_count_);
    for (const auto& face : faces) {
      for (std::size_t k = 0; k < face.size(); ++k) {
        const int a = face[k];
        const int b = face[(k + 1) % face.size()];
        neighbors[a].insert(b);
        neighbors[b].insert(a);
      }
    }
    std::int32_t count = 0;
    topo.push_back(0);
    for (const auto& n : neighbors) topo.push_back(count += static_cast<std::int32_t>(n.size()));
    for (const auto& n : neighbors) topo.insert(topo.end(), n.begin(), n.end());
  }
}

// The block: numbers_ first (8-byte doubles, at the block's start), then the
// topology; aligned to a cache line, so that a small piece's numbers start
// on one.
namespace {
constexpr std::align_val_t kBlockAlignment{detail::kCacheLineBytes};
}  // namespace

void ConvexPolyhedron::reserveBlock() {
  const std::size_t number_bytes = static_cast<std::size_t>(number_count_) * sizeof(double);
  const std::size_t bytes = number_bytes + static_cast<std::size_t>(topology_count_) * sizeof(std::int32_t);
  if (block_ == nullptr || block_bytes_ < bytes) {
    void* fresh = ::operator new(bytes, kBlockAlignment);
    releaseBlock();
    block_ = fresh;
    block_bytes_ = bytes;
  }
  auto* bytes_at = static_cast<unsigned char*>(block_);
  numbers_ = reinterpret_cast<const double*>(bytes_at);
  topology_ = reinterpret_cast<const std::int32_t*>(bytes_at + number_bytes);
}

void ConvexPolyhedron::copyIntoBlock(const double* numbers, const std::int32_t* topology) {
  reserveBlock();
  auto* bytes_at = static_cast<unsigned char*>(block_);
  const std::size_t number_bytes = static_cast<std::size_t>(number_count_) * sizeof(double);
  if (number_count_ > 0) std::memcpy(bytes_at, numbers, number_bytes);
  if (topology_count_ > 0) {
    std::memcpy(bytes_at + number_bytes, topology, static_cast<std::size_t>(topology_count_) * sizeof(std::int32_t));
  }
}

void ConvexPolyhedron::releaseBlock() noexcept {
  if (block_ != nullptr) ::operator delete(block_, kBlockAlignment);
  block_ = nullptr;
  block_bytes_ = 0;
}

void ConvexPolyhedron::copyShape(const ConvexPolyhedron& other) noexcept {
  origin_ = other.origin_;
  centroid_local_ = other.centroid_local_;
  bounds_ = other.bounds_;
  size_ = other.size_;
  vertex_count_ = other.vertex_count_;
  face_count_ = other.face_count_;
  flat_ = other.flat_;
  has_adjacency_ = other.has_adjacency_;
  kernel_ = other.kernel_;
  number_count_ = other.number_count_;
  topology_count_ = other.topology_count_;
}

void ConvexPolyhedron::takeStorage(ConvexPolyhedron& other) noexcept {
  // An owned block moves; an arena's views move with the pieces a terrain
  // moves within itself (only a terrain holds such pieces, by value, and
  // never hands one out but by const reference or by copy).
  numbers_ = other.numbers_;
  topology_ = other.topology_;
  block_ = other.block_;
  block_bytes_ = other.block_bytes_;
  other.numbers_ = nullptr;
  other.topology_ = nullptr;
  other.number_count_ = other.topology_count_ = 0;
  other.vertex_count_ = other.face_count_ = 0;
  other.block_ = nullptr;
  other.block_bytes_ = 0;
}

ConvexPolyhedron::ConvexPolyhedron(const ConvexPolyhedron& other) {
  copyShape(other);
  // Always a block of its own: a copy outlives the piece and the terrain
  // (arena) it was copied from.
  if (other.numbers_ != nullptr) copyIntoBlock(other.numbers_, other.topology_);
}

ConvexPolyhedron::ConvexPolyhedron(ConvexPolyhedron&& other) noexcept {
  copyShape(other);
  takeStorage(other);
}

ConvexPolyhedron& ConvexPolyhedron::operator=(const ConvexPolyhedron& other) {
  if (this == &other) return *this;
  copyShape(other);
  if (other.numbers_ == nullptr) {
    numbers_ = nullptr;
    topology_ = nullptr;
  } else {
    copyIntoBlock(other.numbers_, other.topology_);  // this one's block, when large enough
  }
  return *this;
}

ConvexPolyhedron& ConvexPolyhedron::operator=(ConvexPolyhedron&& other) noexcept {
  if (this == &other) return *this;
  releaseBlock();
  copyShape(other);
  takeStorage(other);
  return *this;
}

ConvexPolyhedron::~ConvexPolyhedron() { releaseBlock(); }

}  // namespace wtc
