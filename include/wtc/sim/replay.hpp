#pragma once
// What a run's replay page draws (wtc::sim): the terrain's faces, the
// vehicle's shapes, and frames at a fixed rate of every body's pose and
// every wheel contact's point and force. Written as one JavaScript file
// (`const WTC_REPLAY = {...};`) so that a page opened from disk can load
// it with a <script> tag (browsers refuse fetch() on file:// URLs).
//
// On soil that remembers (a terrain's soil regions) it also keeps the ruts:
// every kReplaySoilPeriodS of simulated time, at a frame, and at the run's
// end, the nodes of the ground's memory whose plastic sinkage changed since
// (the page draws a square per pressed node, coloured by its sinkage, from
// that frame on).
//
// Numbers are quantised to keep a long run small: positions in mm,
// quaternions in 1e-4, forces in N, times in ms, sinkages in 0.1 mm
// (integers). The terrain is what replayTerrain (wtc/sim/replay_terrain.hpp)
// draws around the bodies' path over the run, within a budget of triangles,
// with a note that says when it is not the whole terrain.
#include <cstdint>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

#include "wtc/geometry/aabb.hpp"
#include "wtc/sim/run.hpp"
#include "wtc/sim/run_observer.hpp"
#include "wtc/sim/run_summary.hpp"
#include "wtc/sim/scene.hpp"

namespace wtc::sim {

class Replay final : public RunObserver {
 public:
  /// Frames every 1 / fps of simulated time (fps > 0).
  Replay(const Scene& scene, double fps);
  /// Call after every step (and once before the first): keeps a frame when
  /// its time has come.
  void observe(const Run& run) override;
  /// Writes the data file. Throws InvalidInputError naming a path it
  /// cannot write.
  void write(const std::filesystem::path& path, const RunSummary& summary) const;
  std::size_t frames() const { return times_ms_.size(); }
  /// The box of every body's position in the frames so far (m; empty, min
  /// above max, before the first).
  Aabb pathBounds() const;

 private:
  const Scene& scene_;
  double period_;
  std::uint64_t last_step_;  // the run's step count: its end
  double next_ = 0.0;
  std::vector<long long> times_ms_;
  std::vector<long long> poses_;                  // per frame: per body x y z (mm) qw qx qy qz (1e-4)
  std::vector<std::vector<long long>> contacts_;  // per frame: per contact px py pz (mm) fx fy fz (N)
  void keepSoil(const Run& run);
  double soil_spacing_ = 0.0;  // the finest region's (m); 0: no soil regions
  double next_soil_ = 0.0;
  std::vector<long long> soil_nodes_;  // per node drawn: x y (mm) and the terrain's top there (mm)
  struct ShownNode {
    std::size_t index;
    long long sinkage;  // 0.1 mm
  };
  std::unordered_map<std::uint64_t, ShownNode> soil_shown_;  // by the node's (x, y) in mm
  std::vector<std::vector<long long>> soil_updates_;         // per snapshot: frame, then node, sinkage (0.1 mm) pairs
};

}  // namespace wtc::sim
