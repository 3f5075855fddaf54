// wtc_study_standstill: the parked-vehicle trap of the wheel-terrain model
// (section 6), measured. A locked wheel carrying a sixth of the 126 kg robot
// (21 kg) rests on a 15 deg slope of asphalt (mu_max = 0.8); after 0.5 s of
// settling, the program integrates 10 s with semi-implicit Euler (the
// integrator of Bullet and ODE, tests/support/wheel_sim.hpp) and prints, per
// law and step: the creep down the slope, the number of velocity reversals
// (oscillation: sign changes of speeds above kStillMps) and the largest speed.
//
//   build/bench/wtc_study_standstill
//
// Laws:
//   tread/slip      wtc's slip law through the relaxing tread state (full effects)
//   tread/coulomb   Coulomb friction through the same tread spring
//   direct/eps=...  the spec's law applied directly, F = -mu(s) R_z V_s/|V_s|
//                   with s = |V_s| / max(V_t, eps): what an implementation
//                   without a low-speed treatment does (1-DOF along the slope).
// Target (issue 4): creep < 10 mm in 10 s and no oscillation, h = 0.1-2 ms.
#include <cmath>
#include <cstdio>
#include <string>

#include "wheel_sim.hpp"
#include "wtc/tyre/traction_law.hpp"

namespace {

using namespace wtc;
using namespace wtc::testing;

constexpr double kSlopeRad = 15 * 0.017453292519943295;
constexpr double kSettleSeconds = 0.5;
constexpr double kRunSeconds = 10.0;
constexpr double kMassKg = 21.0;
// Speeds below this are standing still: their sign is roundoff (m/s).
constexpr double kStillMps = 1e-6;

struct Outcome {
  double creep_m = 0.0;
  int reversals = 0;
  double fastest_mps = 0.0;
};

// Feeds the downhill velocity after settling; the creep is filled by the caller.
struct Watch {
  Outcome outcome;
  double previous = 0.0;
  void see(double v) {
    outcome.fastest_mps = std::max(outcome.fastest_mps, std::abs(v));
    if (std::abs(v) < kStillMps) return;
    if (v * previous < 0.0) ++outcome.reversals;
    previous = v;
  }
};

Outcome tread(const TyreModel& model, double h) {
  const Terrain incline = tiltedSlab(kSlopeRad);
  SimWheel wheel;
  wheel.mass = kMassKg;
  wheel.locked = true;
  // Described as it is: the tread's caps are set for the mass its contact
  // moves, here the whole locked wheel.
  wheel.description.inertia.effective_mass = kMassKg;
  wheel.description.inertia.spin_held = true;
  restOnSlab(wheel, kSlopeRad);
  for (long k = 0; k < std::lround(kSettleSeconds / h); ++k) step(model, incline, h, wheel);
  const Eigen::Vector3d start = wheel.center;
  Watch watch;
  for (long k = 0; k < std::lround(kRunSeconds / h); ++k) {
    step(model, incline, h, wheel);
    watch.see(wheel.velocity.dot(downhill(kSlopeRad)));
  }
  watch.outcome.creep_m = (wheel.center - start).dot(downhill(kSlopeRad));
  return watch.outcome;
}

Outcome direct(double eps, double h) {
  const Material asphalt;
  const double normal = kMassKg * kGravityMps2 * std::cos(kSlopeRad);
  const double downhill_force = kMassKg * kGravityMps2 * std::sin(kSlopeRad);
  double x = 0.0, v = 0.0, start = 0.0;
  Watch watch;
  const long settle = std::lround(kSettleSeconds / h);
  for (long k = 0; k < settle + std::lround(kRunSeconds / h); ++k) {
    const double speed = std::max(std::abs(v), eps);  // V_t = |V_O| = |V_s| for a locked wheel
    const double friction = -normal * tractionSecant(asphalt, std::abs(v) / speed) * v / speed;
    v += h * (downhill_force + friction) / kMassKg;
    x += h * v;
    if (k == settle - 1) start = x;
    if (k >= settle) watch.see(v);
  }
  watch.outcome.creep_m = x - start;
  return watch.outcome;
}

void row(const std::string& law, double h, const Outcome& o) {
  std::printf("| %s | %.1f | %.3g | %d | %.2g |\n", law.c_str(), h * 1e3, o.creep_m * 1e3, o.reversals, o.fastest_mps);
}

}  // namespace

int main() {
  const double steps[] = {1e-4, 5e-4, 1e-3, 2e-3, 5e-3};
  std::printf("| law | h (ms) | creep in 10 s (mm) | velocity reversals | max speed (m/s) |\n");
  std::printf("|---|---|---|---|---|\n");
  const TyreModel slip(EffectSet::full());
  const TyreModel coulomb(EffectSet::full().without(Effect::kSlipTraction).with(Effect::kCoulombFriction));
  for (const double h : steps) row("tread/slip", h, tread(slip, h));
  for (const double h : steps) row("tread/coulomb", h, tread(coulomb, h));
  for (const double eps : {1e-3, 1e-2, 1e-1}) {
    for (const double h : steps) row("direct/eps=" + std::to_string(eps).substr(0, 5), h, direct(eps, h));
  }
}
