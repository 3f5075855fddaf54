// Slabs, inclines, ledges, stairs and boxes as convex pieces. Each builder
// checks its parameters, then adds boxes (or the one wedge) in the local
// frame L placed by pose_WL. Tile boundaries are computed by one formula
// (lo + length * i / n) so adjacent tiles share bit-identical faces.
#include "wtc/terrain/terrain_primitives.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "builder_support.hpp"
#include "wtc/base/checks.hpp"
#include "wtc/base/error.hpp"
#include "wtc/terrain/heightfield.hpp"

namespace wtc {
namespace {


// The i-th of n equal divisions of [lo, lo + length].
double division(double lo, double length, int i, int n) {
  return i == n ? lo + length : lo + length * static_cast<double>(i) / static_cast<double>(n);
}

// Vertex i of the box [min, max]: bit 0 picks x, bit 1 y, bit 2 z. Faces
// counter-clockwise from outside: -x, +x, -y, +y, -z, +z (as in
// ConvexPolyhedron::box).
const std::vector<std::vector<int>>& boxFaces() {
  static const std::vector<std::vector<int>> kFaces = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                                       {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  return kFaces;
}

// No builder.reserve here: a reserve per small call would defeat the
// vector's geometric growth and make many small primitives quadratic.
PieceRange addPieces(TerrainBuilder& builder, std::vector<ConvexPolyhedron> pieces, MaterialId material) {
  PieceRange range{static_cast<PieceId>(builder.pieceCount()), 0};
  for (auto& piece : pieces) {
    builder.addPiece(std::move(piece), material);
    ++range.count;
  }
  return range;
}

}  // namespace

ConvexPolyhedron makeBox(const Eigen::Vector3d& min_L, const Eigen::Vector3d& max_L, const Eigen::Isometry3d& pose_WL) {
  requireRigid(pose_WL, "wtc::makeBox", "pose_WL");
  if (pose_WL.linear() == Eigen::Matrix3d::Identity()) {
    return ConvexPolyhedron::box(pose_WL * min_L, pose_WL * max_L);
  }
  if (!min_L.allFinite() || !max_L.allFinite() || !(min_L.array() < max_L.array()).all()) {
    throw InvalidInputError("wtc::makeBox: needs finite min < max on every axis, got min = " + formatVector(min_L) +
                            ", max = " + formatVector(max_L));
  }
  std::vector<Eigen::Vector3d> v(8);
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d corner{(i & 1) ? max_L.x() : min_L.x(), (i & 2) ? max_L.y() : min_L.y(),
                                 (i & 4) ? max_L.z() : min_L.z()};
    v[i] = pose_WL * corner;
  }
  return ConvexPolyhedron::fromMesh(v, boxFaces());
}

PieceRange addSlab(TerrainBuilder& builder, const SlabParams& p, MaterialId material) {
  constexpr const char* kWhere = "wtc::addSlab";
  requireLength(p.size_x, kWhere, "size_x");
  requireLength(p.size_y, kWhere, "size_y");
  requireLength(p.thickness, kWhere, "thickness");
  requireAtLeast(p.tiles_x, 1, kWhere, "tiles_x");
  requireAtLeast(p.tiles_y, 1, kWhere, "tiles_y");
  requireRigid(p.pose_WL, kWhere, "pose_WL");
  builder.requireRoomFor(static_cast<std::uint64_t>(p.tiles_x) * static_cast<std::uint64_t>(p.tiles_y),
                         std::string(kWhere) + " (tiles_x x tiles_y)");
  std::vector<ConvexPolyhedron> pieces;
  pieces.reserve(static_cast<std::size_t>(p.tiles_x) * static_cast<std::size_t>(p.tiles_y));
  for (int j = 0; j < p.tiles_y; ++j) {
    for (int i = 0; i < p.tiles_x; ++i) {
      const Eigen::Vector3d lo{division(-0.5 * p.size_x, p.size_x, i, p.tiles_x),
                               division(-0.5 * p.size_y, p.size_y, j, p.tiles_y), -p.thickness};
      const Eigen::Vector3d hi{division(-0.5 * p.size_x, p.size_x, i + 1, p.tiles_x),
                               division(-0.5 * p.size_y, p.size_y, j + 1, p.tiles_y), 0.0};
      pieces.push_back(makeBox(lo, hi, p.pose_WL));
    }
  }
  return addPieces(builder, std::move(pieces), material);
}

PieceRange addIncline(TerrainBuilder& builder, const InclineParams& p, MaterialId material) {
  constexpr const char* kWhere = "wtc::addIncline";
  if (!(std::isfinite(p.angle) && p.angle > 0.0 && p.angle < 0.5 * std::numbers::pi)) {
    throw InvalidInputError(std::string(kWhere) + ": angle = " + formatNumber(p.angle) + " must be in (0, pi/2) (rad)");
  }
  requireLength(p.length, kWhere, "length");
  requireLength(p.width, kWhere, "width");
  requireLength(p.thickness, kWhere, "thickness");
  requireNonNegativeLength(p.top_length, kWhere, "top_length");
  requireRigid(p.pose_WL, kWhere, "pose_WL");
  const double rise = p.length * std::tan(p.angle);
  const double y = 0.5 * p.width;
  // Cross-section in the x-z plane: (0, -t), (L, -t), (L, rise), (0, 0),
  // vertices 0-3 at y = -w/2 and 4-7 at y = +w/2.
  const double xz[4][2] = {{0.0, -p.thickness}, {p.length, -p.thickness}, {p.length, rise}, {0.0, 0.0}};
  std::vector<Eigen::Vector3d> v;
  for (double side : {-y, y}) {
    for (const auto& c : xz) v.push_back(p.pose_WL * Eigen::Vector3d(c[0], side, c[1]));
  }
  // Counter-clockwise from outside: -y, +y, bottom, back (+x), front (-x), ramp.
  static const std::vector<std::vector<int>> kWedgeFaces = {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1},
                                                            {1, 5, 6, 2}, {0, 3, 7, 4}, {3, 2, 6, 7}};
  std::vector<ConvexPolyhedron> pieces;
  pieces.push_back(ConvexPolyhedron::fromMesh(v, kWedgeFaces));
  if (p.top_length > 0.0) {
    pieces.push_back(makeBox({p.length, -y, -p.thickness}, {p.length + p.top_length, y, rise}, p.pose_WL));
  }
  return addPieces(builder, std::move(pieces), material);
}

