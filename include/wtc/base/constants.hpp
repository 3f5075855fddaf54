#pragma once
// Physical constants and the bounds of a description, with units, in one
// place (the constants of whole-vehicle runs: wtc/sim/sim_constants.hpp).
#include <numbers>

namespace wtc {
/// Degrees in a radian: what a report in degrees multiplies an angle by.
inline constexpr double kDegPerRad = 180.0 / std::numbers::pi;

/// Gravitational acceleration used by every scene, test and benchmark
/// (m/s^2), along -z of the world.
inline constexpr double kGravityMps2 = 9.81;

/// The largest length a description may give (m): a size, a radius, a
/// thickness, a height, a piece's or a body's distance from the origin.
/// A run stops a body that goes this far (sim::kDivergedDistanceM), so no
/// run drives on or with anything larger; and values far beyond it (1e300)
/// lose the rest of a shape to rounding (a 1 m box at 1e300 m has all its
/// corners at one point), which would surface as a geometric error far
/// from the value at fault. Checked where the value is read, with the
/// value named.
inline constexpr double kMaxLengthM = 1e6;

}  // namespace wtc
