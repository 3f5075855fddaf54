// The planar statics of wtc/mobility/vehicle_statics.hpp (ported from the
// groundwork's tools/mobility_bounds.py, which stays as a cross-check).
#include "wtc/mobility/vehicle_statics.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "wtc/base/constants.hpp"
#include "wtc/base/error.hpp"

namespace wtc::mobility {
namespace {

// A pivot below this (in the units of the rows: N/m, N) leaves the system
// singular: no equilibrium with the supports left.
constexpr double kSingularPivot = 1e-9;

// Gaussian elimination with partial pivoting; false if singular.
bool solve(std::vector<std::vector<double>> a, std::vector<double> b, std::vector<double>& x) {
  const std::size_t n = b.size();
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot = col;
    for (std::size_t r = col; r < n; ++r) {
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    }
    if (std::abs(a[pivot][col]) < kSingularPivot) return false;
    std::swap(a[col], a[pivot]);
    std::swap(b[col], b[pivot]);
    for (std::size_t r = 0; r < n; ++r) {
      if (r == col || a[r][col] == 0.0) continue;
      const double f = a[r][col] / a[col][col];
      for (std::size_t c = col; c < n; ++c) a[r][c] -= f * a[col][c];
      b[r] -= f * b[col];
    }
  }
  x.resize(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = b[i] / a[i][i];
  return true;
}

int rootOf(const vehicle::VehicleDescription& v, int body) {
  while (v.bodies[body].parent >= 0) body = v.bodies[body].parent;
  return body;
}

// One solve with the wheels in `lifted` carrying nothing.
Loads solveLoads(const VehicleStatics& v, double slope, double accel, double k_free, const std::set<int>& lifted) {
  const std::size_t nroots = v.roots.size();
  const std::size_t unknowns = 2 * nroots + (v.hitch ? 1 : 0);
  std::vector<std::vector<double>> rows;
  std::vector<double> rhs;
  const double gx = -kGravityMps2 * std::sin(slope), gz = -kGravityMps2 * std::cos(slope);
  const auto index = [&](int root) {
    for (std::size_t i = 0; i < nroots; ++i) {
      if (v.roots[i].body == root) return i;
    }
    return nroots;
  };
  for (std::size_t i = 0; i < nroots; ++i) {
    const RootInfo& r = v.roots[i];
    const double fx = r.mass_kg * (gx - accel), fz = r.mass_kg * gz;  // gravity and d'Alembert at the centre
    std::vector<double> vert(unknowns, 0.0), mom(unknowns, 0.0);
    for (std::size_t k = 0; k < v.wheels.size(); ++k) {
      const WheelInfo& w = v.wheels[k];
      if (w.root != r.body) continue;
      const double c = lifted.count(static_cast<int>(k)) ? 0.0 : w.stiffness_Npm, x = w.position.x();
      vert[2 * i] -= c;  // N = -c w(x), up at x
      vert[2 * i + 1] -= c * x;
      mom[2 * i] -= c * x;  // its moment x F_z
      mom[2 * i + 1] -= c * x * x;
    }
    double b_vert = -fz, b_mom = -(r.com.x() * fz - r.com.z() * fx);
    if (v.hitch && (r.body == v.hitch->root_a || r.body == v.hitch->root_b)) {
      const double xh = v.hitch->point.x(), zh = v.hitch->point.z(), kz = v.hitch->vertical_stiffness_Npm;
      const std::size_t ia = index(v.hitch->root_a), ib = index(v.hitch->root_b);
      const double sign = r.body == v.hitch->root_b ? 1.0 : -1.0;  // +P on b, -P on a; P_z = kz (w_a - w_b)
      const std::pair<std::size_t, double> terms[] = {
          {2 * ia, kz}, {2 * ia + 1, kz * xh}, {2 * ib, -kz}, {2 * ib + 1, -kz * xh}};
      for (const auto& [j, coef] : terms) {
        vert[j] += sign * coef;
        mom[j] += sign * coef * xh;
      }
      mom[unknowns - 1] += -zh * sign;
    }
    rows.push_back(vert);
    rows.push_back(mom);
    rhs.push_back(b_vert);
    rhs.push_back(b_mom);
  }
  if (v.hitch) {  // the towed root's x balance: its free wheels' ground forces + H_x + m (gx - a) = 0
    const std::size_t i = index(v.hitch->root_b);
    std::vector<double> row(unknowns, 0.0);
    for (std::size_t k = 0; k < v.wheels.size(); ++k) {
      const WheelInfo& w = v.wheels[k];
      if (w.root != v.hitch->root_b) continue;
      const double c = lifted.count(static_cast<int>(k)) ? 0.0 : w.stiffness_Npm, x = w.position.x();
      row[2 * i] += k_free * c;
      row[2 * i + 1] += k_free * c * x;
    }
    row[unknowns - 1] = 1.0;
    rows.push_back(row);
    rhs.push_back(-v.roots[i].mass_kg * (gx - accel));
  }
  Loads loads;
  std::vector<double> x;
  if (!solve(rows, rhs, x)) {
    loads.equilibrium = false;
    return loads;
  }
  for (std::size_t k = 0; k < v.wheels.size(); ++k) {
    const WheelInfo& w = v.wheels[k];
    const std::size_t i = index(w.root);
    const double c = lifted.count(static_cast<int>(k)) ? 0.0 : w.stiffness_Npm;
    const double n = -c * (x[2 * i] + x[2 * i + 1] * w.position.x());
    loads.normal_N.push_back(n);
    (w.driven ? loads.driven_N : loads.free_N) += n;
  }
  if (v.hitch) loads.hitch_x_N = x[unknowns - 1];
  return loads;
}

}  // namespace

double VehicleStatics::weight() const { return mass_kg * kGravityMps2; }

bool VehicleStatics::allDriven() const {
  return std::all_of(wheels.begin(), wheels.end(), [](const WheelInfo& w) { return w.driven; });
}

VehicleStatics describeStatics(const vehicle::VehicleDescription& v) {
  VehicleStatics s;
  s.name = v.name;
  for (std::size_t i = 0; i < v.bodies.size(); ++i) {
    const vehicle::Body& b = v.bodies[i];
    const int root = rootOf(v, static_cast<int>(i));
    auto r = std::find_if(s.roots.begin(), s.roots.end(), [&](const RootInfo& x) { return x.body == root; });
    if (r == s.roots.end()) r = s.roots.insert(s.roots.end(), RootInfo{.body = root});
    r->com = (r->com * r->mass_kg + b.mass * b.pose.translation()) / (r->mass_kg + b.mass);
    r->mass_kg += b.mass;
    s.com = (s.com * s.mass_kg + b.mass * b.pose.translation()) / (s.mass_kg + b.mass);
    s.mass_kg += b.mass;
    if (!b.wheel) continue;
    WheelInfo w;
    w.body = static_cast<int>(i);
    w.name = b.name;
    w.root = root;
    w.position = b.pose.translation();
    w.radius_m = b.wheel->geometry.free_radius;
    w.width_m = b.wheel->geometry.tread_width;
    w.r0_ratio = b.wheel->tyre.rolling_radius_ratio;
    w.stiffness_Npm = b.wheel->tyre.radial_stiffness;
    w.spin_inertia = b.wheel->axle.cwiseAbs().dot(b.inertia);  // the axle along a principal axis
    if (b.joint.actuator && b.parent >= 0) {
      w.driven = true;
      w.max_torque_Nm = b.joint.actuator->max_effort;
      w.max_rate_radps = b.joint.actuator->max_speed;
    }
    const bool swivel = b.parent >= 0 && v.bodies[b.parent].parent >= 0 &&
                        v.bodies[b.parent].joint.type == vehicle::JointType::kRevolute &&
                        std::abs(std::abs(v.bodies[b.parent].joint.axis.z()) - 1.0) < 1e-12;
    w.caster = b.joint.type == vehicle::JointType::kBall || swivel;
    s.wheels.push_back(w);
  }
  if (s.wheels.empty()) throw InvalidInputError("wtc::mobility: vehicle '" + v.name + "' has no wheels");
  if (v.hitch) {
    const vehicle::Hitch& h = *v.hitch;
    HitchInfo hitch{.root_a = rootOf(v, h.body_a),
                    .root_b = rootOf(v, h.body_b),
                    .point = v.bodies[h.body_a].pose * h.point_a,
                    .vertical_stiffness_Npm = h.stiffness.z()};
    for (const WheelInfo& w : s.wheels) {
      if (w.root == hitch.root_b && w.driven) {
        throw InvalidInputError("wtc::mobility: vehicle '" + v.name + "': driven wheel '" + w.name +
                                "' on the towed body (the planar statics handle a driven tug only)");
      }
    }
    s.hitch = hitch;
  }
  return s;
}

Loads wheelLoads(const VehicleStatics& v, double slope, double accel, double k_free) {
  std::set<int> lifted;
  for (;;) {
    Loads loads = solveLoads(v, slope, accel, k_free, lifted);
    if (!loads.equilibrium) return loads;
    int pulling = -1;
    for (std::size_t k = 0; k < loads.normal_N.size(); ++k) {
      if (loads.normal_N[k] < 0.0 && !lifted.count(static_cast<int>(k)) &&
          (pulling < 0 || loads.normal_N[k] < loads.normal_N[pulling])) {
        pulling = static_cast<int>(k);
      }
    }
    if (pulling < 0) {
      for (const int k : lifted) loads.lifted.push_back(v.wheels[k].name);
      return loads;
    }
    lifted.insert(pulling);
  }
}

}  // namespace wtc::mobility
