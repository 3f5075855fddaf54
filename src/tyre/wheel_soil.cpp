// The wheel-soil stresses and their integrals (equations in
// include/wtc/tyre/wheel_soil.hpp, derivations in docs/soft-soil.md).
#include "wtc/tyre/wheel_soil.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "wtc/base/constants.hpp"
#include "wtc/base/error.hpp"
#include "wtc/base/tolerances.hpp"

namespace wtc {
namespace {

// Nodes per sub-arc. sigma ~ (theta_1 - theta)^n near the entry, a root for
// n < 1, which Gauss-Legendre meets at O(N^-(2n+2)); 12 nodes hold W, DP and
// T within 1e-4 of an adaptive quadrature for n = 0.7 (tests/tyre/wheel_soil_test.cpp).
constexpr int kNodes = 12;

struct GaussLegendre {
  std::array<double, kNodes> x{}, w{};  // on [-1, 1]
};

// The nodes as the roots of P_N by Newton's method from Chebyshev guesses,
// the weights 2 / ((1 - x^2) P_N'(x)^2) (Abramowitz & Stegun 25.4.29).
GaussLegendre makeGaussLegendre() {
  GaussLegendre rule;
  for (int k = 0; k < kNodes; ++k) {
    double x = std::cos(std::numbers::pi * (k + 0.75) / (kNodes + 0.5));
    double derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = x;
      for (int m = 2; m <= kNodes; ++m) {
        const double p2 = ((2 * m - 1) * x * p1 - (m - 1) * p0) / m;
        p0 = p1;
        p1 = p2;
      }
      derivative = kNodes * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / derivative;
      x -= dx;
      if (std::abs(dx) < 1e-15) break;
    }
    rule.x[k] = x;
    rule.w[k] = 2.0 / ((1.0 - x * x) * derivative * derivative);
  }
  return rule;
}

const GaussLegendre& gaussLegendre() {
  static const GaussLegendre rule = makeGaussLegendre();
  return rule;
}

double signedShear(double strength, double displacement, double modulus) {
  return std::copysign(strength * -std::expm1(-std::abs(displacement) / modulus), displacement);
}

// Everything the integrand needs, fixed for one call. With a memory, depth
// is the rim's lowest point below the fresh surface and b the width.
struct Arc {
  double r, moving, theta1, theta2, theta_m, cos1, sin1, pressure_scale, n, cohesion, phi, tan_phi, kx, ky, p, q,
      tan_beta;
  const Soil* soil = nullptr;
  const SoilMemoryProfile* memory = nullptr;
  double depth = 0.0, b = 0.0;
};

// sigma where the rim's stress is that of the front at angle theta (its
// cosine given): part 1's on a fresh surface, else the memory's at the
// point of the ground under that angle.
double normalStress(const Arc& a, double cos_theta, double theta) {
  if (a.memory == nullptr) return a.pressure_scale * std::pow(std::max(0.0, cos_theta - a.cos1), a.n);
  return reloadStress(*a.soil, a.b, a.memory->at(a.r * std::sin(theta)), a.depth - a.r * (1.0 - cos_theta));
}

// The integrals over one sub-arc [lo, hi]; `front` says which sigma applies.
struct Sums {
  double w = 0.0, dp = 0.0, torque = 0.0, lateral = 0.0;
};

void integrate(const Arc& a, double lo, double hi, bool front, Sums& sums) {
  if (!(hi > lo)) return;
  const GaussLegendre& rule = gaussLegendre();
  const double half = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
  for (int k = 0; k < kNodes; ++k) {
    const double theta = mid + half * rule.x[k];
    const double c = std::cos(theta), s = std::sin(theta);
    // The rear maps [theta_2, theta_m] onto the front's [theta_1, theta_m]
    // (Wong & Reece): theta* = theta_1 - (theta - theta_2)/(theta_m - theta_2) (theta_1 - theta_m).
    const double theta_stress =
        front ? theta : a.theta1 - (theta - a.theta2) / (a.theta_m - a.theta2) * (a.theta1 - a.theta_m);
    const double sigma = normalStress(a, front ? c : std::cos(theta_stress), theta_stress);
    const double strength = a.cohesion + sigma * a.tan_phi;
    const double j = a.moving * a.r * (a.p * (a.theta1 - theta) - a.q * (a.sin1 - s));
    const double tau = signedShear(strength, j, a.kx);
    const double jy = a.moving * a.r * a.q * (a.theta1 - theta) * a.tan_beta;
    const double tau_y = signedShear(strength, jy, a.ky);
    const double weight = half * rule.w[k];
    sums.w += weight * (sigma * c + tau * s);
    sums.dp += weight * (tau * c - sigma * s);
    sums.torque += weight * tau;
    sums.lateral += weight * tau_y;
  }
}

// F_u = int R_b(h) (r - h cos theta) d theta over the arc, h = r (cos theta - cos theta_1),
// R_b = D_1 c h + D_2 rho g h^2 (Ishigami et al.'s eq. 15; their D_1 4.03 and
// D_2 2.55 for phi = 37.2 deg are these expressions).
double bulldozing(const Soil& soil, const Arc& a) {
  const double xc = 0.25 * std::numbers::pi - 0.5 * a.phi;
  const double cot_xc = 1.0 / std::tan(xc);
  const double d1 = cot_xc + std::tan(xc + a.phi);
  const double d2 = 0.5 * (cot_xc + cot_xc * cot_xc * a.tan_phi);
  const double weight_density = soil.density * kGravityMps2;
  const GaussLegendre& rule = gaussLegendre();
  const double half = 0.5 * (a.theta1 - a.theta2), mid = 0.5 * (a.theta1 + a.theta2);
  double sum = 0.0;
  for (int k = 0; k < kNodes; ++k) {
    const double theta = mid + half * rule.x[k];
    const double c = std::cos(theta);
    const double h = std::max(0.0, a.r * (c - a.cos1));
    const double rb = d1 * soil.cohesion * h + d2 * weight_density * h * h;
    sum += half * rule.w[k] * rb * (a.r - h * c);
  }
  return sum;
}

// The entry angle where the rim meets the remembered surface: the
// outermost theta at which the rim is below it,
//   g(theta) = Z(theta) - z_p(r sin theta) > 0,  Z(theta) = depth - r (1 - cos theta).
// At the fresh surface's entry theta_f = acos(1 - depth / r), Z = 0: where
// the ground there is fresh (or raised) the rim enters at theta_f, as on
// part 1's surface. Otherwise the search steps in from theta_f to the first
// crossing and closes on it by regula falsi (Illinois; tolerances.hpp). The
// outermost crossing, not a fixed point of Z(theta_1) = z_p: under a wheel
// at rest in its own hollow z_p follows the rim at sigma / k_u above it, and
// a fixed-point iteration drifted along it toward the bottom (a wheel half
// again as heavy sank 8 % past the fresh surface's answer).
constexpr int kEntrySteps = 6, kEntryRefinements = 12;

double rememberedEntrySinkage(const WheelSoilState& state) {
  const double r = state.radius, depth = state.sinkage;
  if (!(depth > 0.0)) return 0.0;
  const auto g = [&](double theta) {
    return depth - r * (1.0 - std::cos(theta)) - state.memory->at(r * std::sin(theta)).plastic_sinkage;
  };
  const double fresh = std::acos(1.0 - std::min(depth, r) / r);
  double outer = fresh, g_outer = g(outer);
  if (g_outer >= -tolerance::kSoilFreshEntryRelative * r) return depth;
  double inner = outer, g_inner = g_outer;
  for (int k = 1; k <= kEntrySteps && g_inner <= 0.0; ++k) {
    outer = inner;
    g_outer = g_inner;
    inner = fresh * (1.0 - static_cast<double>(k) / kEntrySteps);  // the last step reaches the bottom
    g_inner = g(inner);
  }
  if (g_inner <= 0.0) return 0.0;  // above the remembered surface all along the arc
  for (int k = 0, side = 0; k < kEntryRefinements && outer - inner > tolerance::kSoilEntryRad; ++k) {
    const double theta = (inner * g_outer - outer * g_inner) / (g_outer - g_inner);
    const double g_theta = g(theta);
    if (g_theta > 0.0) {
      inner = theta;
      g_inner = g_theta;
      if (side == 1) g_outer *= 0.5;  // Illinois: the stale end's value halved
      side = 1;
    } else {
      outer = theta;
      g_outer = g_theta;
      if (side == -1) g_inner *= 0.5;
      side = -1;
    }
    if (std::abs(g_theta) < tolerance::kSoilEntryRelative * r) break;
  }
  return r * (1.0 - std::cos(inner));
}

// The sinkage below the surface the rim meets: the fresh one, or the
// remembered one at the entry; 0 when the rim is clear of the soil.
double entrySinkage(const WheelSoilState& state) {
  return std::clamp(state.memory != nullptr ? rememberedEntrySinkage(state) : state.sinkage, 0.0, state.radius);
}

// The arc of a rim entering the soil at sinkage z > 0.
Arc makeArc(const Soil& soil, const WheelSoilState& state, double z) {
  const double r = state.radius, b = state.width;
  const double i = std::clamp(state.slip, -1.0, 1.0);
  const double sym = std::clamp(state.symmetry, 0.0, 1.0);
  Arc a{};
  a.r = r;
  a.moving = 1.0 - sym;  // the shear displacement is the rolling's; a wheel at rest has none
  a.theta1 = std::acos(1.0 - z / r);
  const double rolling_exit = -std::acos(1.0 - soil.rebound_ratio * z / r);
  a.theta2 = (1.0 - sym) * rolling_exit - sym * a.theta1;
  a.theta_m = (1.0 - sym) * std::clamp((soil.a0 + soil.a1 * i) * a.theta1, a.theta2, a.theta1);
  a.cos1 = std::cos(a.theta1);
  a.sin1 = std::sin(a.theta1);
  a.pressure_scale = (soil.k_c / b + soil.k_phi) * std::pow(r, soil.n);
  a.n = soil.n;
  a.cohesion = soil.cohesion;
  a.phi = soil.friction_angle_deg * std::numbers::pi / 180.0;
  a.tan_phi = std::tan(a.phi);
  a.kx = soil.shear_modulus_x;
  a.ky = soil.shear_modulus_y;
  a.p = i >= 0.0 ? 1.0 : 1.0 + i;
  a.q = i >= 0.0 ? 1.0 - i : 1.0;
  a.tan_beta = std::tan(state.slip_angle);
  a.soil = &soil;
  a.memory = state.memory;
  a.depth = state.sinkage;
  a.b = b;
  return a;
}

// W, DP, T and the shear's lateral part over the arc: all but the bulldozing.
WheelSoilForces integrateArc(const Arc& a) {
  Sums sums;
  integrate(a, a.theta2, a.theta_m, false, sums);
  integrate(a, a.theta_m, a.theta1, true, sums);
  WheelSoilForces out;
  const double r = a.r, b = a.b;
  out.normal = r * b * sums.w;
  out.drawbar_pull = r * b * sums.dp;
  out.torque = r * r * b * sums.torque;
  out.lateral = -(r * b * sums.lateral);
  out.entry_angle = a.theta1;
  out.exit_angle = a.theta2;
  out.max_stress_angle = a.theta_m;
  out.peak_stress = normalStress(a, std::cos(a.theta_m), a.theta_m);
  out.patch_area = b * r * (std::sin(a.theta1) - std::sin(a.theta2));
  return out;
}

// A ball's slice `aside` off its centre line reads the memory there.
class BesideProfile final : public SoilMemoryProfile {
 public:
  BesideProfile(const SoilMemoryProfile* line, double aside) : line_(line), aside_(aside) {}
  SoilMemory at(double ahead) const override { return line_->beside(ahead, aside_); }

