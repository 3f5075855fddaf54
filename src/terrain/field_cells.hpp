#pragma once
// A run of a compact heightfield's cells along one row, cell by cell
// (internal to wtc::core): what CompactHeightfield::within and a wheel's
// meeting with the field as one surface (src/contact/field_surface.cpp) both
// read from a run of Terrain::withinSurfaces.
#include <algorithm>
#include <cstddef>

#include <Eigen/Core>

#include "wtc/geometry/aabb.hpp"
#include "wtc/terrain/heightfield.hpp"
#include "wtc/terrain/terrain.hpp"

namespace wtc::detail {

/// Relative and absolute (m^2) margin of a cell's box test: far above
/// rounding; the pieces' own boxes (or distances) decide what it lets by.
inline constexpr double kCellSlack = 1e-9;

/// visit(c, id, x0, x1, top) for each ground cell (r, c), lo <= c <= hi:
/// `id` its first prism, counted on from `first`, the first ground cell's,
/// over the ground cells; x0, x1 (m) its sides along x as sample() computes
/// them, `top` (m) its box's top (its two prisms' union up to its highest
/// sample).
template <typename Visit>
void forEachCellBox(const Heightfield& f, int r, int lo, int hi, PieceId first, Visit&& visit) {
  const auto x = [&](int i) { return f.origin.x() + i * f.spacing_x; };  // as sample() computes them
  // The samples on the row's two lines, and the higher of each column's
  // pair: a cell's top is the higher of its two columns' (origin.z + h
  // rounds monotonically in h, so the highest sample gives the highest top).
  const double* below = f.heights.data() + static_cast<std::size_t>(r) * f.cols;
  const double* above = below + f.cols;
  double left = std::max(below[lo], above[lo]);
  double x_left = x(lo);  // a cell's right side is the next one's left, the same sum
  PieceId id = first;
  for (int c = lo; c <= hi; ++c) {
    const double right = std::max(below[c + 1], above[c + 1]);
    const double top = f.origin.z() + std::max(left, right);
    const double x_right = x(c + 1);
    const double x0 = x_left;
    left = right, x_left = x_right;
    if (f.isHole(r, c)) continue;
    const PieceId cell_first = id;
    id += 2;
    visit(c, cell_first, x0, x_right, top);
  }
}

/// The distance (m) along y from `y` to row r's cells, as sample() computes
/// the row's lines.
inline double rowDistance(const Heightfield& f, int r, double y) {
  return std::max({0.0, f.origin.y() + r * f.spacing_y - y, y - (f.origin.y() + (r + 1) * f.spacing_y)});
}

/// visit(c, id) for each ground cell (r, c), lo <= c <= hi, whose box
/// comes within `reach` (m) of `point`, with kCellSlack's margin
/// (forEachCellBox's cells and ids).
template <typename Visit>
void forEachCellNear(const Heightfield& f, int r, int lo, int hi, PieceId first, const Eigen::Vector3d& point,
                     double reach, Visit&& visit) {
  const double slack2 = reach * reach * (1.0 + kCellSlack) + kCellSlack;
  const double dy = rowDistance(f, r, point.y());
  forEachCellBox(f, r, lo, hi, first, [&](int c, PieceId id, double x0, double x1, double top) {
    const double dx = std::max({0.0, x0 - point.x(), point.x() - x1});
    const double dz = std::max(0.0, point.z() - top);
    if (dx * dx + dy * dy + dz * dz <= slack2) visit(c, id);
  });
}

// Where the distance from a point O falls away (SurfaceRun::passed). At a
// point q of the surface, rho (m) horizontally from O's vertical and H (m)
// below O, a step along the surface toward that vertical (the unit
// horizontal v) over a triangle of gradient g changes |q - O|^2 / 2 at
// the rate -rho - H g.v <= -rho + |H| |g|: it falls whenever
// |H| |g| < rho. When that holds over a cell with every triangle a step
// from it can enter (those of the 3 x 3 cells around it), none of its
// points is a local minimum: not a triangle's face point (there q - O is
// the triangle's normal, so rho = |H| |g|), and a triangle's edge or
// vertex point lies on the triangle the step enters, whose own closest
// point is strictly nearer: the neighbour across that edge, or one of the
// six around that vertex, exactly those the search compares it with
// (src/contact/field_surface.cpp).
//
// A cell passes where rho > kFallMargin |H| |g| + kFallMarginM, with |H|
// and |g| bounded over the samples of the 3 x 3 cells around it (by its
// tile's, CompactHeightfield::TileFall): with that margin the nearer
// neighbour is nearer by far more than roundoff.
inline constexpr double kFallMargin = 2.0;    // on |H| |g|
inline constexpr double kFallMarginM = 1e-6;  // on rho (m)

/// The top of prism t of cell (r, c): its triangle's highest corner, the
/// corners' z as sample() computes them; t = 0 (p00, p01, p11), 1 (p00, p11, p10).
inline double prismTop(const Heightfield& f, int r, int c, int t) {
  const double z00 = f.origin.z() + f.height(r, c), z11 = f.origin.z() + f.height(r + 1, c + 1);
  return std::max({z00, z11, f.origin.z() + (t == 0 ? f.height(r, c + 1) : f.height(r + 1, c))});
}

/// Whether prism t of cell (r, c), its box from `base_z` (m) to its top
/// (prismTop), comes within `reach` (m) of `point`: exactly
/// Terrain::within's test on the prism's bounds.
inline bool prismBoxWithin(const Heightfield& f, int r, int c, int t, double base_z, const Eigen::Vector3d& point,
                           double reach) {
  const double top = prismTop(f, r, c, t);
  const Aabb box{{f.origin.x() + c * f.spacing_x, f.origin.y() + r * f.spacing_y, base_z},
                 {f.origin.x() + (c + 1) * f.spacing_x, f.origin.y() + (r + 1) * f.spacing_y, top}};
  return point.z() - reach <= top && box.squaredDistance(point) <= reach * reach;
}

}  // namespace wtc::detail
