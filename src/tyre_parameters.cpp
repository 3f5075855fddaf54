#include "wtc/tyre_parameters.hpp"

#include <string>

#include "builder_support.hpp"
#include "wtc/error.hpp"

namespace wtc {
namespace {

void requireFraction(double value, const std::string& where, const char* name) {
  if (!(value > 0.0 && value <= 1.0)) {
    throw InvalidInputError(where + ": " + name + " = " + formatNumber(value) +
                            " must be in (0, 1] (dimensionless)");
  }
}

}  // namespace

void validate(const TyreParameters& t, const std::string& where) {
  const std::string context = "wtc::TyreParameters (" + where + ")";
  const char* c = context.c_str();
  detail::requirePositive(t.radial_stiffness, c, "radial_stiffness", "N/m");
  detail::requireNonNegative(t.radial_damping, c, "radial_damping", "N s/m");
  requireFraction(t.rolling_radius_ratio, context, "rolling_radius_ratio");
  detail::requirePositive(t.slip_speed_floor, c, "slip_speed_floor", "m/s");
  detail::requirePositive(t.tangential_stiffness, c, "tangential_stiffness", "N/m");
  detail::requireNonNegative(t.standstill_damping_ratio, c, "standstill_damping_ratio", "dimensionless");
  detail::requirePositive(t.standstill_speed, c, "standstill_speed", "m/s");
  requireFraction(t.stability_fraction, context, "stability_fraction");
  detail::requirePositive(t.spin_floor, c, "spin_floor", "rad/s");
}

void validate(const WheelInertia& inertia, const std::string& where) {
  const std::string context = "wtc::WheelInertia (" + where + ")";
  detail::requirePositive(inertia.effective_mass, context.c_str(), "effective_mass", "kg");
  detail::requirePositive(inertia.axial_inertia, context.c_str(), "axial_inertia", "kg m^2");
}

void validate(const WheelDescription& wheel, const std::string& where) {
  validate(wheel.geometry, where);
  validate(wheel.tyre, where);
  validate(wheel.inertia, where);
}

}  // namespace wtc