namespace {

// LedgeParams::heightfield_spacing > 0: the ledge sampled into a heightfield.
PieceRange addSampledLedge(TerrainBuilder& builder, const LedgeParams& p, MaterialId material) {
  constexpr const char* kWhere = "wtc::addLedge";
  const double s = p.heightfield_spacing;
  if (!p.pose_WL.linear().isIdentity(0.0)) {
    throw InvalidInputError(std::string(kWhere) +
                            ": heightfield_spacing needs a pose without rotation (a heightfield is axis-aligned)");
  }
  const double front_cells = std::max(1.0, std::round(p.approach_length / s));
  const double back_cells = std::max(1.0, std::round(p.top_length / s));
  const double side_cells = std::max(1.0, std::round(p.width / s));
  const double pieces = 2.0 * (front_cells + back_cells) * side_cells;
  if (!(pieces < 4e9))
    throw InvalidInputError(std::string(kWhere) + ": heightfield_spacing " + formatNumber(s) + " m makes " +
                            formatNumber(pieces) + " pieces");
  builder.requireRoomFor(static_cast<std::uint64_t>(pieces), std::string(kWhere) + " (heightfield_spacing)");
  Heightfield field;
  field.cols = static_cast<int>(front_cells + back_cells) + 1;
  field.rows = static_cast<int>(side_cells) + 1;
  field.spacing_x = s;
  field.spacing_y = p.width / side_cells;
  field.origin = p.pose_WL.translation() + Eigen::Vector3d(-front_cells * s, -0.5 * p.width, 0.0);
  field.base_depth = p.thickness;
  field.heights.resize(static_cast<std::size_t>(field.rows) * static_cast<std::size_t>(field.cols));
  for (int r = 0; r < field.rows; ++r) {
    for (int c = 0; c < field.cols; ++c) {
      field.heights[static_cast<std::size_t>(r) * field.cols + c] = c >= static_cast<int>(front_cells) ? p.height : 0.0;
    }
  }
  return p.compact_heightfield ? addCompactHeightfield(builder, std::move(field), material)
                               : addHeightfield(builder, field, material);
}

}  // namespace

