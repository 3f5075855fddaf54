#pragma once
// What the soil contact needs of a GroundMemory (internal to wtc::core):
// the grid under a point, to read a wheel's profile from (GridProfile) and
// to press its nodes (pressNodes).
#include <Eigen/Core>

#include "soil_grid_profile.hpp"
#include "terrain/soil_grid.hpp"
#include "wtc/terrain/soil.hpp"
#include "wtc/tyre/ground_memory.hpp"

namespace wtc::detail {

struct GroundMemoryAccess {
  /// The region's grid holding world (x, y), or null outside every region.
  static SoilGrid* gridAt(GroundMemory& memory, double x, double y);
};

/// A rim pressing a region's nodes: every node within the wheel's band
/// (|across| <= width / 2 about `bottom`, along the horizontal `travel`)
/// behind the rim's lowest point, and ahead of it as far as the wheel is at
/// rest (-r sin theta_1 <= s <= at_rest r sin theta_1), lies at depth
/// Z(s) = depth - (r - sqrt(r^2 - s^2)) under the rim, depth the rim's
/// lowest point below the fresh surface, and keeps pressedSoil(soil, width,
/// its memory, Z(s)). A rolling wheel leaves the ground ahead of its lowest
/// point fresh, on part 1's virgin curve, until that point has passed (the
/// deepest it presses a point; behind it, where the rim rises, pressedSoil
/// changes nothing); a wheel at rest presses the whole hollow it sits in.
/// A ball's surface rises across the band too: Z = depth - (r - sqrt(r^2 -
/// s^2 - y^2)), y the node's offset across, its band the patch's width.
struct RimPress {
  Eigen::Vector2d bottom, travel;
  double radius, width, depth, entry_angle;
  double at_rest;     ///< The contact's symmetry, [0, 1] (WheelSoilState::symmetry).
  bool ball = false;  ///< A sphere's patch (sphereSoilForces), not a cylinder's band.
};
void pressNodes(SoilGrid& grid, const Soil& soil, const RimPress& press);

}  // namespace wtc::detail
