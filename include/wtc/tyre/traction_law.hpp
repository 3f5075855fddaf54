#pragma once
// The traction law of the wheel-terrain model (section 4):
//
//   mu(s) = mu_max (1 - exp(-s/s1)) (1 + s2 exp(-s/s1)),   s >= 0,
//
// mu(0) = 0, mu -> mu_max as s -> inf, initial slope mu_max (1 + s2) / s1,
// and for s2 > 1 a peak mu_max (1 + s2)^2 / (4 s2) above mu_max. The source's
// formula is damaged; this is the project's reading (docs/tyre-model.md).
//
// tractionCoefficient is the one function to replace for another law; the
// others describe it to the tyre model (its slope at 0 sets the tread's
// relaxation length, its saturation bounds the tread's deflection) and must
// be replaced with it.
#include "wtc/terrain/material.hpp"

namespace wtc {

/// mu(s) (dimensionless) at slip ratio s >= 0.
double tractionCoefficient(const Material& material, double slip_ratio);

/// mu(s) / s, continued at s = 0 by the initial slope: the force law
/// written as F = -R_z (mu(s)/s) (V_s / V_t) has no 0/0.
double tractionSecant(const Material& material, double slip_ratio);

/// d mu / ds at s = 0: mu_max (1 + s2) / s1 (dimensionless).
double tractionInitialSlope(const Material& material);

/// d mu / ds at s >= 0 (dimensionless): negative past the peak when s2 > 1.
double tractionSlope(const Material& material, double slip_ratio);

/// sup over s of mu(s): the static coefficient of the vehicles spec
/// (mu_max if s2 <= 1, else mu_max (1 + s2)^2 / (4 s2)).
double tractionPeak(const Material& material);

/// A slip ratio beyond which mu(s) stays within
/// tolerance::kTractionSaturation x mu_max of mu_max:
/// s1 ln((1 + s2) / kTractionSaturation).
double tractionSaturationSlip(const Material& material);

/// The s2 whose peak is `peak_ratio` x mu_max (peak_ratio > 1): the larger
/// root of s2^2 + (2 - 4 rho) s2 + 1 = 0. The spec's static/dynamic pairs
/// have rho = 5/3, so s2 = 4.44. Throws InvalidInputError unless rho > 1.
double adhesionBoostForPeakRatio(double peak_ratio);

}  // namespace wtc
