#pragma once
// Which of a vehicle's bodies meet soft soil in a run, and their shapes
// (internal to the sim engines): with the soft_soil effect on a terrain
// that has a soil, every body that is not a wheel and has a collision
// shape presses the soil under it (wtc/tyre/body_soil.hpp, through the
// engine's plugin: addSoilBody); without the effect the soil pieces are
// hard ground for the bodies, as they are for the wheels (a scene computes
// only what it asks for).
#include <vector>

#include "wtc/geometry/convex_polyhedron.hpp"
#include "wtc/sim/engine.hpp"
#include "wtc/terrain/terrain.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::sim {

struct SoilBodyShape {
  int body = -1;                        ///< Its index in the vehicle's bodies.
  std::vector<ConvexPolyhedron> hulls;  ///< In its centre-of-mass frame (vehicle::convexHulls).
};

std::vector<SoilBodyShape> soilBodyShapes(const EngineSettings& settings, const Terrain& terrain,
                                          const vehicle::VehicleDescription& vehicle);

}  // namespace wtc::sim
