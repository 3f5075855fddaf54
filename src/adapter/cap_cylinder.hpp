#pragma once
// The cut sphere's caps as a cylinder (internal to the engine adapters):
// where the ground touches a cap (a wheel on its side), WTC gives no force
// and each adapter lets its engine collide a cylinder whose two faces are
// the caps (Bullet: wheel_terrain_algorithm.cpp; ODE: Plugin collideCaps).
// The wheel is the sphere of radius r_f cut by two planes w / 2 either side
// of its centre along the axle, so each cap is a disc of radius
// sqrt(r_f^2 - (w/2)^2), and the cylinder between them has that radius and
// height w. A wheel as wide as its sphere (w >= 2 r_f) has no caps: a
// cylinder of radius 0 and height 2 r_f.
#include "wtc/contact/wheel_contact.hpp"

namespace wtc {

struct CapCylinder {
  double radius = 0.0;       ///< The caps' radius (m), >= 0.
  double half_height = 0.0;  ///< Half the distance between the caps (m): min(w, 2 r_f) / 2.
};

CapCylinder capCylinder(const WheelGeometry& geometry);

}  // namespace wtc
