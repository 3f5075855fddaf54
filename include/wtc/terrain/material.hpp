#pragma once
#include <optional>
#include <string>

#include "wtc/terrain/soil.hpp"

namespace wtc {

/// Ground material: the parameters of the traction law and rolling
/// resistance of the wheel-terrain model (docs/tyre-model.md).
///   mu(s) = mu_max (1 - exp(-s/s1)) (1 + s2 exp(-s/s1))
/// Defaults: the source's "asphalt concrete" (mu_max, f_r), the project's
/// choice for s1 and s2 (s2 = 0 on asphalt).
struct Material {
  std::string name = "asphalt_concrete";
  double mu_max = 0.8;              ///< Traction coefficient as slip -> inf (dimensionless).
  double s1 = 0.1;                  ///< Slip scale of the initial slope (dimensionless, > 0).
  double s2 = 0.0;                  ///< Adhesion boost at small slip (dimensionless, >= 0).
  double rolling_resistance = 0.018;  ///< f_r (dimensionless, >= 0).
  /// Soft ground: with the soft_soil effect a wheel on this material meets
  /// the soil's stresses instead of the tyre's spring and slip law.
  std::optional<Soil> soil{};
};

/// Throws InvalidInputError naming the field and the material if a value is
/// non-finite or out of range (its soil's too). `where` says where the material came from.
void validate(const Material& material, const std::string& where);

}  // namespace wtc
