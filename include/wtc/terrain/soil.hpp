#pragma once
// Soil: the parameters of a soft ground's wheel-soil stresses
// (docs/soft-soil.md; the model is wtc/tyre/wheel_soil.hpp).
//
//   normal stress (Bekker):       sigma = (k_c / b + k_phi) z^n
//   shear strength (Mohr-Coulomb): tau_max = c + sigma tan(phi)
//   shear (Janosi-Hanamoto):      tau = tau_max (1 - exp(-j / K))
//   maximum-stress angle (Wong-Reece): theta_m = (a_0 + a_1 i) theta_1
//   side bulldozing (Ishigami et al. 2007): the soil's density and phi
//
// A Material with a soil is soft ground when a scene asks for the
// soft_soil effect; without it, the material's slip law applies as on any
// hard ground.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace wtc {

struct Soil {
  std::string name;
  double k_c = 0.0;                  ///< Bekker's cohesive modulus (N/m^(n+1)).
  double k_phi = 0.0;                ///< Bekker's frictional modulus (N/m^(n+2)).
  double n = 1.0;                    ///< Bekker's sinkage exponent (dimensionless, > 0).
  double cohesion = 0.0;             ///< c (Pa, >= 0).
  double friction_angle_deg = 30.0;  ///< phi, the internal friction angle (deg, in (0, 90)).
  double shear_modulus_x = 0.01;     ///< Janosi's K_x along the wheel's travel (m, > 0).
  double shear_modulus_y = 0.01;     ///< K_y along the axle, under side slip (m, > 0).
  double a0 = 0.4;                   ///< Wong-Reece theta_m / theta_1 at zero slip (dimensionless, [0, 1]).
  double a1 = 0.15;                  ///< Its growth with slip (dimensionless; a0 + a1 in [0, 1]).
  /// k_u, sigma's slope when the load is taken off (Pa/m, > 0): Wong's
  /// unloading line, read by the ground that remembers (issue 55); a fresh
  /// surface (part 1) is loaded at every step.
  double unloading_stiffness = 2e8;
  /// R, a damping pressure per speed into the soil (Pa s/m, >= 0), added to
  /// sigma as Project Chrono's SCM does: the loss a spring without memory lacks.
  double damping = 3e4;
  double density = 1600.0;           ///< Bulk density rho (kg/m^3, > 0): side bulldozing's weight.
  double rebound_ratio = 0.0;        ///< Rear sinkage / front sinkage (dimensionless, [0, 1)); 0: theta_2 = 0.
};

/// Throws InvalidInputError naming `where`, the soil, the field, its value,
/// range and unit if a value is non-finite or out of range.
void validate(const Soil& soil, const std::string& where);

/// A soil's numeric fields by the names terrain files, wtc-mobility's
/// settings and Python give them (k_c, k_phi, n, cohesion, ...).
struct SoilField {
  const char* name;
  double Soil::*member;
};
std::span<const SoilField> soilFields();

/// A shipped soil by name (its published source in src/terrain/soil_catalog.cpp),
/// or nullopt. soilNames() lists them.
std::optional<Soil> namedSoil(std::string_view name);
std::vector<std::string> soilNames();

}  // namespace wtc
