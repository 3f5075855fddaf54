// Validation of ground materials: every field finite and inside the range in
// which the traction law of docs/tyre-model.md is defined,
//   mu(s) = mu_max (1 - exp(-s/s1)) (1 + s2 exp(-s/s1)),
// so s1 > 0 (it divides s), mu_max >= 0, s2 >= 0 (a negative s2 would dip mu
// below zero at small slip) and f_r >= 0 (resistance never drives the wheel).
#include "wtc/material.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "wtc/error.hpp"

namespace wtc {
namespace {

enum class Bound { kPositive, kNonNegative };

void check(const Material& material, const std::string& where, const char* field, double value, Bound bound) {
  const bool ok = std::isfinite(value) && (bound == Bound::kPositive ? value > 0.0 : value >= 0.0);
  if (ok) return;
  std::ostringstream out;
  out.precision(17);
  out << "wtc::Material '" << material.name << "' (" << where << "): " << field << " = " << value
      << " must be finite and " << (bound == Bound::kPositive ? "> 0" : ">= 0") << " (dimensionless)";
  throw InvalidInputError(out.str());
}

}  // namespace

void validate(const Material& material, const std::string& where) {
  if (material.name.empty()) {
    throw InvalidInputError("wtc::Material (" + where + "): the name is empty");
  }
  check(material, where, "mu_max", material.mu_max, Bound::kNonNegative);
  check(material, where, "s1", material.s1, Bound::kPositive);
  check(material, where, "s2", material.s2, Bound::kNonNegative);
  check(material, where, "rolling_resistance", material.rolling_resistance, Bound::kNonNegative);
}

}  // namespace wtc
