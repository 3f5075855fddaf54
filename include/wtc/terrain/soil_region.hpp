#pragma once
// A soil region: where a terrain's soft ground remembers (issue 55;
// docs/soft-soil.md, the ground that remembers). Over the region a grid of
// nodes keeps each point's plastic sinkage and the largest pressure it has
// carried (wtc/tyre/ground_memory.hpp); elsewhere a soil forgets, each step
// loading a fresh surface (part 1). The region is a rectangle in world x, y
// over the base terrain, whose surface is the fresh one. Where the scene
// asks (flow_factor > 0), the soil a wheel presses down is partly raised
// beside its track, as a berm no steeper than the angle of repose.
#include <string>

#include <Eigen/Core>

namespace wtc {

/// The finest grid a region may have (m): below a millimetre a node is
/// smaller than a sand grain's neighbourhood the stresses average over.
inline constexpr double kMinSoilSpacingM = 1e-3;

struct SoilRegion {
  Eigen::Vector2d origin{Eigen::Vector2d::Zero()};  ///< The node (0, 0): the region's lower corner (world x, y; m).
  Eigen::Vector2d size{Eigen::Vector2d::Zero()};    ///< The region's extent along x and y (m, > 0).
  double spacing = 0.02;                            ///< Between nodes (m, >= kMinSoilSpacingM).
  /// The most the region may hold with every node touched (bytes): a
  /// region beyond it is refused before a run, not found out during one.
  double memory_cap_bytes = 2.0 * 1024 * 1024 * 1024;
  /// Bulldozing: of the soil a wheel presses down, the fraction raised
  /// beside its track ([0, 1]; 0, the default: it is compacted, as
  /// Bekker's sinkage assumes), the rest compacted.
  double flow_factor = 0.0;
  /// The steepest slope raised soil keeps (deg, (0, 90)): beyond it, it
  /// slides outward.
  double repose_angle_deg = 30.0;
};

/// Throws InvalidInputError naming `where`, the field, its value and its
/// range: a spacing below kMinSoilSpacingM, a size that is not positive,
/// anything not finite, or a region whose nodes, all touched, would pass
/// the memory cap (naming both).
void validate(const SoilRegion& region, const std::string& where);

}  // namespace wtc
