#pragma once
// Where a wheel rests: the centre above (x, y) whose deepest contact is
// `depth` deep in the actual pieces (not in the smooth relief a terrain was
// sampled from: flat cells and mesh jitter move the resting height by up to
// 11 mm). Shared by the wheel benchmarks so that every timed query touches.
//
// The deepest depth falls as the wheel rises, so: a bracket of half-width
// kGuessBracketM around the caller's guess, widened until its bottom is
// deeper than `depth` and its top shallower (widening stops at r_f: a failure
// shows up as a wrong depth), then bisection to kBisectionM, keeping the top
// (depth <= `depth`).
#include <algorithm>

#include <wtc/contact/wheel_contact.hpp>

namespace wtc::bench {

inline constexpr double kGuessBracketM = 0.01;  // first half-width of the height bracket (m)
inline constexpr double kBisectionM = 1e-8;     // bisection stops at this bracket width (m)

struct Placement {
  Eigen::Vector3d centre;
  double depth;  // of the deepest contact there (m)
};

inline Placement restingCentre(const Terrain& terrain, WheelContactFinder& finder, const WheelGeometry& wheel,
                               const Eigen::Vector3d& axle, const ContactOptions& options, double x, double y,
                               double guess_z, double depth) {
  auto depthAt = [&](double z) {
    double deepest = 0.0;
    for (const WheelContact& c : finder.find(terrain, wheel, {{x, y, z}, axle}, options)) {
      deepest = std::max(deepest, c.deflection);
    }
    return deepest;
  };
  const double r = wheel.free_radius;
  double low = guess_z - kGuessBracketM, high = guess_z + kGuessBracketM;
  for (double widen = kGuessBracketM; widen <= r && depthAt(low) <= depth; widen *= 2.0) low -= widen;
  double high_depth = depthAt(high);
  for (double widen = kGuessBracketM; widen <= r && high_depth > depth; widen *= 2.0) {
    high += widen;
    high_depth = depthAt(high);
  }
  while (high - low > kBisectionM) {
    const double z = 0.5 * (low + high);
    const double d = depthAt(z);
    if (d > depth) {
      low = z;
    } else {
      high = z;
      high_depth = d;
    }
  }
  return {{x, y, high}, high_depth};
}

}  // namespace wtc::bench
