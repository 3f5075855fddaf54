#pragma once
// A wheel as a translating body that spins about a fixed axle direction,
// stepped by semi-implicit Euler (v += h a; x += h v), the integrator of
// Bullet and ODE, with the tyre model's forces computed at the start of each
// step. It is the smallest "engine" that exercises the model's explicit
// coupling: what these tests prove about stability and creep, an engine in
// force mode inherits. Scenes: a flat slab, or one tilted about y.
#include <Eigen/Core>

#include "wtc/terrain/terrain.hpp"
#include "wtc/tyre/tyre_model.hpp"

namespace wtc::testing {

inline constexpr double kGravityMps2 = 9.81;

struct SimWheel {
  WheelDescription description;
  double mass = 21.0;                                 ///< Body mass (kg): a sixth of the 126 kg robot.
  Eigen::Vector3d axle{Eigen::Vector3d::UnitY()};     ///< Fixed in the world.
  Eigen::Vector3d center{Eigen::Vector3d::Zero()};    ///< (m)
  Eigen::Vector3d velocity{Eigen::Vector3d::Zero()};  ///< (m/s)
  double spin = 0.0;                                  ///< omega . axle (rad/s)
  bool locked = false;                                ///< Spin held at zero (a brake).
  double drive_torque = 0.0;                          ///< About the axle (N m).
  WheelState state;
};

/// A 20 x 20 m slab of `material` whose top passes through the origin,
/// tilted by `slope_rad` about y so that it rises toward +x.
Terrain tiltedSlab(double slope_rad, const Material& material = {});

/// A flat slab (top z = 0), 40 x 40 m, optionally tiled into tiles x tiles
/// boxes (the engine tests' ground).
Terrain flatGround(int tiles = 1, const Material& material = {});

/// Two prisms meeting in a V along y through the origin, whose flanks rise
/// at `slope_rad` on each side (a shallow concave crease for small slopes).
Terrain valley(double slope_rad);

/// A flat floor `floor_width` wide (m) along y through the origin, with a
/// flank rising at `slope_rad` from each of its edges: a shallow trough, in
/// which a resting wheel has three contacts a few millimetres apart.
Terrain trough(double slope_rad, double floor_width);

/// The unit normal of tiltedSlab's top and its downhill unit direction.
Eigen::Vector3d slabNormal(double slope_rad);
Eigen::Vector3d downhill(double slope_rad);

/// Places the wheel at rest on tiltedSlab at its static deflection.
void restOnSlab(SimWheel& wheel, double slope_rad);

/// One step: the tyre model, then gravity and forces integrated.
const WheelForces& step(const TyreModel& model, const Terrain& terrain, double step_seconds, SimWheel& wheel);

}  // namespace wtc::testing
