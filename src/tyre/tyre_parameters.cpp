#include "wtc/tyre/tyre_parameters.hpp"

#include <cmath>
#include <string>

#include "wtc/base/checks.hpp"
#include "wtc/base/error.hpp"
#include "wtc/base/tolerances.hpp"

namespace wtc {
namespace {

void requireFraction(double value, const char* where, const char* name) {
  if (!(value > 0.0 && value <= 1.0)) {
    throw InvalidInputError(std::string(where) + ": " + name + " = " + formatNumber(value) +
                            " must be in (0, 1] (dimensionless)");
  }
}

}  // namespace

void validate(const TyreParameters& t, const char* where) {
  requirePositive(t.radial_stiffness, where, "tyre radial_stiffness", "N/m");
  requireNonNegative(t.radial_damping, where, "tyre radial_damping", "N s/m");
  requireFraction(t.rolling_radius_ratio, where, "tyre rolling_radius_ratio");
  requirePositive(t.slip_speed_floor, where, "tyre slip_speed_floor", "m/s");
  requirePositive(t.tangential_stiffness, where, "tyre tangential_stiffness", "N/m");
  requireNonNegative(t.standstill_damping_ratio, where, "tyre standstill_damping_ratio", "dimensionless");
  requirePositive(t.standstill_speed, where, "tyre standstill_speed", "m/s");
  requireFraction(t.stability_fraction, where, "tyre stability_fraction");
  requirePositive(t.spin_floor, where, "tyre spin_floor", "rad/s");
}

void validate(const WheelInertia& inertia, const char* where) {
  requirePositive(inertia.effective_mass, where, "wheel effective_mass", "kg");
  requirePositive(inertia.axial_inertia, where, "wheel axial_inertia", "kg m^2");
}

WheelInertia bodyInertia(double mass, const Eigen::Matrix3d& inertia_local, const Eigen::Vector3d& axle_local,
                         bool spin_held, const char* where) {
  const Eigen::Vector3d a = axle_local.normalized();
  const WheelInertia inertia{.effective_mass = mass, .axial_inertia = a.dot(inertia_local * a), .spin_held = spin_held};
  if (!std::isfinite(inertia.effective_mass) || !std::isfinite(inertia.axial_inertia)) {
    throw InvalidInputError(std::string(where) + ": the wheel body's mass " + formatNumber(mass) +
                            " kg or moment about the axle " + formatNumber(inertia.axial_inertia) +
                            " kg m^2 is not finite (a static body?)");
  }
  validate(inertia, where);
  return inertia;
}

WheelDescription mountedDescription(WheelDescription given, InertiaSource source, double body_mass,
                                    const Eigen::Matrix3d& body_inertia_local, const Eigen::Vector3d& axle_local,
                                    const char* where) {
  if (source == InertiaSource::kBody) {
    given.inertia = bodyInertia(body_mass, body_inertia_local, axle_local, given.inertia.spin_held, where);
  }
  validate(given, where);
  return given;
}

void validate(const WheelDescription& wheel, const char* where) {
  validate(wheel.geometry, where);
  validate(wheel.tyre, where);
  validate(wheel.inertia, where);
}

void validateMounting(const Eigen::Vector3d& axle_local, const Eigen::Vector3d& centre_local, const char* where) {
  if (!axle_local.allFinite() || axle_local.norm() < tolerance::kMinAxleNorm) {
    throw InvalidInputError(std::string(where) + ": axle_local = " + formatVector(axle_local) +
                            " is not finite or is zero");
  }
  if (!centre_local.allFinite()) {
    throw InvalidInputError(std::string(where) + ": centre_local = " + formatVector(centre_local) + " is not finite");
  }
}

}  // namespace wtc