PieceRange addLedge(TerrainBuilder& builder, const LedgeParams& p, MaterialId material) {
  constexpr const char* kWhere = "wtc::addLedge";
  requireNonNegativeLength(p.height, kWhere, "height");
  requireLength(p.approach_length, kWhere, "approach_length");
  requireLength(p.top_length, kWhere, "top_length");
  requireLength(p.width, kWhere, "width");
  requireLength(p.thickness, kWhere, "thickness");
  requireAtLeast(p.approach_tiles, 1, kWhere, "approach_tiles");
  builder.requireRoomFor(static_cast<std::uint64_t>(p.approach_tiles) + 1, std::string(kWhere) + " (approach_tiles)");
  requireRigid(p.pose_WL, kWhere, "pose_WL");
  requireNonNegativeLength(p.heightfield_spacing, kWhere, "heightfield_spacing");
  if (p.heightfield_spacing > 0.0) return addSampledLedge(builder, p, material);
  const double y = 0.5 * p.width;
  std::vector<ConvexPolyhedron> pieces;
  for (int i = 0; i < p.approach_tiles; ++i) {
    pieces.push_back(makeBox({division(-p.approach_length, p.approach_length, i, p.approach_tiles), -y, -p.thickness},
                             {division(-p.approach_length, p.approach_length, i + 1, p.approach_tiles), y, 0.0},
                             p.pose_WL));
  }
  pieces.push_back(makeBox({0.0, -y, -p.thickness}, {p.top_length, y, p.height}, p.pose_WL));
  return addPieces(builder, std::move(pieces), material);
}

PieceRange addStairs(TerrainBuilder& builder, const StairsParams& p, MaterialId material) {
  constexpr const char* kWhere = "wtc::addStairs";
  requireAtLeast(p.steps, 1, kWhere, "steps");
  builder.requireRoomFor(static_cast<std::uint64_t>(p.steps), std::string(kWhere) + " (steps)");
  requireLength(p.rise, kWhere, "rise");
  requireLength(p.run, kWhere, "run");
  requireLength(p.width, kWhere, "width");
  requireLength(p.thickness, kWhere, "thickness");
  requireNonNegativeLength(p.top_length, kWhere, "top_length");
  requireRigid(p.pose_WL, kWhere, "pose_WL");
  const double y = 0.5 * p.width;
  std::vector<ConvexPolyhedron> pieces;
  for (int i = 0; i < p.steps; ++i) {
    const double x_end = (i + 1) * p.run + (i + 1 == p.steps ? p.top_length : 0.0);
    pieces.push_back(makeBox({i * p.run, -y, -p.thickness}, {x_end, y, (i + 1) * p.rise}, p.pose_WL));
  }
  return addPieces(builder, std::move(pieces), material);
}

PieceRange addBox(TerrainBuilder& builder, const BoxParams& p, MaterialId material) {
  constexpr const char* kWhere = "wtc::addBox";
  requireLength(p.size.x(), kWhere, "size.x");
  requireLength(p.size.y(), kWhere, "size.y");
  requireLength(p.size.z(), kWhere, "size.z");
  requireRigid(p.pose_WL, kWhere, "pose_WL");
  std::vector<ConvexPolyhedron> pieces;
  pieces.push_back(makeBox(-0.5 * p.size, 0.5 * p.size, p.pose_WL));
  return addPieces(builder, std::move(pieces), material);
}

}  // namespace wtc
