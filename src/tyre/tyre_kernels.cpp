// The per-contact force kernels (wheel-terrain model, sections 3-4, and the
// standstill treatment of tyre_model.hpp). Each effect is a compile-time
// switch, so a kernel contains only the code of its effects.
#include "tyre_kernels.hpp"

#include "exp_minus_one.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "wtc/base/tolerances.hpp"
#include "wtc/tyre/traction_law.hpp"

namespace wtc::detail {
namespace {

using Eigen::Vector3d;
using Inputs = KernelInputs;

// ln(1 / kTractionSaturation): s_sat >= s1 times this for every s2 >= 0.
const double kSaturationLog = -std::log(tolerance::kTractionSaturation);

double square(double x) { return x * x; }

// The exact solution of du/dt = V_s - lambda u over a step with V_s
// constant: u <- decay u + weight V_s, decay = exp(-lambda h),
// weight = h (1 - exp(-lambda h)) / (lambda h). One expm1 gives both.
struct Relaxation {
  double decay;
  double weight;  // (s)
};
Relaxation relaxation(double step, double lambda_h) {
  const double em = expMinusOne(lambda_h);
  return {1.0 + em, step * oneMinusExpOverX(lambda_h, em)};
}

// The tread state of the previous step's contact most aligned with e (within
// 30 deg, kTreadStateMatchCos), moved into the tangent plane of e; else zero.
TreadState inheritTread(std::span<const TreadState> previous, const Vector3d& e) {
  const TreadState* best = nullptr;
  double best_cos = tolerance::kTreadStateMatchCos;
  for (const TreadState& t : previous) {
    const double cosine = t.e.dot(e);
    if (cosine >= best_cos) {
      best_cos = cosine;
      best = &t;
    }
  }
  TreadState t{e, Vector3d::Zero(), Vector3d::Zero()};
  if (best == nullptr) return t;
  t.u = best->u - best->u.dot(e) * e;
  t.elastic = best->elastic - best->elastic.dot(e) * e;
  return t;
}

// The tread's axes in the tangent plane of e: the axle projected onto it
// (kLateral) and e x that (kRolling). A tread contact's e is within
// asin(w / 2 r_f) of normal to the axle (the cut sphere), so the projection
// is at least cos(18.4 deg) long; the fallback only keeps the axes finite.
struct TreadAxes {
  std::array<Vector3d, 2> t;
  Vector3d e;
};
TreadAxes treadAxes(const Vector3d& axle, const Vector3d& e) {
  Vector3d lateral = axle - axle.dot(e) * e;
  const double length = lateral.norm();
  lateral = length > 0.5 ? Vector3d(lateral / length) : e.unitOrthogonal();
  return {{e.cross(lateral), lateral}, e};
}

// Implicit mode's rows for a tread that acts as a spring over the coming
// step (tyre_model.hpp's elastic branch, and Coulomb's law): with
// d+ = decay d + w V+ (d this step's deflection, the last step's d+ at the
// V seen now), G+ = -k (d+ + tau V+) = K (v - V+), K = k (w + tau),
// v = -decay d / (w + tau): the same K along both axes, so any frame will do;
// row 0 along the spring's force. `target` is v (m/s), `force` the force now.
// What the cone leaves across a row 0 bounded by `limit` that carries
// `mu_now` (both over R_z): sqrt(limit^2 - mu_now^2).
double acrossLimit(double limit, double mu_now) { return std::sqrt(std::max(limit * limit - mu_now * mu_now, 0.0)); }

TreadRows springRows(const TreadAxes& axes, const Vector3d& target, double damping, const Vector3d& force, double limit,
                     double mu_now) {
  TreadRows rows;
  const double norm = force.norm();
  rows.direction = norm > 0.0 ? Vector3d(force / norm) : axes.t[0];
  const Vector3d across = rows.direction.cross(axes.e);
  rows.velocity = {target.dot(rows.direction), target.dot(across)};
  rows.damping = {damping, damping};
  rows.limit = {limit, acrossLimit(limit, mu_now)};
  return rows;
}

// The slip law through the relaxing tread (tyre_model.hpp), per tread axis i
// with sigma_i = mu'(0) R_z / k_i:
//   du_i/dt = V_s,i - (V_t / sigma_i) u_i,  q_i = (u_i + tau_i V_s,i) / sigma_i,
//   F = -R_z mu(|q|) q / |q|.
// In steady state q_i = V_s,i / V_t on both axes: the spec's isotropic law.
//
// u is the slip's memory: after a slide it holds sigma s, far more than the
// tread's elastic deflection |F| / k_i (16 mm against 1.6 mm for a locked
// 21 kg wheel), and a force taken from it alone stays on until the wheel has
// moved u back (issue 11: a braked wheel sprang back 14 mm). So the tread
// also keeps its elastic deflection d, as a brush tyre's bristles: it moves
// with the slip and relaxes with the rolling as u does, and its force
// G = -k_i (d_i + tau_i V_s,i) is what the tread gives while it is below the
// law's: loading, d reaches the law and is held there (F = the law's force,
// exactly as before); unloading, the force falls at k_i per metre.
void slipLawTraction(const Inputs& in, const Material& m, double normal_force, const TreadAxes& axes, TreadState& t,
                     ContactForce& f) {
  const double slope_load = tractionInitialSlope(m) * normal_force;  // mu'(0) R_z (N)
  if (!(slope_load > 0.0)) {                                         // unloaded, or a frictionless material
    t.u.setZero();
    t.elastic.setZero();
    return;
  }
  std::array<double, 2> sigma, slip_velocity, memory, elastic, slip;
  std::array<Relaxation, 2> relaxed;
  for (int i = 0; i < 2; ++i) {
    sigma[i] = slope_load / in.tread_stiffness[i];  // (m)
    slip_velocity[i] = axes.t[i].dot(f.slip_velocity);
    relaxed[i] = relaxation(in.step, in.transport_speed * in.step / sigma[i]);
    memory[i] = relaxed[i].decay * axes.t[i].dot(t.u) + relaxed[i].weight * slip_velocity[i];
    elastic[i] = relaxed[i].decay * axes.t[i].dot(t.elastic) + relaxed[i].weight * slip_velocity[i];
  }
  // The law's force from the memory (per axis), after capping |u_i / sigma_i|
  // at s_sat; s1 ln(1/kTractionSaturation) <= s_sat spares the logarithm
  // while the tread is below it (nearly always).
  const auto law = [&](std::array<double, 2>& deflection) {
    const double squared = square(deflection[0] / sigma[0]) + square(deflection[1] / sigma[1]);
    if (squared > square(m.s1 * kSaturationLog)) {
      const double saturation = tractionSaturationSlip(m);
      if (squared > square(saturation)) {
        const double scale = saturation / std::sqrt(squared);
        for (double& d : deflection) d *= scale;
      }
    }
    for (int i = 0; i < 2; ++i) slip[i] = (deflection[i] + in.tread_damping_time[i] * slip_velocity[i]) / sigma[i];
    const double ratio = std::hypot(slip[0], slip[1]);
    const double secant = tractionSecant(m, ratio);  // mu(s)/s, finite at 0
    return Eigen::Vector2d(-normal_force * secant * slip[0], -normal_force * secant * slip[1]);
  };
  const auto spring = [&] {
    return Eigen::Vector2d(-in.tread_stiffness[0] * (elastic[0] + in.tread_damping_time[0] * slip_velocity[0]),
                           -in.tread_stiffness[1] * (elastic[1] + in.tread_damping_time[1] * slip_velocity[1]));
  };
  Eigen::Vector2d force = law(memory);
  const Eigen::Vector2d tread = spring();
  // The slip has turned against the memory: the memory restarts from the
  // elastic deflection (the bristles' state), where the two agree.
  if (tread.dot(force) < 0.0) {
    memory = elastic;
    force = law(memory);
  }
  const double law_squared = force.squaredNorm();  // the law's force at the memory (N^2)
  const bool loading = tread.squaredNorm() >= law_squared;
  if (loading) {
    for (int i = 0; i < 2; ++i) {  // held at the law
      elastic[i] = -force[i] / in.tread_stiffness[i] - in.tread_damping_time[i] * slip_velocity[i];
    }
  } else {
    force = tread;  // unloading: elastic
  }
  f.tangential_force = force[0] * axes.t[0] + force[1] * axes.t[1];
  f.mu = force.norm() / normal_force;
  t.u = memory[0] * axes.t[0] + memory[1] * axes.t[1];
  t.elastic = elastic[0] * axes.t[0] + elastic[1] * axes.t[1];
  if (!in.implicit_tread) return;
  // Implicit mode: the force at the end of the step. The lag w + tau is
  // how far the end's slip velocity V+ moves the tread over the step.
  std::array<double, 2> lag;
  for (int i = 0; i < 2; ++i) lag[i] = relaxed[i].weight + in.tread_damping_time[i];  // (s)
  if (!loading) {  // unloading: the spring (springRows)
    Vector3d target = Vector3d::Zero();
    for (int i = 0; i < 2; ++i) target -= (relaxed[i].decay * elastic[i] / lag[i]) * axes.t[i];
    f.tread_rows = springRows(axes, target, in.tread_stiffness[kRolling] * lag[kRolling], f.tangential_force,
                              std::sqrt(law_squared) / normal_force, f.mu);
    return;
  }
  // Loading: the law at the end's slip q+ = (decay u + (w + tau) V+) / sigma,
  // F+ = -R_z mu(|q+|) q+/|q+|, linearized about V+ = V (the slip seen
  // now), q* = (decay u + (w + tau) V) / sigma. Along -q* (row 0) its
  // stiffness in V+ is R_z mu'(|q*|) (w + tau) / sigma, across it (row 1)
  // R_z (mu/s)(|q*|) (w + tau) / sigma (the law turns with the slip): both
  // k (w + tau) at small slip, where the spring and the law agree. Exact
  // where mu is linear; the curvature of mu within one step is the
  // approximation (docs/tyre-model.md). Where mu' <= 0 (saturated, or past
  // a peak) row 0 keeps a floor of its stiffness and so pushes with the
  // law's force at q*, as force mode does.
  Eigen::Vector2d q;
  for (int i = 0; i < 2; ++i) q[i] = (relaxed[i].decay * memory[i] + lag[i] * slip_velocity[i]) / sigma[i];
  const double ratio = q.norm(), gain = normal_force * lag[kRolling] / sigma[kRolling];  // (N s/m)
  const double mu = tractionCoefficient(m, ratio), peak = tractionPeak(m);
  const double initial = tractionInitialSlope(m);
  const double along = gain * std::max(tractionSlope(m, ratio), tolerance::kTreadSlopeFloor * initial);
  TreadRows& rows = f.tread_rows;
  rows.direction = ratio > 0.0 ? Vector3d(-(q[0] * axes.t[0] + q[1] * axes.t[1]) / ratio) : axes.t[0];
  const Vector3d across = rows.direction.cross(axes.e), velocity = f.slip_velocity;
  rows.velocity = {velocity.dot(rows.direction) + normal_force * mu / along, velocity.dot(across)};
  rows.damping = {along, gain * tractionSecant(m, ratio)};
  rows.limit = {peak, acrossLimit(peak, mu)};
}

// Coulomb's law through the same tread spring: elastic up to mu_max R_z,
// then sliding at it.
void coulombTraction(const Inputs& in, const Material& m, double normal_force, const TreadAxes& axes, TreadState& t,
                     ContactForce& f) {
  const double limit = m.mu_max * normal_force;  // (N)
  Vector3d& u = t.u;
  if (!(limit > 0.0)) {
    u.setZero();
    t.elastic.setZero();
    return;
  }
  Eigen::Vector2d spring, damper;  // k_i u_i and k_i tau_i V_s,i (N)
  for (int i = 0; i < 2; ++i) {
    const double slip_velocity = axes.t[i].dot(f.slip_velocity);
    spring[i] = in.tread_stiffness[i] * (axes.t[i].dot(u) + in.step * slip_velocity);
    damper[i] = in.tread_stiffness[i] * in.tread_damping_time[i] * slip_velocity;
  }
  if (spring.norm() > limit) spring *= limit / spring.norm();
  Eigen::Vector2d force = -(spring + damper);
  if (force.norm() > limit) force *= limit / force.norm();
  f.tangential_force = force[0] * axes.t[0] + force[1] * axes.t[1];
  f.mu = force.norm() / normal_force;
  u = (spring[0] / in.tread_stiffness[0]) * axes.t[0] + (spring[1] / in.tread_stiffness[1]) * axes.t[1];
  t.elastic = u;  // capped at the limit: all of it is elastic
  if (!in.implicit_tread) return;
  // Implicitly (no relaxation: decay 1, w = h), springRows.
  const double lag = in.step + in.tread_damping_time[kRolling];  // (s)
  f.tread_rows = springRows(axes, -u / lag, in.tread_stiffness[kRolling] * lag, f.tangential_force, m.mu_max, f.mu);
}

template <bool kDamping, Traction kTraction, bool kRolling>
void contactForces(const Inputs& in, std::span<const WheelContact> contacts, std::span<const TreadState> tread_in,
                   std::vector<TreadState>& tread_out, ContactForce* out) {
  const WheelMotion& motion = *in.motion;
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const WheelContact& c = contacts[k];
    ContactForce& f = out[k];
    f.contact = c;
    // Section 3: V_P = V_O + omega x OP, v_z = V_P . e, V_s = V_P - v_z e.
    const Vector3d velocity_p = motion.velocity + motion.angular_velocity.cross(in.free_radius * c.e);
    f.deflection_rate = velocity_p.dot(c.e);
    f.slip_velocity = velocity_p - f.deflection_rate * c.e;
    f.slip_ratio = f.slip_velocity.norm() / std::max(in.transport_speed, in.slip_speed_floor);
    // Section 4: R_z = c Z + b v_z, never pulling; scaled by the contact's
    // load share at a shallow concave crease (wheel_contact.hpp).
    double normal_force = in.stiffness * c.deflection;
    if constexpr (kDamping) normal_force += in.damping * f.deflection_rate;
    f.normal_force = c.load_share * std::max(normal_force, 0.0);
    f.tangential_force.setZero();
    f.mu = 0.0;
    f.friction_limit = 0.0;
    f.tread_rows = TreadRows{};
    if constexpr (kTraction != Traction::kNone) {
      const Material& m = in.materials[c.material];
      TreadState t = inheritTread(tread_in, c.e);
      const TreadAxes axes = treadAxes(in.axle, c.e);
      if constexpr (kTraction == Traction::kSlipLaw) {
        slipLawTraction(in, m, f.normal_force, axes, t, f);
      } else {
        coulombTraction(in, m, f.normal_force, axes, t, f);
      }
      tread_out.push_back(t);
      // At rest the tread sticks up to the peak of mu(s) R_z (tyre_model.hpp).
      const double peak = kTraction == Traction::kSlipLaw ? tractionPeak(m) : m.mu_max;
      f.friction_limit = std::max(f.mu, in.sticking * peak);
    }
    f.force = f.tangential_force - f.normal_force * c.e;
    if constexpr (kRolling) {
      // M_r = -f_r R_z r_0 sign(omega . a) a, sign ramped over a width that
      // bounds the gain by kappa I / h (and never below spin_floor). The
      // rate is the tread's rolling over the (static) ground, the wheel's
      // absolute spin about its axle, not its spin relative to the hub:
      // M_r acts on the wheel, so its power M_r . omega =
      // -f_r R_z r_0 clamp(s / w) s <= 0 whatever the hub does.
      const double resisting = in.materials[c.material].rolling_resistance * f.normal_force * in.rolling_radius;
      const double width = std::max(in.spin_floor, resisting * in.spin_ramp_gain);
      const double spin = motion.angular_velocity.dot(in.axle);
      f.rolling_moment = (-resisting * std::clamp(spin / width, -1.0, 1.0)) * in.axle;
    } else {
      f.rolling_moment.setZero();
    }
  }
}

template <bool kDamping, Traction kTraction>
constexpr std::array<Kernel, 2> byRolling = {&contactForces<kDamping, kTraction, false>,
                                             &contactForces<kDamping, kTraction, true>};
template <bool kDamping>
constexpr std::array<std::array<Kernel, 2>, 3> byTraction = {byRolling<kDamping, Traction::kNone>,
                                                             byRolling<kDamping, Traction::kSlipLaw>,
                                                             byRolling<kDamping, Traction::kCoulomb>};
constexpr std::array<std::array<std::array<Kernel, 2>, 3>, 2> kKernels = {byTraction<false>, byTraction<true>};

}  // namespace

int selectKernel(bool damping, Traction traction, bool rolling_resistance) {
  return ((damping ? 1 : 0) * 3 + static_cast<int>(traction)) * 2 + (rolling_resistance ? 1 : 0);
}

Kernel kernel(int index) {
  return kKernels[static_cast<std::size_t>(index / 6)][static_cast<std::size_t>(index / 2 % 3)]
                 [static_cast<std::size_t>(index % 2)];
}

}  // namespace wtc::detail
