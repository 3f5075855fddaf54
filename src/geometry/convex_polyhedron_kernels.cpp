// The read side of ConvexPolyhedron, used by every query: topology
// accessors, the support function (scan or hill climb) and the face-plane
// bound. Construction and validation are in convex_polyhedron.cpp.
#include <algorithm>

#include "polyhedron_layout.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"

namespace wtc {

std::span<const std::int32_t> ConvexPolyhedron::faceVertices(int f) const {
  const std::int32_t* start = topology_;
  const std::int32_t* list = start + face_count_ + 1;
  return {list + start[f], list + start[f + 1]};
}

int ConvexPolyhedron::faceOfEdge(std::int32_t face_edge) const {
  // Face starts are ascending: a short scan for the small pieces of ground
  // (5 to 8 faces), a binary search for large ones.
  const std::int32_t* start = topology_;
  if (face_count_ <= 16) {
    int f = 0;
    while (start[f + 1] <= face_edge) ++f;
    return f;
  }
  return static_cast<int>(std::upper_bound(start, start + face_count_ + 1, face_edge) - start) - 1;
}

std::int32_t ConvexPolyhedron::faceEdgeNext(std::int32_t face_edge) const {
  const int f = faceOfEdge(face_edge);
  return face_edge + 1 < topology_[f + 1] ? face_edge + 1 : topology_[f];
}

std::span<const std::int32_t> ConvexPolyhedron::vertexNeighbors(int i) const {
  const std::int32_t* start = topology_ + face_count_ + 1 + 2 * topology_[face_count_];
  const std::int32_t* list = start + vertex_count_ + 1;
  return {list + start[i], list + start[i + 1]};
}

int ConvexPolyhedron::support(const Eigen::Vector3d& dir, int hint) const { return supportLocal(dir, hint); }

int ConvexPolyhedron::supportLocal(const Eigen::Vector3d& dir, int hint) const {
  if (has_adjacency_) return hillClimb(dir, hint < 0 ? 0 : hint);
  const double* x = vx();
  const double* y = vy();
  const double* z = vz();
  // Branch-free argmax: the winner is data-dependent, a branch mispredicts.
  int best = 0;
  double best_dot = dir.x() * x[0] + dir.y() * y[0] + dir.z() * z[0];
  for (int i = 1; i < vertex_count_; ++i) {
    const double d = dir.x() * x[i] + dir.y() * y[i] + dir.z() * z[i];
    const bool better = d > best_dot;
    best = better ? i : best;
    best_dot = better ? d : best_dot;
  }
  return best;
}

// On a convex polytope a linear function has no local maximum on the vertex
// graph that is not global, so a greedy walk along edges finds the support
// vertex; from a warm start it takes one or two steps.
int ConvexPolyhedron::hillClimb(const Eigen::Vector3d& dir, int start) const {
  const double* x = vx();
  const double* y = vy();
  const double* z = vz();
  int current = start;
  double current_dot = dir.x() * x[current] + dir.y() * y[current] + dir.z() * z[current];
  for (bool moved = true; moved;) {
    moved = false;
    for (std::int32_t next : vertexNeighbors(current)) {
      const double d = dir.x() * x[next] + dir.y() * y[next] + dir.z() * z[next];
      if (d > current_dot) {
        current_dot = d;
        current = next;
        moved = true;
      }
    }
  }
  return current;
}

double ConvexPolyhedron::planeBound(const Eigen::Vector3d& p, int* face) const {
  return planeBoundLocal(p - origin_, face);
}

double ConvexPolyhedron::planeBoundLocal(const Eigen::Vector3d& q, int* face) const {
  const double* a = nx();
  const double* b = ny();
  const double* c = nz();
  const double* d = pd();
  switch (face_count_) {
    case 5:
      return detail::PolyhedronLayout::planeBoundOf<5>(*this, q, face);
    case 6:
      return detail::PolyhedronLayout::planeBoundOf<6>(*this, q, face);
    default:
      break;
  }
  int best = 0;
  double best_value = a[0] * q.x() + b[0] * q.y() + c[0] * q.z() - d[0];
  for (int f = 1; f < face_count_; ++f) {
    const double value = a[f] * q.x() + b[f] * q.y() + c[f] * q.z() - d[f];
    const bool better = value > best_value;  // branch-free, as in supportLocal
    best = better ? f : best;
    best_value = better ? value : best_value;
  }
  if (face != nullptr) *face = best;
  return best_value;
}

std::size_t ConvexPolyhedron::memoryBytes() const {
  // Its numbers and topology wherever they are (its own block, or a
  // terrain's arena, which counts them in Terrain::pieceMemoryBytes).
  return sizeof(*this) + static_cast<std::size_t>(number_count_) * sizeof(double) +
         static_cast<std::size_t>(topology_count_) * sizeof(std::int32_t);
}

}  // namespace wtc
