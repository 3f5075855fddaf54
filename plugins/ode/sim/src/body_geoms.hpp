#pragma once
// A vehicle body's collision shape as ODE geoms on its body: a box,
// cylinder or sphere, or a compound of them and convex hulls (a URDF link's
// collision elements), each geom at its part's offset from the body. ODE
// has no compound geom: several geoms on one body are its compound, and
// the sim engine's near callback tells bodies apart by dGeomGetBody.
#include <deque>
#include <vector>

#include <ode/ode.h>

#include "sim/placed_shape.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::ode {

/// What ODE's convex geoms point into (dCreateConvex copies nothing): kept
/// as long as the geoms, by the engine.
struct ConvexGeomData {
  std::vector<dReal> numbers;          ///< points (3 a vertex), then planes (4 a face)
  std::vector<unsigned int> polygons;  ///< per face: its vertex count, then its vertices
};

/// Creates body's shape geoms in `space` on `b` (none for Kind::kNone and
/// no compound) and returns the first, or null.
dGeomID addBodyGeoms(const vehicle::Body& body, dSpaceID space, dBodyID b, std::deque<ConvexGeomData>& convex);

/// A geom of a body as the engine-free contact rules see it: a box, sphere
/// or cylinder (ODE's along its z) where it is now; kOther for a hull.
sim::PlacedShape placedShape(dGeomID geom);

}  // namespace wtc::ode
