#pragma once
// The vehicle's start against its terrain (wtc::sim, private): a body whose
// collision shape starts inside the ground is thrown out by the engine's
// own contact in the first step. A bumper placed 5 mm in left at about
// 1 m/s, and Bullet flipped the robot 174 deg, with no word (issue 57
// row 4). runScene says so before the run, as a warning; the energy balance
// counts that step (energy_balance.hpp).
//
// Each shape is looked at by its points: a box's corners, a hull's
// vertices, a sphere's lowest point, a cylinder's two rims (kRimPoints
// each); a point inside a terrain piece is inside by the piece's exact
// signed distance (ConvexPolyhedron::planeBound). An edge through a thin
// ridge with no point inside is not seen: the check is for bodies placed
// into the ground, not a collision detector. Wheels are left out: WTC's
// tyre meets the ground by its deflection, which is no overlap.
#include <span>
#include <string>
#include <vector>

#include "wtc/terrain/terrain.hpp"
#include "wtc/vehicle/controller.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::sim::detail {

/// One line per body whose shape starts more than kStartOverlapM inside the
/// terrain: "body 'bumper' starts 5.0 mm inside the terrain (its deepest
/// point at (x, y, z) m): the engine throws it out in the first step",
/// for the bodies at `bodies` (the engine's start state, body order).
std::vector<std::string> startOverlaps(const Terrain& terrain, const vehicle::VehicleDescription& vehicle,
                                       std::span<const vehicle::BodyKinematics> bodies);

}  // namespace wtc::sim::detail
