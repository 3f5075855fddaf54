#pragma once
// A vehicle body's collision shape as convex hulls in its centre-of-mass
// frame: what a body on soft soil presses (wtc/tyre/body_soil.hpp; issue 55,
// a belly dragging in sand). A box and a hull are exact; a cylinder is a
// prism of kCylinderHullSides sides about it, a sphere the hull of
// kSphereHullRings rings of points on it, both circumscribed by their
// points lying on the surface: the hull is inside the solid, below its
// curve by at most r (1 - cos(pi / sides)) (0.5 % of r at 32 sides).
#include <vector>

#include "wtc/geometry/convex_polyhedron.hpp"
#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::vehicle {

/// Sides of a cylinder's prism (count).
inline constexpr int kCylinderHullSides = 32;
/// Rings of a sphere's hull from pole to pole, each of 2 kSphereHullRings
/// points (count).
inline constexpr int kSphereHullRings = 16;

/// The hulls of `body`'s collision shape (its compound's parts, or its
/// shape), in its centre-of-mass frame (Body::pose); empty for a body
/// without one (Shape::Kind::kNone).
std::vector<ConvexPolyhedron> convexHulls(const Body& body);

/// One shape's hull in its own frame (Shape::Kind::kNone: InvalidInputError).
ConvexPolyhedron convexHull(const Shape& shape);

}  // namespace wtc::vehicle
