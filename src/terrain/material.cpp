// Validation of ground materials: every field finite and inside the range in
// which the traction law of docs/tyre-model.md is defined,
//   mu(s) = mu_max (1 - exp(-s/s1)) (1 + s2 exp(-s/s1)),
// so s1 > 0 (it divides s), mu_max >= 0, s2 >= 0 (a negative s2 would dip mu
// below zero at small slip) and f_r >= 0 (resistance never drives the wheel).
#include "wtc/terrain/material.hpp"

#include <string>

#include "builder_support.hpp"
#include "wtc/base/checks.hpp"
#include "wtc/base/error.hpp"

namespace wtc {

void validate(const Material& material, const std::string& where) {
  if (material.name.empty()) {
    throw InvalidInputError("wtc::Material (" + where + "): the name is empty");
  }
  const std::string context = "wtc::Material '" + material.name + "' (" + where + ")";
  requireNonNegative(material.mu_max, context.c_str(), "mu_max", "dimensionless");
  requirePositive(material.s1, context.c_str(), "s1", "dimensionless");
  requireNonNegative(material.s2, context.c_str(), "s2", "dimensionless");
  requireNonNegative(material.rolling_resistance, context.c_str(), "rolling_resistance", "dimensionless");
  if (material.soil) validate(*material.soil, "material '" + material.name + "', " + where);
}

}  // namespace wtc
