// The shipped soils, each with its source. Units: k_c N/m^(n+1), k_phi
// N/m^(n+2), c Pa, phi deg, K m, rho kg/m^3, k_u Pa/m.
//
// Where a source gives no value the soil takes a stated assumption:
//  - k_u, the unloading line's slope: as Project Chrono's SCM pairs its
//    elastic stiffness with k_phi. Its Curiosity demo on the lunar soil
//    below (demo_ROBOT_Curiosity_SCM) takes 2e8 Pa/m for k_phi 0.82e6, its
//    soft-sand default 4e7 for 0.2e6: 200-245 times k_phi's number. Each
//    soil here takes about that ratio (the lunar soil SCM's own value). It
//    sets how much of a sinkage a lifted wheel gets back (sigma / k_u, 0.4 %
//    of the sinkage for n = 1) and only where the ground remembers.
//  - R (damping): 3e4 Pa s/m, the value Project Chrono's SCM vehicle demos
//    give its damping (demo_VEH_SCMTerrain_*); it damps a bounce, not a steady state.
//  - rho: 1600 kg/m^3, a dry sand's bulk density; it enters only the side
//    bulldozing (a wheel under side slip).
#include <array>

#include "wtc/terrain/soil.hpp"

namespace wtc {
namespace {

Soil make(const char* name, double k_c, double k_phi, double n, double cohesion, double phi_deg, double k_x,
          double k_y, double a0, double a1, double rebound, double k_u) {
  Soil soil;
  soil.name = name;
  soil.k_c = k_c;
  soil.k_phi = k_phi;
  soil.n = n;
  soil.cohesion = cohesion;
  soil.friction_angle_deg = phi_deg;
  soil.shear_modulus_x = k_x;
  soil.shear_modulus_y = k_y;
  soil.a0 = a0;
  soil.a1 = a1;
  soil.unloading_stiffness = k_u;
  soil.density = 1600.0;
  soil.rebound_ratio = rebound;
  return soil;
}

const std::array<Soil, 5>& catalog() {
  static const std::array<Soil, 5> soils = {
      // Toyoura sand as Ishigami's group measured it in their single-wheel
      // test bed: Ishigami, Mizuuchi & Yoshida, "Terramechanics-based
      // analysis on locomotion mechanics of wheeled mobile robots (part 1)",
      // JSME ROBOMEC 1A1-S-055, Table 1 (c, phi, n, k_c, k_phi, a0, a1; a
      // smooth wheel's K_x 0.014-0.023 m and K_y 0.016-0.022 m, the upper
      // ends taken); the same values in Ishigami et al. 2007, J. Field
      // Robotics 24(3), and in Mizukami, Yoshimitsu & Kubota 2012 (JSME C).
      // Rear sinkage 0 (the paper's ratio is 0.1-0.3; theta_2 = 0 is this
      // library's default).
      make("toyoura_sand", 1.37e3, 8.14e5, 1.0, 800.0, 37.2, 0.023, 0.022, 0.40, 0.15, 0.0, 2e8),
      // LETE sand: Wong, Theory of Ground Vehicles, table of Bekker
      // parameters (n 0.79, k_c 102 kN/m^(n+1), k_phi 5301 kN/m^(n+2),
      // c 1.3 kPa, phi 31.1 deg); K 1.2 cm as Project Chrono's SCM demos
      // take it (not Wong's); theta_m: Wong & Reece 1967, J. Terramechanics
      // 4(1), compact sand (c_1 0.43, c_2 0.32).
      make("lete_sand", 102e3, 5301e3, 0.79, 1.3e3, 31.1, 0.012, 0.012, 0.43, 0.32, 0.0, 1.2e9),
      // Dry sand (Land Locomotion Laboratory): Wong, Theory of Ground
      // Vehicles, the same table (n 1.1, k_c 0.99 kN/m^(n+1), k_phi
      // 1528.43 kN/m^(n+2), c 1.04 kPa, phi 28 deg); K 2 cm, a loose sand's
      // (assumed); theta_m: Wong & Reece 1967, loose sand (c_1 0.18, c_2 0.32).
      make("dry_sand", 0.99e3, 1528.43e3, 1.1, 1.04e3, 28.0, 0.02, 0.02, 0.18, 0.32, 0.0, 3.5e8),
      // Lunar soil, the nominal values of the lunar surface (Bekker, as
      // tabulated by Wong and used for rover studies, e.g. Project Chrono's
      // Curiosity-on-SCM demo: n 1, k_c 1.4 kN/m^(n+1), k_phi 820 kN/m^(n+2),
      // c 0.17 kPa, phi 35 deg, K 1.78 cm); theta_m as Toyoura sand's.
      make("lunar_regolith", 1.4e3, 820e3, 1.0, 170.0, 35.0, 0.0178, 0.0178, 0.40, 0.15, 0.0, 2e8),
      // Sandy loam at 15 % moisture (Land Locomotion Laboratory): Wong,
      // Theory of Ground Vehicles, the same table (n 0.7, k_c 5.27
      // kN/m^(n+1), k_phi 1515.04 kN/m^(n+2), c 1.72 kPa, phi 29 deg); K 2
      // cm (assumed, as dry sand's; Chrono's SCM demo takes the same);
      // theta_m Wong & Reece 1967's compact sand (c_1 0.43, c_2 0.32,
      // assumed: they give none for a loam); k_u as dry sand's, whose k_phi
      // it shares.
      make("sandy_loam", 5.27e3, 1515.04e3, 0.7, 1.72e3, 29.0, 0.02, 0.02, 0.43, 0.32, 0.0, 3.5e8),
  };
  return soils;
}

}  // namespace

std::optional<Soil> namedSoil(std::string_view name) {
  for (const Soil& soil : catalog()) {
    if (soil.name == name) return soil;
  }
  return std::nullopt;
}

std::vector<std::string> soilNames() {
  std::vector<std::string> names;
  for (const Soil& soil : catalog()) names.push_back(soil.name);
  return names;
}

}  // namespace wtc
