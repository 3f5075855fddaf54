#pragma once
// The memory of a terrain's soft ground (issue 55, the ground that
// remembers; docs/soft-soil.md): one grid per soil region of the terrain
// (wtc/terrain/soil_region.hpp), each node keeping its plastic sinkage and
// the largest pressure it has carried. A wheel whose WheelState is given
// one (WheelState::setGroundMemory) meets, in a region, the surface the
// wheels before it left, and leaves its own: every node under its soil arc,
// pressed by the rim to depth Z, keeps the foot of the unloading line it is
// on (pressedSoil, wtc/tyre/wheel_soil.hpp). Outside the regions a soil
// forgets (part 1). The engine plugins hold one per world.
//
// Not thread-safe: the wheels of one world write it in turn, as an engine
// steps them; a world per thread needs a memory per world.
#include <cstddef>
#include <functional>
#include <memory>

#include "wtc/terrain/terrain.hpp"
#include "wtc/tyre/wheel_soil.hpp"

namespace wtc {
namespace detail {
struct GroundMemoryAccess;
}  // namespace detail

class GroundMemory {
 public:
  /// A grid for each of terrain.soilRegions() (validated when the terrain
  /// was built); nothing is allocated until a wheel presses a node.
  explicit GroundMemory(const Terrain& terrain);
  ~GroundMemory();
  GroundMemory(GroundMemory&&) noexcept;
  GroundMemory& operator=(GroundMemory&&) noexcept;
  GroundMemory(const GroundMemory&) = delete;
  GroundMemory& operator=(const GroundMemory&) = delete;

  /// The regions' count (0: the ground forgets everywhere).
  std::size_t regionCount() const;
  /// What the ground remembers at world (x, y): the nodes around it
  /// interpolated (bilinear); fresh outside every region and where no
  /// wheel has pressed.
  SoilMemory at(double x, double y) const;
  /// Nodes pressed so far, and the memory they hold (bytes, the regions'
  /// tiles and indices): what a long run costs.
  std::size_t touchedNodes() const;
  /// Calls visit(x, y, memory) for every pressed node of every region, at
  /// its world (x, y), in no set order (the replay page draws the ruts from
  /// it; a node raised by bulldozing has a negative plastic sinkage).
  void forEachTouchedNode(const std::function<void(double x, double y, const SoilMemory& memory)>& visit) const;
  std::size_t bytes() const;
  /// Writes the node at world (x, y) as `memory` (its max_pressure rounded
  /// up to the stored precision): a node forEachTouchedNode gave, back
  /// (ruts saved by one run and read by another, wtc/io/ground_memory_file.hpp).
  /// False, and nothing written, where (x, y) is no region's node (within
  /// tolerance::kSoilNodeRelative of its spacing) or memory is not finite in
  /// single precision (or its pressure is negative).
  bool setNode(double x, double y, const SoilMemory& memory);
  /// Forgets every rut (a new run on the same terrain).
  void clear();

 private:
  friend struct detail::GroundMemoryAccess;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace wtc
