#pragma once
// Plausibility warnings for a vehicle description (wtc::vehicle): values
// that are valid but what a unit slip gives, said before a run instead of
// after a strange one (issue 57 row 8). Masses in grams make the tyres
// deflect through their wheels (8.5 cm on 8 cm wheels); lengths in
// millimetres put bodies kilometres apart; rpy in degrees turns a wheel's
// axle off the horizontal. Nothing is refused: each is a warning naming the
// body, the value and the likely slip.
#include <string>
#include <vector>

#include "wtc/vehicle/vehicle_description.hpp"

namespace wtc::vehicle {

/// A wheel's static deflection under an equal share of its tree's weight
/// (the root it hangs from and all below it), as a share of its radius, beyond which a warning is given (dimensionless):
/// tyres deflect a few percent of their radius (the shipped ones 1-12 %).
inline constexpr double kPlausibleDeflectionShare = 0.25;
/// A body's distance from the vehicle's origin, a box's edge or a wheel's
/// radius beyond which a warning is given (m): no wheeled vehicle WTC runs
/// is this large, a millimetre figure read as metres is.
inline constexpr double kPlausibleSizeM = 50.0;
/// A wheel's axle further than this from the horizontal at the reference
/// pose gives a warning (rad, 30 deg): an rpy in degrees read as radians.
inline constexpr double kPlausibleAxleTiltRad = 0.5235987755982988;

/// One line per implausible value, in body order; empty for a plausible
/// vehicle (the shipped ones).
std::vector<std::string> plausibilityWarnings(const VehicleDescription& vehicle);

}  // namespace wtc::vehicle
