#pragma once
// What of a terrain a run's replay page draws (wtc::sim::Replay), within a
// budget of kReplayTerrainMaxTriangles (include/wtc/sim/sim_constants.hpp), so that
// the page stays small and quick whatever the terrain. Three ways, the
// first that fits:
//
//   kWhole   every piece's faces (every shipped terrain: they are small);
//   kRegion  the faces of the pieces whose boxes overlap the region: the
//            bodies' positions over the run, padded horizontally by
//            kReplayTerrainMarginM, and the terrain's whole height;
//   kGrid    the region's top surface (the highest piece at each point)
//            sampled on a square grid as coarse as the budget asks, two
//            triangles a cell; points with no ground under them (a hole,
//            past the terrain's edge) leave their cells out. Steps and
//            walls become slopes one cell wide, rocks lumps.
//
// Faces that look down (outward normal z below -0.7) are left out in every
// way: nobody sees them from above.
#include <optional>
#include <string>
#include <vector>

#include "wtc/geometry/aabb.hpp"
#include "wtc/sim/sim_constants.hpp"
#include "wtc/terrain/terrain.hpp"

namespace wtc::sim {

struct ReplayTerrain {
  enum class Kind { kWhole, kRegion, kGrid };
  Kind kind = Kind::kWhole;
  std::vector<long long> positions;  ///< x y z of each vertex (mm, rounded: what the page reads).
  std::vector<long long> indices;    ///< Three vertex indices per triangle, counter-clockwise seen from outside.
  Aabb region;                       ///< kRegion, kGrid: the part drawn (m; x, y and the terrain's z).
  double grid_spacing_m = 0.0;       ///< kGrid: the grid's spacing (m).
  long long full_triangles = 0;      ///< kRegion, kGrid: at most this many triangles drew the whole terrain.

  long long triangles() const { return static_cast<long long>(indices.size() / 3); }
  /// What the page tells its viewer ("" for kWhole): "terrain within 10 m
  /// of the path", "... as a 0.12 m height grid".
  std::string note() const;
};

/// The terrain drawn within `max_triangles` (> 0) around `path`: the box of
/// every body's positions over the run (m; only x and y are used).
ReplayTerrain replayTerrain(const Terrain& terrain, const Aabb& path,
                            long long max_triangles = kReplayTerrainMaxTriangles);

/// The terrain's top on the vertical line through (x, y): the highest of
/// its pieces there, or nullopt where there is no ground.
std::optional<double> terrainTopAt(const Terrain& terrain, double x, double y);

}  // namespace wtc::sim
