// Validation of soils: every field finite and inside the range where the
// wheel-soil stresses of docs/soft-soil.md are defined.
//   sigma = (k_c / b + k_phi) z^n needs k_c, k_phi >= 0 with k_c / b + k_phi > 0
//     for every width (k_phi > 0, or k_c > 0), and n > 0;
//   tau = (c + sigma tan phi)(1 - exp(-j / K)) needs K > 0 and phi in (0, 90) deg
//     (tan phi finite; 0 would leave a cohesionless soil without strength);
//   theta_m = (a_0 + a_1 i) theta_1 must stay in the contact arc for i in [0, 1]:
//     a_0 and a_0 + a_1 in [0, 1];
//   the rear sinkage lambda z needs lambda in [0, 1).
#include "wtc/terrain/soil.hpp"

#include <cmath>
#include <string>

#include "wtc/base/checks.hpp"
#include "wtc/base/error.hpp"

namespace wtc {
namespace {

void requireWithin(double value, double low, double high, bool high_open, const std::string& context,
                   const char* name, const char* unit) {
  const bool inside = std::isfinite(value) && value >= low && (high_open ? value < high : value <= high);
  if (!inside) {
    throw InvalidInputError(context + ": " + name + " = " + formatNumber(value) + " must be in [" +
                            formatNumber(low) + ", " + formatNumber(high) + (high_open ? ")" : "]") + " (" + unit +
                            ")");
  }
}

constexpr SoilField kFields[] = {{"k_c", &Soil::k_c},
                                 {"k_phi", &Soil::k_phi},
                                 {"n", &Soil::n},
                                 {"cohesion", &Soil::cohesion},
                                 {"friction_angle_deg", &Soil::friction_angle_deg},
                                 {"shear_modulus_x", &Soil::shear_modulus_x},
                                 {"shear_modulus_y", &Soil::shear_modulus_y},
                                 {"a0", &Soil::a0},
                                 {"a1", &Soil::a1},
                                 {"unloading_stiffness", &Soil::unloading_stiffness},
                                 {"damping", &Soil::damping},
                                 {"density", &Soil::density},
                                 {"rebound_ratio", &Soil::rebound_ratio}};

}  // namespace

std::span<const SoilField> soilFields() { return kFields; }

void validate(const Soil& soil, const std::string& where) {
  if (soil.name.empty()) throw InvalidInputError("wtc::Soil (" + where + "): the name is empty");
  const std::string context = "wtc::Soil '" + soil.name + "' (" + where + ")";
  const char* c = context.c_str();
  requireNonNegative(soil.k_c, c, "k_c", "N/m^(n+1)");
  requireNonNegative(soil.k_phi, c, "k_phi", "N/m^(n+2)");
  if (soil.k_c == 0.0 && soil.k_phi == 0.0) {
    throw InvalidInputError(context + ": k_c and k_phi are both 0: the soil would carry no load");
  }
  requirePositive(soil.n, c, "n", "dimensionless");
  requireNonNegative(soil.cohesion, c, "cohesion", "Pa");
  if (!(std::isfinite(soil.friction_angle_deg) && soil.friction_angle_deg > 0.0 && soil.friction_angle_deg < 90.0)) {
    throw InvalidInputError(context + ": friction_angle_deg = " + formatNumber(soil.friction_angle_deg) +
                            " must be in (0, 90) (deg)");
  }
  requirePositive(soil.shear_modulus_x, c, "shear_modulus_x", "m");
  requirePositive(soil.shear_modulus_y, c, "shear_modulus_y", "m");
  requireWithin(soil.a0, 0.0, 1.0, false, context, "a0", "dimensionless");
  requireWithin(soil.a0 + soil.a1, 0.0, 1.0, false, context, "a0 + a1", "dimensionless");
  requirePositive(soil.unloading_stiffness, c, "unloading_stiffness", "Pa/m");
  requireNonNegative(soil.damping, c, "damping", "Pa s/m");
  requirePositive(soil.density, c, "density", "kg/m^3");
  requireWithin(soil.rebound_ratio, 0.0, 1.0, true, context, "rebound_ratio", "dimensionless");
}

}  // namespace wtc
