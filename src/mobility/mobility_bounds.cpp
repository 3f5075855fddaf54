// The bounds of wtc/mobility/mobility_bounds.hpp; each section follows
// docs/mobility-bounds.md's of the same event.
#include "wtc/mobility/mobility_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "short_number.hpp"
#include "wtc/base/constants.hpp"
#include "wtc/tyre/traction_law.hpp"
#include "wtc/tyre/wheel_soil.hpp"

namespace wtc::mobility {
namespace {

constexpr double kSearchTopRad = 60.0 / kDegPerRad;  // the planar statics' grades are searched below this
constexpr int kBisections = 80;                      // halvings of an interval: to double precision
constexpr double kAxleTolM = 1e-6;                   // wheels within this in x share an axle (m)
constexpr double kMinTurnSpeedMps = 1e-3;            // the slip ratio's floor speed in the turn's balance

// The root of f in [lo, hi], f(lo) and f(hi) of opposite signs (else an end).
template <class F>
double bisect(F f, double lo, double hi) {
  const bool lo_positive = f(lo) > 0.0;
  if ((f(hi) > 0.0) == lo_positive) return hi;
  for (int i = 0; i < kBisections; ++i) {
    const double mid = 0.5 * (lo + hi);
    ((f(mid) > 0.0) == lo_positive ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double stepHeight(double r, double alpha) { return r * (1.0 - std::cos(std::min(alpha, std::numbers::pi / 2))); }

// A single-body vehicle facing up a grade tips back over its rearmost
// wheels when its centre of mass passes above them: tan theta = (x_com -
// x_rear) / z_com (pi / 2 for a vehicle of several bodies).
double tipGrade(const VehicleStatics& v) {
  if (v.roots.size() != 1) return std::numbers::pi / 2;
  double rear = v.wheels.front().position.x();
  for (const WheelInfo& w : v.wheels) rear = std::min(rear, w.position.x());
  return std::atan2(v.com.x() - rear, v.com.z());
}

Bound grade(const VehicleStatics& v, const Material& g, double peak) {
  const double weight = v.weight();
  const double r0 = v.wheels.front().r0_ratio;
  double traction = 0.0;
  std::string note;
  if (v.allDriven()) {
    traction = std::atan(peak);
    note = "all wheels driven: tan theta = peak of mu " + shortNumber(peak);
  } else {
    const double k = g.rolling_resistance * r0;
    const auto need = [&](double theta) {
      const Loads n = wheelLoads(v, theta, 0.0, k);
      if (!n.equilibrium) return -1.0;
      return peak * n.driven_N - (weight * std::sin(theta) + k * n.free_N);
    };
    traction = bisect(need, 0.0, kSearchTopRad);
    const Loads n = wheelLoads(v, traction, 0.0, k);
    note = "driven wheels carry " + shortNumber(n.driven_N) + " N there, free " + shortNumber(n.free_N) + " N" +
           (n.lifted.empty() ? "" : " (" + n.lifted.front() + (n.lifted.size() > 1 ? ", ..." : "") + " lifted)");
  }
  // sum T_max = r_f (W sin + f_r (r0/r_f) W cos) for one radius of driven wheel.
  double torque = 0.0, r_d = 0.0;
  for (const WheelInfo& w : v.wheels) {
    if (!w.driven) continue;
    torque += w.max_torque_Nm;
    r_d = w.radius_m;
  }
  const double kt = torque / (r_d * weight), a = g.rolling_resistance * r0;
  const double by_torque =
      kt < std::hypot(1.0, a) ? std::asin(kt / std::hypot(1.0, a)) - std::atan(a) : std::numbers::pi / 2;
  const double tip = tipGrade(v);
  Bound b;
  b.value = std::min({traction, by_torque, tip}) * kDegPerRad;
  b.governs = traction <= by_torque && traction <= tip ? "traction" : (by_torque <= tip ? "drive torque" : "tip-over");
  b.detail = "traction " + shortNumber(traction * kDegPerRad) + " deg (" + note + "), drive torque " +
             (kt < std::hypot(1.0, a) ? shortNumber(by_torque * kDegPerRad) + " deg" : "any grade") +
             " (sum T_max / (r_f W) = " + shortNumber(kt) + ")" +
             (v.roots.size() == 1 ? ", tip-over " + shortNumber(tip * kDegPerRad) + " deg" : "");
  return b;
}

Bound parked(const VehicleStatics& v, double peak) {
  Bound b;
  b.governs = "the peak of mu at the held wheels";
  if (v.allDriven()) {
    b.value = std::atan(peak) * kDegPerRad;
    b.detail = "every wheel held: tan theta = " + shortNumber(peak);
    return b;
  }
  const auto hold = [&](double theta) {
    const Loads n = wheelLoads(v, theta);
    return n.equilibrium ? peak * n.driven_N - v.weight() * std::sin(theta) : -1.0;
  };
  const double theta = bisect(hold, 0.0, kSearchTopRad);
  const Loads n = wheelLoads(v, theta);
  b.value = theta * kDegPerRad;
  b.detail = "held (driven) wheels carry " + shortNumber(n.driven_N) + " N: " + shortNumber(peak) +
             " N_held = W sin theta" + (n.lifted.empty() ? "" : " (" + n.lifted.front() + " lifted)") +
             "; free wheels hold nothing at rest";
  return b;
}

// Per axle at the edge, the others at their level loads pushing (driven, the peak) or dragging (free):
// tan(alpha - phi) <= P / L driven, tan alpha <= P / L free; h = r (1 - cos alpha).
void stepAndGap(const VehicleStatics& v, const Material& g, double peak, Bound& step, Bound& gap) {
  const Loads n0 = wheelLoads(v);
  const double phi = std::atan(peak), k = g.rolling_resistance * v.wheels.front().r0_ratio;
  std::map<double, std::vector<std::size_t>, std::greater<>> axles;
  for (std::size_t i = 0; i < v.wheels.size(); ++i) {
    const double x = std::round(v.wheels[i].position.x() / kAxleTolM) * kAxleTolM;
    axles[x].push_back(i);
  }
  step.value = gap.value = INFINITY;
  for (const auto& [x, members] : axles) {
    double load = 0.0, push = 0.0;
    for (std::size_t i = 0; i < v.wheels.size(); ++i) {
      const bool here = std::find(members.begin(), members.end(), i) != members.end();
      if (here) {
        load += n0.normal_N[i];
      } else {
        push += v.wheels[i].driven ? peak * n0.normal_N[i] : -k * n0.normal_N[i];
      }
    }
    const WheelInfo& w = v.wheels[members.front()];
    const double alpha = w.driven ? phi + std::atan2(push, load) : std::atan2(std::max(push, 0.0), load);
    const double h = stepHeight(w.radius_m, alpha);
    const double width = 2.0 * std::sqrt(h * (2.0 * w.radius_m - h));
    if (h < step.value) {
      step.value = h;
      step.governs = "friction at the edge of the axle at x = " + shortNumber(x) + " m (" + w.name + ")";
    }
    if (width < gap.value) {
      gap.value = width;
      gap.governs = "the far edge as a step for the axle at x = " + shortNumber(x) + " m";
    }
    step.detail += (step.detail.empty() ? "" : "; ") + std::string("x = ") + shortNumber(x) + ": L " +
                   shortNumber(load) + " N, P " + shortNumber(push) + " N, h <= " + shortNumber(h) + " m";
  }
  // A rigid three-axle all-wheel drive lifts its middle axle as soon as the front rises a few tyre
  // deflections: front and rear carry W/2, P/L = mu, alpha <= 2 phi.
  if (axles.size() == 3 && v.allDriven() && v.roots.size() == 1) {
    const double r = v.wheels.front().radius_m;
    step.lower = stepHeight(r, 2.0 * phi);
    const double h = *step.lower;
    gap.lower = 2.0 * std::sqrt(h * (2.0 * r - h));
    step.detail += "; rigid, middle axle hanging: h <= " + shortNumber(*step.lower) + " m";
  }
}

void sideSlope(const VehicleStatics& v, double peak, VehicleBounds& out) {
  const Loads n0 = wheelLoads(v);
  const double weight = v.weight();
  double lateral = 0.0;
  for (std::size_t i = 0; i < v.wheels.size(); ++i) {
    if (!v.wheels[i].caster) lateral += n0.normal_N[i];
  }
  double slide = std::atan(peak * lateral / weight);
  std::string slide_note = "the side-resisting wheels carry " + shortNumber(100.0 * lateral / weight) + " % of W";
  if (v.hitch) {
    // The towed body resists sideways at one axle: its yaw balance about it puts H = G_b (x_cb - x_m) /
    // (x_h - x_m) on the hitch; the tug carries G_a + H at its axle, and H's yaw moment about that axle as
    // a longitudinal couple of its two held wheels (first order: level loads times cos phi).
    const HitchInfo& h = *v.hitch;
    std::vector<const WheelInfo*> side_a, side_b;
    std::set<double> xa, xb;
    for (const WheelInfo& w : v.wheels) {
      if (w.caster) continue;
      (w.root == h.root_a ? side_a : side_b).push_back(&w);
      (w.root == h.root_a ? xa : xb).insert(std::round(w.position.x() / kAxleTolM) * kAxleTolM);
    }
    const auto root = [&](int body) {
      return *std::find_if(v.roots.begin(), v.roots.end(), [&](const RootInfo& r) { return r.body == body; });
    };
    if (xa.size() == 1 && xb.size() == 1 && side_a.size() == 2) {
      const RootInfo a = root(h.root_a), b = root(h.root_b);
      const double xm = *xb.begin(), xd = *xa.begin(), xh = h.point.x();
      const double share = (b.com.x() - xm) / (xh - xm);
      double n_main = 0.0, n_tug = INFINITY;
      for (std::size_t i = 0; i < v.wheels.size(); ++i) {
        if (v.wheels[i].caster) continue;
        if (v.wheels[i].root == h.root_b) n_main += n0.normal_N[i];
        if (v.wheels[i].root == h.root_a) n_tug = std::min(n_tug, n0.normal_N[i]);
      }
      const double tan_main = peak * n_main / ((1.0 - share) * b.mass_kg * kGravityMps2);
      const double half = std::abs(side_a.front()->position.y());
      const double lateral_kg = (a.mass_kg + share * b.mass_kg) / 2.0;
      const double couple_kg = share * b.mass_kg * (xd - xh) / (2.0 * half);
      const double tan_tug = peak * n_tug / (std::hypot(lateral_kg, couple_kg) * kGravityMps2);
      slide = std::atan(std::min(tan_tug, tan_main));
      slide_note = "the hitch carries " + shortNumber(share) +
                   " of the towed body's side load; the tug's wheels slide at " +
                   shortNumber(std::atan(tan_tug) * kDegPerRad) + " deg, the towed body's at " +
                   shortNumber(std::atan(tan_main) * kDegPerRad) + " deg";
    }
  }
  // Tipping about the downhill contacts: atan(half-width of the support at the centre of mass / its height).
  double tip = INFINITY;
  std::string tip_note;
  for (const RootInfo& r : v.roots) {
    std::vector<std::pair<double, double>> support;
    for (const WheelInfo& w : v.wheels) {
      if (w.root == r.body) support.emplace_back(w.position.x(), std::abs(w.position.y()));
    }
    if (v.hitch && r.body == v.hitch->root_b) support.emplace_back(v.hitch->point.x(), 0.0);
    double half = 0.0;
    for (const auto& [x1, y1] : support) {
      for (const auto& [x2, y2] : support) {
        if (x1 == x2) {
          if (std::abs(x1 - r.com.x()) < kAxleTolM) half = std::max({half, y1, y2});
          continue;
        }
        const double t = (r.com.x() - x1) / (x2 - x1);
        if (t >= 0.0 && t <= 1.0) half = std::max(half, y1 + t * (y2 - y1));
      }
    }
    const double angle = std::atan2(half, r.com.z());
    if (angle < tip) {
      tip = angle;
      tip_note = "half-width " + shortNumber(half) + " m at the centre of mass, " + shortNumber(r.com.z()) + " m high";
    }
  }
  out.side_slide_deg = slide * kDegPerRad;
  out.side_tip_deg = tip * kDegPerRad;
  out.side_slope_deg.value = std::min(slide, tip) * kDegPerRad;
  out.side_slope_deg.governs = slide <= tip ? "sliding" : "tipping";
  out.side_slope_deg.detail = "slides at " + shortNumber(slide * kDegPerRad) + " deg (" + slide_note + "), tips at " +
                              shortNumber(tip * kDegPerRad) + " deg (" + tip_note + ")";
}

std::optional<Bound> turn(const VehicleStatics& v, const Material& g, const TurnSettings& t, double& moment) {
  moment = 0.0;
  if (!v.allDriven() || v.roots.size() != 1) return std::nullopt;
  const double half = std::abs(v.wheels.front().position.y());
  for (const WheelInfo& w : v.wheels) {
    if (std::abs(std::abs(w.position.y()) - half) > kAxleTolM) return std::nullopt;  // one track only
  }
  const Loads n0 = wheelLoads(v);
  for (std::size_t i = 0; i < v.wheels.size(); ++i) {
    moment += g.mu_max * n0.normal_N[i] * v.wheels[i].position.head<2>().norm();
  }
  // The steady turn at wheel rates +-omega (right forward): the yaw moment of the ground forces vanishes.
  const double rate = t.wheel_rate_radps, r = v.wheels.front().radius_m;
  const auto yaw = [&](double omega) {
    double total = 0.0;
    for (std::size_t i = 0; i < v.wheels.size(); ++i) {
      const double x = v.wheels[i].position.x(), y = v.wheels[i].position.y();
      const double spin = y < 0.0 ? rate : -rate;
      const Eigen::Vector2d vs(-omega * y - spin * r, omega * x);
      const double speed = vs.norm();
      const double vo = std::max(omega * std::hypot(x, y), kMinTurnSpeedMps);
      const double f = -tractionCoefficient(g, speed / vo) * n0.normal_N[i] / speed;
      total += x * f * vs.y() - y * f * vs.x();
    }
    return total;
  };
  Bound b;
  b.value = bisect(yaw, 1e-6, rate * r / half);
  b.governs = "the slip law's direction at the sliding wheels";
  b.detail = "sum mu N_i d_i = " + shortNumber(moment) +
             " N m to drag the wheels around; yaw balance at wheel rates +-" + shortNumber(rate) + " rad/s";
  return b;
}

// A free wheel on a soil rolls on its bearing at the slip where the soil's
// torque on it is zero (it skids a little: T(-1) < 0 <= T(0)); there it
// pulls its compaction resistance (DP < 0).
double freeWheelPull(const Soil& soil, const WheelInfo& w, double load) {
  auto at = [&](double slip) { return steadyWheelOnSoil(soil, w.radius_m, w.width_m, load, slip).forces; };
  const double slip = bisect([&](double i) { return at(i).torque; }, -1.0, 0.0);
  return at(slip).drawbar_pull;
}

// The steepest grade climbed on soft soil (docs/soft-soil.md, the grade on
// sand). Facing up theta, each wheel carries its share N_k(theta) of W cos
// theta and more (wheelLoads); the driven wheels, at one slip i, pull
// DP(N_k, i) from the soil's steady state, the free ones their compaction
// resistance; the vehicle climbs while sum DP >= W sin theta. The event
// calls it climbed when the vehicle advances min_progress along the slope
// in its duration, while its wheels turn omega (T - ramp / 2) (the drive's
// rate limit clamps omega): the slip may be at most i_max = 1 - d / (r
// omega (T - ramp / 2)). A drive at its torque limit holds the slip
// below that. Tip-over as on hard ground.
Bound soilGrade(const VehicleStatics& v, const Soil& soil, const GradeSettings& s) {
  double rate = s.wheel_rate_radps, r = 0.0;
  for (const WheelInfo& w : v.wheels) {
    if (!w.driven) continue;
    if (w.max_rate_radps > 0.0) rate = std::min(rate, w.max_rate_radps);
    r = w.radius_m;
  }
  Bound b;
  const double travel = r * rate * (s.duration_s - 0.5 * kEventRampS);
  const double slip_max = 1.0 - s.min_progress_m / travel;
  if (!(slip_max > 0.0)) {
    b.governs = "the drives' rate";
    b.detail = "the wheels roll " + shortNumber(travel) + " m in the run, less than min_progress " +
               shortNumber(s.min_progress_m) + " m";
    return b;
  }
  // Sum DP - W sin theta at slip i, or nullopt where a drive's torque is past its limit.
  const auto margin = [&](double theta, double i) -> std::optional<double> {
    const Loads n = wheelLoads(v, theta);
    if (!n.equilibrium) return -v.weight();
    double pull = 0.0;
    for (std::size_t k = 0; k < v.wheels.size(); ++k) {
      const WheelInfo& w = v.wheels[k];
      const double load = n.normal_N[k];
      if (!(load > 0.0)) continue;
      if (!w.driven) {
        pull += freeWheelPull(soil, w, load);
        continue;
      }
      const WheelSoilForces f = steadyWheelOnSoil(soil, w.radius_m, w.width_m, load, i).forces;
      if (w.max_torque_Nm > 0.0 && f.torque > w.max_torque_Nm) return std::nullopt;
      pull += f.drawbar_pull;
    }
    return pull - v.weight() * std::sin(theta);
  };
  // The largest slip the drives' torques allow on theta, up to slip_max.
  const auto slipOn = [&](double theta) {
    if (margin(theta, slip_max)) return slip_max;
    return bisect([&](double i) { return margin(theta, i) ? 1.0 : -1.0; }, 0.0, slip_max);
  };
  const double traction =
      bisect([&](double theta) { return margin(theta, slipOn(theta)).value_or(-v.weight()); }, 0.0, kSearchTopRad);
  const double slip = slipOn(traction), tip = tipGrade(v);
  b.value = std::min(traction, tip) * kDegPerRad;
  b.governs = tip < traction ? "tip-over" : (slip < slip_max ? "drive torque on " : "the pull of ") + soil.name;
  b.detail = "sum DP(N_k(theta), i) = W sin theta at i = " + shortNumber(slip) + " (i_max " + shortNumber(slip_max) +
             ": min_progress " + shortNumber(s.min_progress_m) + " m of " + shortNumber(travel) +
             " m of rim travel): " + shortNumber(traction * kDegPerRad) + " deg" +
             (v.roots.size() == 1 ? ", tip-over " + shortNumber(tip * kDegPerRad) + " deg" : "");
  return b;
}

// DP/W and sum T / (r_f W) on soft soil: each driven wheel at the soil's
// steady state under its static load at slip i (steadyWheelOnSoil), each
// free wheel at the slip where the soil's torque on it is zero (it rolls
// on its bearing, pulling its compaction resistance).
std::vector<DrawbarPoint> soilDrawbar(const VehicleStatics& v, const Soil& soil, const Loads& n0,
                                      const std::vector<double>& slips) {
  std::vector<DrawbarPoint> points;
  for (const double i : slips) {
    double pull = 0.0, torque = 0.0;
    for (std::size_t k = 0; k < v.wheels.size(); ++k) {
      const WheelInfo& w = v.wheels[k];
      const double load = n0.normal_N[k];
      if (!(load > 0.0)) continue;
      auto at = [&](double slip) { return steadyWheelOnSoil(soil, w.radius_m, w.width_m, load, slip).forces; };
      if (w.driven) {
        const WheelSoilForces f = at(i);
        pull += f.drawbar_pull;
        torque += f.torque / w.radius_m;
        continue;
      }
      pull += freeWheelPull(soil, w, load);
    }
    points.push_back({.slip = i, .dp_per_weight = pull / v.weight(), .torque_coefficient = torque / v.weight()});
  }
  return points;
}

}  // namespace

double slipLawPeak(const Material& g) { return tractionPeak(g); }

VehicleBounds computeBounds(const VehicleStatics& v, const MobilitySettings& settings) {
  const Material& g = settings.ground;
  const double peak = tractionPeak(g);
  VehicleBounds out;
  // On a soil the grade's bound costs a steady state per wheel per trial
  // grade and slip, and a soil too weak for the vehicle refuses it: made
  // only when the event is asked for.
  const bool grade_asked = std::find(settings.events.begin(), settings.events.end(), "grade") != settings.events.end();
  if (!g.soil) {
    out.grade_deg = grade(v, g, peak);
  } else if (grade_asked) {
    out.grade_deg = soilGrade(v, *g.soil, settings.grade);
  } else {
    out.grade_deg.governs = "not computed: the grade event was not asked for on this soil";
  }
  out.parked_deg = parked(v, peak);
  sideSlope(v, peak, out);
  stepAndGap(v, g, peak, out.step_m, out.gap_m);
  out.turn_radps = turn(v, g, settings.turn, out.turn_moment_Nm);

  const Loads n0 = wheelLoads(v);
  const double weight = v.weight(), k = g.rolling_resistance * v.wheels.front().r0_ratio;
  if (g.soil) {
    out.drawbar = soilDrawbar(v, *g.soil, n0, settings.drawbar.slips);
  }
  for (const double i : g.soil ? std::vector<double>{} : settings.drawbar.slips) {
    const double mu = tractionCoefficient(g, i / (1.0 - i));
    // DP = mu(s) N_driven - f_r (r0/r_f) N_free; the drives also carry their wheels' rolling moment.
    out.drawbar.push_back({.slip = i,
                           .dp_per_weight = (mu * n0.driven_N - k * n0.free_N) / weight,
                           .torque_coefficient = (mu * n0.driven_N + k * n0.driven_N) / weight});
  }

  // Coast-down: a = sum f_r N_i r0_i / r_i / (m + sum I_i / r_i^2).
  double resist = 0.0, inertia = 0.0;
  for (std::size_t i = 0; i < v.wheels.size(); ++i) {
    const WheelInfo& w = v.wheels[i];
    resist += g.rolling_resistance * w.r0_ratio * n0.normal_N[i];
    inertia += w.spin_inertia / (w.radius_m * w.radius_m);
  }
  out.coast_mps2.value = resist / (v.mass_kg + inertia);
  out.coast_mps2.governs = "rolling resistance with the wheels' inertia";
  out.coast_mps2.detail = "sum f_r N r0/r_f = " + shortNumber(resist) +
                          " N over m + sum I/r^2 = " + shortNumber(v.mass_kg + inertia) + " kg";

  // Locked stop from V: every wheel at mu(1) (all driven); else the driven wheels locked, the rest
  // rolling, with the deceleration's load transfer (iterated).
  const double mu1 = tractionCoefficient(g, 1.0), speed = settings.braking.speed_mps;
  double decel = kGravityMps2 * mu1;
  if (!v.allDriven()) {
    double free_inertia = 0.0;
    for (const WheelInfo& w : v.wheels) {
      if (!w.driven) free_inertia += w.spin_inertia / (w.radius_m * w.radius_m);
    }
    decel = kGravityMps2 * mu1 * n0.driven_N / weight;
    for (int it = 0; it < 50; ++it) {
      const Loads n = wheelLoads(v, 0.0, -decel, k);
      decel = (mu1 * n.driven_N + k * n.free_N) / (v.mass_kg + free_inertia);
    }
  }
  out.braking_m.value = speed * speed / (2.0 * decel);
  out.braking_m.governs = v.allDriven() ? "mu(1) at every wheel" : "mu(1) at the locked (driven) wheels";
  out.braking_m.detail = "deceleration " + shortNumber(decel) + " m/s^2, mu(1) = " + shortNumber(mu1, 6);
  // Pitch-over: at that deceleration the loads' moment about the leading
  // locked wheels tips the vehicle (the wheels behind lift and it goes over
  // them: m a h > m g l, l the centre of mass's lead over those wheels, h its
  // height; issue 57 row 6: a front-drive robot landed upside down and the
  // report said +100.3 % of this distance).
  if (!wheelLoads(v, 0.0, -decel, v.allDriven() ? 0.0 : k).equilibrium) {
    out.braking_m.governs = "pitch-over about the locked wheels: no stop on its wheels";
    out.braking_m.detail += "; at that deceleration the wheels behind lift and the vehicle goes over the locked ones";
  }
  return out;
}

}  // namespace wtc::mobility