 private:
  const SoilMemoryProfile* line_;
  double aside_;
};

}  // namespace

double reloadStress(const Soil& soil, double width, const SoilMemory& m, double depth) {
  const double k = soil.k_c / width + soil.k_phi;
  const double virgin = k * std::pow(std::max(0.0, depth), soil.n);
  if (m.fresh) return virgin;
  if (!(depth > m.plastic_sinkage)) return 0.0;
  return std::min(soil.unloading_stiffness * (depth - m.plastic_sinkage), std::max(m.max_pressure, virgin));
}

SoilMemory pressedSoil(const Soil& soil, double width, const SoilMemory& before, double depth) {
  const double sigma = reloadStress(soil, width, before, depth);
  if (!(sigma > 0.0)) return before;
  return {.plastic_sinkage = std::max(before.plastic_sinkage, depth - sigma / soil.unloading_stiffness),
          .max_pressure = std::max(before.max_pressure, sigma),
          .fresh = false};
}

WheelSoilForces wheelSoilForces(const Soil& soil, const WheelSoilState& state) {
  const double z = entrySinkage(state);
  if (!(z > 0.0)) return {};
  const Arc a = makeArc(soil, state, z);
  WheelSoilForces out = integrateArc(a);
  out.bulldozing = state.slip_angle != 0.0 ? bulldozing(soil, a) : 0.0;
  out.lateral -= std::copysign(out.bulldozing, state.slip_angle);
  return out;
}

