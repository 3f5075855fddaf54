// The soil's stresses as a contact's force (design in docs/soft-soil.md).
//
// The frame: n = -e, the soil surface's normal at the contact (its piece's
// face under a wheel on flat soil); the travel t = +-(a x n) / |a x n|, the
// way the wheel moves (a wheel spinning forward about a rolls toward a x n);
// l = n x (a x n) / |.|, the axle laid on the surface. With the travel speed
// v = V_O . t, the rim speed r omega . a (mirrored with t) and v_y = V_O . l:
//   i = soilSlip(v, r omega, eps),  beta = atan2(v_y, max(v, eps)),
//   symmetry = (1 - max(|v|, |r omega|) / w)+  (a wheel at rest sits in its own hollow),
// w the rest ramp's width (below).
// The sinkage is the contact's Z (a rigid wheel: the soil takes all of it).
// The stresses of a fresh surface depend on z alone, a spring without
// loss; the soil's damping R (Pa s/m, as Project Chrono's SCM adds to its
// Bekker pressure) over the patch b L damps the wheel's bounce:
//   the normal force is max(0, W + R b L v_z),  L = r (sin theta_1 - sin theta_2),
// v_z the rim's speed into the soil. The shear scales with the normal
// stress only as the damping unloads it (by min(1, that ratio)): on a soil
// too weak to carry the wheel W -> 0 while R b L v_z does not, and a ratio
// above one multiplied the cohesion's shear, which does not grow with the
// pressure, into a cart thrown 33 m (docs/soft-soil.md).
// Where the ground remembers (a GroundMemory region under the rim's lowest
// point P), Z is the depth below the fresh surface, the stresses meet the
// remembered one along the travel's horizontal direction (GridProfile), and
// the rim then presses the nodes under its arc (pressNodes): the wheels
// after it meet the rut it leaves.
#include "soil_contact.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "ground_memory_access.hpp"
#include "wtc/base/tolerances.hpp"
#include "wtc/tyre/wheel_soil.hpp"

namespace wtc::detail {

void applySoil(const KernelInputs& in, double width, std::span<const WheelContact> contacts, GroundMemory* memory,
               ContactForce* out) {
  const double r = in.free_radius, eps = in.slip_speed_floor;
  const Eigen::Vector3d& a = in.axle;
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const WheelContact& c = contacts[k];
    const Material& material = in.materials[static_cast<std::size_t>(c.material)];
    if (!material.soil) continue;
    const Eigen::Vector3d n = -c.e;
    Eigen::Vector3d travel = a.cross(n);
    const double across = travel.norm();
    ContactForce& f = out[k];
    f = ContactForce{};
    f.contact = c;
    f.soft_soil = true;
    // A wheel on its side (axle along the normal) has no arc to integrate.
    if (across < tolerance::kWheelOnItsSideSine) continue;
    travel /= across;
    const Eigen::Vector3d lateral = n.cross(travel);
    const double v_x = in.motion->velocity.dot(travel);
    const double rim_x = r * in.motion->angular_velocity.dot(a);
    const double direction = v_x + rim_x >= 0.0 ? 1.0 : -1.0;
    travel *= direction;
    const double v = direction * v_x, rim = direction * rim_x;
    const double v_y = in.motion->velocity.dot(lateral);

    // The ground's memory under P along the travel's horizontal direction
    // (none on a travel near the vertical: a wheel falling into the soil).
    SoilGrid* grid = memory != nullptr ? GroundMemoryAccess::gridAt(*memory, c.point.x(), c.point.y()) : nullptr;
    const Eigen::Vector2d bottom = c.point.head<2>();
    Eigen::Vector2d level = travel.head<2>();
    if (grid != nullptr && level.norm() < tolerance::kWheelOnItsSideSine) grid = nullptr;
    std::optional<GridProfile> profile;
    if (grid != nullptr) {
      level.normalize();
      profile.emplace(*grid, bottom, level);
    }

    WheelSoilState state;
    state.radius = r;
    state.width = width;
    state.sinkage = grid != nullptr ? c.deflection : std::min(c.deflection, r);
    if (profile) state.memory = &*profile;
    state.slip = soilSlip(v, rim, eps);
    state.slip_angle = std::atan2(v_y, std::max(v, eps));
    WheelSoilForces soil = wheelSoilForces(*material.soil, state);
    // The rest ramp is wide enough that its pull and torque cannot reverse
    // the wheel within a step: h |DP| / (kappa m) in travel, r h |T| / (kappa I)
    // at the rim (the explicit step's stability, as the rolling resistance's ramp).
    const double ramp = std::max({eps, in.travel_ramp_gain * std::abs(soil.drawbar_pull),
                                  r * in.spin_ramp_gain * std::abs(soil.torque)});
    state.symmetry = std::max(0.0, 1.0 - std::max(std::abs(v), std::abs(rim)) / ramp);
    if (state.symmetry > 0.0) soil = wheelSoilForces(*material.soil, state);
    const Eigen::Vector3d point_velocity = in.motion->velocity + in.motion->angular_velocity.cross(r * c.e);
    f.deflection_rate = point_velocity.dot(c.e);
    // The soil's damping R v_z over the contact patch b L, L = r (sin theta_1 - sin theta_2).
    const double length = r * (std::sin(soil.entry_angle) - std::sin(soil.exit_angle));
    const double damped = std::max(0.0, soil.normal + material.soil->damping * width * length * f.deflection_rate);
    const double scale = soil.normal > 0.0 ? std::min(1.0, damped / soil.normal) : 0.0;

    // The soil as a spring about z for the stability report and the
    // engine-solved modes' normal row: Bekker's W ~ z^(n + 1/2) (the closed
    // form of docs/soft-soil.md) has dW/dz = (n + 1/2) W / z.
    const double exponent = material.soil->n + 0.5;
    const double z = profile ? r * (1.0 - std::cos(soil.entry_angle)) : state.sinkage;
    f.soil_sinkage = z;
    if (z > 0.0) {
      f.soil_stiffness = c.load_share * exponent * soil.normal / z;
      f.soil_depth = z / exponent;
    }
    f.soil_damping = c.load_share * material.soil->damping * width * length;
    const double share = c.load_share * scale;
    const Eigen::Vector3d tangential = share * (soil.drawbar_pull * travel + soil.lateral * lateral);
    f.normal_force = c.load_share * damped;
    f.tangential_force = tangential;
    f.force = f.normal_force * n + tangential;
    f.slip_velocity = point_velocity - f.deflection_rate * c.e;
    f.slip_ratio = state.slip;
    f.mu = f.normal_force > 0.0 ? tangential.norm() / f.normal_force : 0.0;
    f.friction_limit = f.mu;
    const Eigen::Vector3d spin_axis = direction * a;
    f.rolling_moment = -share * soil.torque * spin_axis - a.dot((r * c.e).cross(f.force)) * a;
    if (profile) {
      pressNodes(*grid, *material.soil,
                 {.bottom = bottom, .travel = level, .radius = r, .width = width, .depth = c.deflection,
                  .entry_angle = soil.entry_angle, .at_rest = state.symmetry});
    }
  }
}

}  // namespace wtc::detail
