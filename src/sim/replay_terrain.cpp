#include "wtc/sim/replay_terrain.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "replay_mm.hpp"
#include "wtc/base/error.hpp"
#include "wtc/base/tolerances.hpp"

namespace wtc::sim {
namespace {

// Faces whose outward normal's z is below this look down: left out.
constexpr double kDownFacingNz = -0.7;
// A formed piece is the prism of a heightfield's or a mesh's triangle: two
// triangles and three quads, so at most 8 triangles drawn.
constexpr long long kFormedPieceMaxTriangles = 8;

// The triangles appendPiece draws of `piece`.
long long drawnTriangles(const ConvexPolyhedron& piece) {
  long long n = 0;
  for (int f = 0; f < piece.faceCount(); ++f) {
    if (piece.faceNormal(f).z() >= kDownFacingNz) n += static_cast<long long>(piece.faceVertices(f).size()) - 2;
  }
  return n;
}

// At most the triangles appendPiece draws of piece `id`, without forming it.
long long triangleBound(const Terrain& terrain, PieceId id) {
  return terrain.isFormed(id) ? kFormedPieceMaxTriangles : drawnTriangles(terrain.piece(id));
}

// At most the triangles of every piece (a compact part's pieces counted, not formed).
long long wholeBound(const Terrain& terrain) {
  long long n = 0;
  for (std::size_t k = 0; k < terrain.compactFieldCount(); ++k) {
    n += kFormedPieceMaxTriangles * terrain.compactField(k).count;
  }
  for (const ConvexPolyhedron& piece : terrain.pieces()) n += drawnTriangles(piece);
  return n;
}

// The piece's vertices, and its faces that do not look down as fans (faces
// are convex).
void appendPiece(const ConvexPolyhedron& piece, ReplayTerrain& out) {
  const auto base = static_cast<long long>(out.positions.size() / 3);
  for (int v = 0; v < piece.vertexCount(); ++v) {
    const Eigen::Vector3d p = piece.vertex(v);
    out.positions.insert(out.positions.end(), {replayMm(p.x()), replayMm(p.y()), replayMm(p.z())});
  }
  for (int f = 0; f < piece.faceCount(); ++f) {
    if (piece.faceNormal(f).z() < kDownFacingNz) continue;
    const auto face = piece.faceVertices(f);
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      out.indices.insert(out.indices.end(), {base + face[0], base + face[k], base + face[k + 1]});
    }
  }
}

// The top of `piece` on the vertical line through (x, y), or nullopt if the
// line misses it. The line is inside the piece where n . p <= d for every
// face plane: a face with n_z > 0 bounds z from above, one with n_z < 0
// from below, a vertical one holds or excludes the whole line.
std::optional<double> topAt(const ConvexPolyhedron& piece, double x, double y) {
  const double slack = tolerance::kReplayGridSlackRelative * piece.bounds().extent().norm();
  double low = -std::numeric_limits<double>::infinity(), high = std::numeric_limits<double>::infinity();
  for (int f = 0; f < piece.faceCount(); ++f) {
    const Eigen::Vector3d n = piece.faceNormal(f);
    const double room = piece.faceOffset(f) - n.x() * x - n.y() * y;  // n_z z <= room
    if (n.z() > 0.0) {
      high = std::min(high, room / n.z());
    } else if (n.z() < 0.0) {
      low = std::max(low, room / n.z());
    } else if (room < -slack) {
      return std::nullopt;
    }
  }
  if (!(low <= high + slack)) return std::nullopt;
  return high;
}

// The highest of the pieces' tops on the vertical line through (x, y)
// between z_low and z_high, or nullopt where no piece is (`near` and
// `scratch`: the caller's, reused).
std::optional<double> highestTop(const Terrain& terrain, double x, double y, double z_low, double z_high,
                                 std::vector<PieceId>& near, std::optional<ConvexPolyhedron>& scratch) {
  near.clear();
  terrain.overlapping({{x, y, z_low}, {x, y, z_high}}, near);
  std::optional<double> top;
  for (const PieceId id : near) {
    if (const auto z = topAt(terrain.piece(id, scratch), x, y); z && (!top || *z > *top)) top = z;
  }
  return top;
}

// The region's top surface on a grid of at most `max_triangles` triangles.
void appendGrid(const Terrain& terrain, long long max_triangles, ReplayTerrain& out) {
  const double width = out.region.extent().x(), depth = out.region.extent().y();
  const long long cells = max_triangles / 2;  // two triangles a cell
  if (!(width > 0.0 && depth > 0.0) || cells < 1) return;
  // nx ny <= cells, nx / ny about width / depth: cells about square.
  const long long ny =
      std::clamp(static_cast<long long>(std::sqrt(static_cast<double>(cells) * depth / width)), 1LL, cells);
  const long long nx = std::max(1LL, cells / ny);
  const double sx = width / static_cast<double>(nx), sy = depth / static_cast<double>(ny);
  out.grid_spacing_m = std::max(sx, sy);
  std::vector<long long> vertex((nx + 1) * (ny + 1), -1);  // index of grid point (i, j), -1: no ground
  std::vector<PieceId> near;
  std::optional<ConvexPolyhedron> scratch;
  for (long long j = 0; j <= ny; ++j) {
    for (long long i = 0; i <= nx; ++i) {
      const double x = out.region.min.x() + static_cast<double>(i) * sx;
      const double y = out.region.min.y() + static_cast<double>(j) * sy;
      const std::optional<double> top =
          highestTop(terrain, x, y, out.region.min.z(), out.region.max.z(), near, scratch);
      if (!top) continue;
      vertex[j * (nx + 1) + i] = static_cast<long long>(out.positions.size() / 3);
      out.positions.insert(out.positions.end(), {replayMm(x), replayMm(y), replayMm(*top)});
    }
  }
  // Cell (i, j): corners a (i, j), b (i + 1, j), c (i + 1, j + 1), d (i, j + 1),
  // triangles abc and acd, counter-clockwise seen from above.
  for (long long j = 0; j < ny; ++j) {
    for (long long i = 0; i < nx; ++i) {
      const long long a = vertex[j * (nx + 1) + i], b = vertex[j * (nx + 1) + i + 1];
      const long long c = vertex[(j + 1) * (nx + 1) + i + 1], d = vertex[(j + 1) * (nx + 1) + i];
      if (a >= 0 && b >= 0 && c >= 0) out.indices.insert(out.indices.end(), {a, b, c});
      if (a >= 0 && c >= 0 && d >= 0) out.indices.insert(out.indices.end(), {a, c, d});
    }
  }
}

std::string metres(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

}  // namespace

std::string ReplayTerrain::note() const {
  switch (kind) {
    case Kind::kWhole:
      return {};
    case Kind::kRegion:
      return "terrain within " + metres(kReplayTerrainMarginM) + " m of the path";
    case Kind::kGrid:
      return "terrain within " + metres(kReplayTerrainMarginM) + " m of the path, as a " + metres(grid_spacing_m) +
             " m height grid";
  }
  return {};
}

ReplayTerrain replayTerrain(const Terrain& terrain, const Aabb& path, long long max_triangles) {
  if (max_triangles <= 0) {
    throw InvalidInputError("wtc::sim::replayTerrain: a budget of " + std::to_string(max_triangles) +
                            " triangles (must be > 0)");
  }
  ReplayTerrain out;
  std::optional<ConvexPolyhedron> scratch;
  out.full_triangles = wholeBound(terrain);
  if (out.full_triangles <= max_triangles) {
    for (PieceId id = 0; id < static_cast<PieceId>(terrain.pieceCount()); ++id) {
      appendPiece(terrain.piece(id, scratch), out);
    }
    return out;
  }
  // The region: the path padded, within the terrain's bounds, at its whole height.
  const Aabb& bounds = terrain.bounds();
  const Eigen::Vector3d margin(kReplayTerrainMarginM, kReplayTerrainMarginM, 0.0);
  out.region.min = (path.min - margin).cwiseMax(bounds.min);
  out.region.max = (path.max + margin).cwiseMin(bounds.max);
  out.region.min.z() = bounds.min.z();
  out.region.max.z() = bounds.max.z();
  out.kind = ReplayTerrain::Kind::kRegion;
  if (!(out.region.min.array() <= out.region.max.array()).all()) {
    out.region.max = out.region.min;  // the path never came near the terrain: nothing to draw
    return out;
  }
  std::vector<PieceId> ids;
  terrain.overlapping(out.region, ids);
  std::sort(ids.begin(), ids.end());  // the terrain's own order, as drawn whole
  long long bound = 0;
  for (std::size_t k = 0; k < ids.size() && bound <= max_triangles; ++k) bound += triangleBound(terrain, ids[k]);
  if (bound <= max_triangles) {
    for (const PieceId id : ids) appendPiece(terrain.piece(id, scratch), out);
    return out;
  }
  out.kind = ReplayTerrain::Kind::kGrid;
  appendGrid(terrain, max_triangles, out);
  return out;
}

std::optional<double> terrainTopAt(const Terrain& terrain, double x, double y) {
  std::vector<PieceId> near;
  std::optional<ConvexPolyhedron> scratch;
  const Aabb box = terrain.bounds();
  return highestTop(terrain, x, y, box.min.z(), box.max.z(), near, scratch);
}

}  // namespace wtc::sim