WheelSoilForces sphereSoilForces(const Soil& soil, const SphereSoilState& state) {
  const double r = state.radius, z = state.sinkage;
  if (!(z > 0.0)) return {};
  const double half = z < r ? std::sqrt(z * (2.0 * r - z)) : r;  // a, the patch's half width
  const double b = 2.0 * half;
  const double slip_angle = std::atan2(state.side_slip_speed, std::max(state.travel_speed, state.speed_floor));
  const auto slice = [&](double rho, const SoilMemoryProfile* memory) {
    WheelSoilState s;
    s.radius = rho;
    s.width = b;
    s.sinkage = z - (r - rho);
    s.slip = soilSlip(state.travel_speed, state.rim_speed * rho / r, state.speed_floor);
    s.slip_angle = slip_angle;
    s.symmetry = state.symmetry;
    s.memory = memory;
    return s;
  };

  WheelSoilForces out;
  const GaussLegendre& rule = gaussLegendre();
  for (int k = 0; k < kNodes; ++k) {
    const double y = half * rule.x[k], rho = std::sqrt(r * r - y * y);
    const BesideProfile beside(state.memory, y);
    const WheelSoilState s = slice(rho, state.memory != nullptr ? &beside : nullptr);
    const double zk = entrySinkage(s);
    if (!(zk > 0.0)) continue;
    const WheelSoilForces f = integrateArc(makeArc(soil, s, zk));
    const double per_width = half * rule.w[k] / b;  // the slice's dy over the b integrateArc multiplied
    out.normal += per_width * f.normal;
    out.drawbar_pull += per_width * f.drawbar_pull;
    out.torque += per_width * f.torque;
    out.lateral += per_width * f.lateral;
    out.patch_area += per_width * f.patch_area;
  }
  // The centre line's angles; the bulldozing of the leading side.
  const WheelSoilState centre = slice(r, state.memory);
  const double zc = entrySinkage(centre);
  if (zc > 0.0) {
    const Arc a = makeArc(soil, centre, zc);
    out.entry_angle = a.theta1;
    out.exit_angle = a.theta2;
    out.max_stress_angle = a.theta_m;
    out.peak_stress = normalStress(a, std::cos(a.theta_m), a.theta_m);
    out.bulldozing = slip_angle != 0.0 ? bulldozing(soil, a) : 0.0;
    out.lateral -= std::copysign(out.bulldozing, slip_angle);
  }
  return out;
}

