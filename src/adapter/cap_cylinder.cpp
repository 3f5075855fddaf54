#include "cap_cylinder.hpp"

#include <algorithm>
#include <cmath>

namespace wtc {

CapCylinder capCylinder(const WheelGeometry& g) {
  CapCylinder c;
  c.half_height = 0.5 * std::min(g.tread_width, 2.0 * g.free_radius);
  c.radius = std::sqrt(std::max(g.free_radius * g.free_radius - c.half_height * c.half_height, 0.0));
  return c;
}

}  // namespace wtc
