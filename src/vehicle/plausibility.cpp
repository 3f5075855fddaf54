// Values that are valid but what a unit slip gives (plausibility.hpp).
#include "wtc/vehicle/plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "wtc/base/constants.hpp"

namespace wtc::vehicle {
namespace {

std::string format(const char* pattern, auto... values) {
  char text[320];
  std::snprintf(text, sizeof text, pattern, values...);
  return text;
}

}  // namespace

std::vector<std::string> plausibilityWarnings(const VehicleDescription& vehicle) {
  std::vector<std::string> out;
  // Each tree (a root and the bodies below it: the towed system's tug and
  // towed body) carries its own weight on its own wheels.
  const std::size_t n = vehicle.bodies.size();
  std::vector<std::size_t> root(n);
  std::vector<double> tree_mass(n, 0.0), tree_wheels(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const int parent = vehicle.bodies[i].parent;
    root[i] = parent < 0 ? i : root[static_cast<std::size_t>(parent)];
    tree_mass[root[i]] += vehicle.bodies[i].mass;
    if (vehicle.bodies[i].wheel) tree_wheels[root[i]] += 1.0;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Body& b = vehicle.bodies[i];
    const double share_N = tree_mass[root[i]] * kGravityMps2 / std::max(tree_wheels[root[i]], 1.0);
    const double far = b.pose.translation().norm();
    if (far > kPlausibleSizeM) {
      out.push_back(format("body '%s' is %.4g m from the vehicle's origin: lengths in millimetres?", b.name.c_str(), far));
    }
    if (b.shape.kind == Shape::Kind::kBox && b.shape.box_size.maxCoeff() > kPlausibleSizeM) {
      out.push_back(format("body '%s': a box %.4g m long: lengths in millimetres?", b.name.c_str(),
                           b.shape.box_size.maxCoeff()));
    }
    if (!b.wheel) continue;
    const double r = b.wheel->geometry.free_radius;
    if (r > kPlausibleSizeM) {
      out.push_back(format("wheel '%s': radius %.4g m: lengths in millimetres?", b.name.c_str(), r));
    }
    const double deflection = share_N / b.wheel->tyre.radial_stiffness;
    if (deflection > kPlausibleDeflectionShare * r) {
      out.push_back(format("wheel '%s': under an equal share of its body's weight (%.4g N) its tyre deflects %.3g "
                           "mm, %.0f %% of its radius (%.3g mm): masses in grams, or a tyre far too soft? (tyres "
                           "deflect a few %% of their radius)",
                           b.name.c_str(), share_N, deflection * 1e3, 100.0 * deflection / r, r * 1e3));
    }
    const Eigen::Vector3d axle = b.pose.linear() * b.wheel->axle;
    const double tilt = std::asin(std::min(1.0, std::abs(axle.z()) / axle.norm()));
    if (tilt > kPlausibleAxleTiltRad) {
      out.push_back(format("wheel '%s': its axle is %.0f deg off the horizontal at the reference pose: an rpy in "
                           "degrees read as radians?",
                           b.name.c_str(), tilt * 180.0 / std::numbers::pi));
    }
  }
  return out;
}

}  // namespace wtc::vehicle
