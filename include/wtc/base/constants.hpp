#pragma once
// Physical constants, with units, in one place.
namespace wtc {

/// Gravitational acceleration used by every scene, test and benchmark
/// (m/s^2), along -z of the world.
inline constexpr double kGravityMps2 = 9.81;

}  // namespace wtc
