#pragma once
// The signed-volumes simplex sub-algorithm of GJK (Montanari, Petrinic,
// Barbieri, ACM TOG 36(3), 2017, section 3): the point of a simplex
// (1 to 4 vertices) closest to the origin, and the smallest sub-simplex that
// supports it.
//
// Barycentric coordinates of the origin's projection come from signed
// measures (lengths, areas, volumes) of the sub-simplices with the origin
// substituted for one vertex. A vertex whose measure has the opposite sign to
// the whole (or zero) is dropped, and the faces (edges) opposite to the
// dropped vertices are searched; the best candidate wins. Degenerate
// simplices (zero area or volume) have no consistent sign and fall through
// to their boundary, so the routine never divides by zero.
#include <cstdint>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace wtc::detail {

struct Simplex {
  Eigen::Vector3d point[4];  // Vertices of the Minkowski difference, poly - p.
  std::int32_t vertex[4];    // Their indices in the polyhedron.
  int count = 0;
};

/// Reduces `s` to the sub-simplex supporting the closest point to the
/// origin and returns that point. A 4-vertex result means the origin is
/// strictly inside the tetrahedron.
Eigen::Vector3d closestToOrigin(Simplex& s);

}  // namespace wtc::detail
