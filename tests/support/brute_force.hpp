#pragma once
// The brute-force oracle: the closest point of a convex polyhedron found by
// visiting every face, written for obvious correctness, not speed. Tests and
// benchmarks measure wtc::queryPoint against it.
//
// Method. Every face polygon is fan-triangulated and the closest point of
// each triangle is found exactly (Ericson, "Real-Time Collision Detection",
// 2005, section 5.1.5: project p on the triangle's plane; if the projection
// is inside the triangle it is the answer, otherwise the answer is the
// closest of the three edge points, section 5.1.2). The minimum over all
// faces is the unsigned distance to the surface. The sign comes from face
// planes recomputed here from the face vertices (Newell's method), not taken
// from the piece: p is inside a solid piece when it lies below every face
// plane, and then the signed distance is max_i (n_i . p - d_i) (exact for a
// convex solid: the nearest face plane holds the nearest face) and the
// closest point is p projected on that plane. A flat piece (isFlat(): two
// faces of opposite normals) has no inside; its signed distance is the
// unsigned distance.
//
// Precision. Everything is computed in long double (64-bit significand on
// x86-64, 2048 times finer than double) relative to a vertex of the piece, so
// a 1 mm piece 1e6 m from the origin, or a query point 1e9 m away, loses no
// digits that matter at double precision. Only the results are rounded to
// double.
#include <Eigen/Core>
#include <memory>

#include "wtc/geometry/convex_polyhedron.hpp"

namespace wtc::testing {

struct BruteForceResult {
  /// Distance from p to the surface (m): positive outside, negative inside.
  double signed_distance = 0.0;
  /// The point of the surface closest to p (world, m).
  Eigen::Vector3d closest_point{Eigen::Vector3d::Zero()};
  /// The face holding closest_point (outside) or the nearest face plane
  /// (inside).
  int face = -1;
  /// True when p is strictly below every face plane of a solid piece.
  bool inside = false;
};

/// The oracle for one piece: the faces and their planes are prepared once,
/// in extended precision, so that many queries of one piece stay cheap.
class BruteForceOracle {
 public:
  explicit BruteForceOracle(const ConvexPolyhedron& poly);
  ~BruteForceOracle();
  BruteForceOracle(BruteForceOracle&&) noexcept;
  BruteForceOracle& operator=(BruteForceOracle&&) noexcept;

  /// The exact closest point and signed distance from p (world, m).
  BruteForceResult query(const Eigen::Vector3d& p) const;
  /// Unsigned distance from p to the surface (m): checks that a reported
  /// closest point lies on the surface.
  double surfaceDistance(const Eigen::Vector3d& p) const;

 private:
  struct Faces;
  std::unique_ptr<Faces> faces_;
};

/// One-off form of BruteForceOracle(poly).query(p).
BruteForceResult bruteForceQuery(const ConvexPolyhedron& poly, const Eigen::Vector3d& p);

}  // namespace wtc::testing
