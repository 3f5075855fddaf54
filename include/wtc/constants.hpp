#pragma once
// Physical constants, with units, in one place.
namespace wtc {

/// Gravitational acceleration used by every scene, test and benchmark
/// (m/s^2), along -z of the world.
inline constexpr double kGravityMps2 = 9.81;

}  // namespace wtc

namespace wtc {

/// Coulomb friction of a vehicle's non-wheel bodies (chassis, carriers)
/// against the ground, in every engine (dimensionless): what a steel frame
/// scraping asphalt has, roughly; only off-design contacts use it.
inline constexpr double kBodyGroundFriction = 0.6;

}  // namespace wtc
