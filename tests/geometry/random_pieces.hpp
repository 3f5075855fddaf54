#pragma once
// Seeded random convex pieces and query points for the oracle tests.
//
// Pieces are placed at a random scale (10^-3 .. 10^3 m), with a random
// rotation, within 100 sizes of the origin: far enough to exercise the local
// frame, near enough that world coordinates keep ~1e-14 of the piece's size
// (the 1e6 m case has its own test and its own tolerance). Query points mix
// every region a wheel centre can be in: inside, exactly on faces, edges and
// vertices, a hair off the surface, in the bounding box, and far away.
#include <Eigen/Core>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "wtc/geometry/convex_polyhedron.hpp"

namespace wtc::test {

struct RandomPiece {
  ConvexPolyhedron poly;
  std::string kind;                     ///< What was generated, for failure messages.
  std::vector<Eigen::Vector3d> points;  ///< The input to fromPoints; empty for box().
};

class RandomPieces {
 public:
  explicit RandomPieces(std::uint64_t seed) : engine_(seed) {}

  /// Hull of `count` points drawn from one of several distributions (ball,
  /// sphere surface, flattened ellipsoid, integer grid with many coplanar
  /// and duplicate points, cube corners plus noise).
  RandomPiece hull(int count);
  /// A box: axis-aligned through ConvexPolyhedron::box, or rotated through
  /// fromPoints; extents differ by up to 100x.
  RandomPiece box();
  /// A triangular prism with a tilted top: a heightfield cell.
  RandomPiece prism();
  /// `count` coplanar points (>= 3) in a random plane: a flat piece.
  RandomPiece flatPolygon(int count);
  /// One of the above, chosen at random.
  RandomPiece any();

  /// A query point for `poly`, from a random region (see the file note).
  Eigen::Vector3d query(const ConvexPolyhedron& poly);

  double uniform(double lo, double hi) { return std::uniform_real_distribution<>(lo, hi)(engine_); }
  int uniformInt(int lo, int hi) { return std::uniform_int_distribution<>(lo, hi)(engine_); }
  Eigen::Vector3d onUnitSphere();
  Eigen::Vector3d inUnitBall();
  std::mt19937_64& engine() { return engine_; }

 private:
  // Scales by 10^U(-3, 3), rotates at random and moves within 100 sizes of
  // the origin; appends the scale to `kind`.
  std::vector<Eigen::Vector3d> place(std::vector<Eigen::Vector3d> points, std::string& kind);
  Eigen::Matrix3d rotation();
  Eigen::Vector3d pointOnFace(const ConvexPolyhedron& poly, int face);

  std::mt19937_64 engine_;
};

/// All vertices and faces of `poly` at full precision: enough to rebuild it
/// with fromMesh and reproduce a failure.
std::string describe(const ConvexPolyhedron& poly);

}  // namespace wtc::test