SoilSteadyState steadyWheelOnSoil(const Soil& soil, double radius, double width, double load, double slip,
                                  double slip_angle, const SoilMemoryProfile* memory) {
  if (!(std::isfinite(load) && load > 0.0)) {
    throw InvalidInputError("wtc::steadyWheelOnSoil: load = " + formatNumber(load) + " must be finite and > 0 (N)");
  }
  WheelSoilState state;
  state.radius = radius;
  state.width = width;
  state.slip = slip;
  state.slip_angle = slip_angle;
  state.memory = memory;
  auto at = [&](double z) {
    state.sinkage = z;
    return wheelSoilForces(soil, state);
  };
  // Below the fresh surface, z runs from above the remembered one (raised
  // soil) to the axle in the rut under the wheel.
  const double rut = memory != nullptr ? memory->at(0.0).plastic_sinkage : 0.0;
  double lo = std::min(0.0, rut), hi = radius + std::max(0.0, rut);
  const double most = at(hi).normal;
  if (!(most >= load)) {
    throw InvalidInputError("wtc::steadyWheelOnSoil: soil '" + soil.name + "' carries at most " + formatNumber(most) +
                            " N under a wheel of radius " + formatNumber(radius) + " m, width " + formatNumber(width) +
                            " m at slip " + formatNumber(slip) + " before the axle sinks in; the load is " +
                            formatNumber(load) + " N");
  }
  // W(z) grows with z: bisection to a relative 1e-12 of the radius.
  while (hi - lo > 1e-12 * radius) {
    const double mid = 0.5 * (lo + hi);
    (at(mid).normal < load ? lo : hi) = mid;
  }
  SoilSteadyState steady;
  steady.sinkage = 0.5 * (lo + hi);
  steady.forces = at(steady.sinkage);
  return steady;
}

double soilSlip(double travel_speed, double rim_speed, double floor) {
  const double scale = std::max({std::abs(rim_speed), std::abs(travel_speed), floor});
  return std::clamp((rim_speed - travel_speed) / scale, -1.0, 1.0);
}

}  // namespace wtc
