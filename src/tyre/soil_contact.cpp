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
namespace {

// The travel frame of one contact (n the surface's normal): the travel t,
// the axle laid on the surface n x t (the lateral), the axis the rim spins
// about, and the speeds along them.
struct SoilFrame {
  Eigen::Vector3d travel, lateral, spin_axis;
  double v = 0.0, rim = 0.0, v_y = 0.0;  ///< V . t, the rim's speed along t, the side slip's speed.
};

// A wheel on `axle` a: t = +-(a x n) / |a x n|, the sign the way it moves
// (none on its side, the axle along the normal: no arc to integrate).
std::optional<SoilFrame> wheelFrame(const KernelInputs& in, const Eigen::Vector3d& axle, const Eigen::Vector3d& n) {
  Eigen::Vector3d travel = axle.cross(n);
  const double across = travel.norm();
  if (across < tolerance::kWheelOnItsSideSine) return std::nullopt;
  travel /= across;
  SoilFrame f;
  f.lateral = n.cross(travel);
  const double v_x = in.motion->velocity.dot(travel);
  const double rim_x = in.free_radius * in.motion->angular_velocity.dot(axle);
  const double direction = v_x + rim_x >= 0.0 ? 1.0 : -1.0;
  f.travel = direction * travel;
  f.spin_axis = direction * axle;
  f.v = direction * v_x;
  f.rim = direction * rim_x;
  f.v_y = in.motion->velocity.dot(f.lateral);
  return f;
}

// A ball rolls about any axle: t is the way its centre's travel and its
// rim's roll (r omega x n) carry it together, the axle n x t; the side slip
// is its lowest point's, V . a + r omega . t. Where both are below a
// rounding's reach of the slip floor (a ball dropped straight down) the
// frame is its body's axle's, as a wheel's, or the surface's own.
SoilFrame ballFrame(const KernelInputs& in, const Eigen::Vector3d& n) {
  const Eigen::Vector3d& velocity = in.motion->velocity;
  const Eigen::Vector3d& spin = in.motion->angular_velocity;
  const double r = in.free_radius;
  const Eigen::Vector3d travel = velocity - velocity.dot(n) * n + r * spin.cross(n);
  std::optional<SoilFrame> f;
  if (travel.norm() >= tolerance::kWheelOnItsSideSine * in.slip_speed_floor) {
    // v + rim = |travel|^2 / |travel| >= 0: oriented as wheelFrame orients.
    f.emplace();
    f->travel = travel.normalized();
  } else if (!(f = wheelFrame(in, in.axle, n))) {
    f = wheelFrame(in, n.unitOrthogonal(), n);  // an axle on the surface: never on its side
  }
  f->lateral = n.cross(f->travel);
  f->spin_axis = f->lateral;
  f->v = velocity.dot(f->travel);
  f->rim = r * spin.dot(f->spin_axis);
  f->v_y = velocity.dot(f->lateral) + r * spin.dot(f->travel);
  return *f;
}

}  // namespace

void applySoil(const KernelInputs& in, double width, std::span<const WheelContact> contacts, GroundMemory* memory,
               ContactForce* out) {
  const double r = in.free_radius, eps = in.slip_speed_floor;
  const bool ball = width >= 2.0 * r;  // the tread is a whole sphere (wheel_contact.hpp)
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const WheelContact& c = contacts[k];
    const Material& material = in.materials[static_cast<std::size_t>(c.material)];
    if (!material.soil) continue;
    const Eigen::Vector3d n = -c.e;
    ContactForce& f = out[k];
    f = ContactForce{};
    f.contact = c;
    f.soft_soil = true;
    const std::optional<SoilFrame> frame = ball ? ballFrame(in, n) : wheelFrame(in, in.axle, n);
    if (!frame) continue;
    const Eigen::Vector3d &travel = frame->travel, &lateral = frame->lateral;
    const double v = frame->v, rim = frame->rim;

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

    const double sinkage = grid != nullptr ? c.deflection : std::min(c.deflection, r);
    const SoilMemoryProfile* remembered = profile ? &*profile : nullptr;
    const double slip = soilSlip(v, rim, eps);
    const auto forcesAt = [&](double symmetry) {
      if (ball) {
        return sphereSoilForces(*material.soil, {.radius = r, .sinkage = sinkage, .travel_speed = v,
                                                 .rim_speed = rim, .side_slip_speed = frame->v_y,
                                                 .speed_floor = eps, .symmetry = symmetry, .memory = remembered});
      }
      return wheelSoilForces(*material.soil, {.radius = r, .width = width, .sinkage = sinkage,
                                              .slip = slip,
                                              .slip_angle = std::atan2(frame->v_y, std::max(v, eps)),
                                              .symmetry = symmetry, .memory = remembered});
    };
    WheelSoilForces soil = forcesAt(0.0);
    // The rest ramp is wide enough that its pull and torque cannot reverse
    // the wheel within a step: h |DP| / (kappa m) in travel, r h |T| / (kappa I)
    // at the rim (the explicit step's stability, as the rolling resistance's ramp).
    const double ramp = std::max({eps, in.travel_ramp_gain * std::abs(soil.drawbar_pull),
                                  r * in.spin_ramp_gain * std::abs(soil.torque)});
    const double symmetry = std::max(0.0, 1.0 - std::max(std::abs(v), std::abs(rim)) / ramp);
    if (symmetry > 0.0) soil = forcesAt(symmetry);
    // The side's bulldozing F_u is Ishigami's whole passive earth pressure
    // at any side slip, a step in F_y as v_y crosses 0 (Coulomb's, on a
    // wheel rolling straight: it flipped with the side speed's rounding).
    // It is ramped over the side speed it could reverse within a step,
    // h F_u / (kappa m) (as the rest ramp above): F_u min(1, |v_y| / that).
    if (soil.bulldozing > 0.0) {
      const double side_ramp = std::max(eps, in.travel_ramp_gain * soil.bulldozing);
      const double unramped = soil.bulldozing * (1.0 - std::min(1.0, std::abs(frame->v_y) / side_ramp));
      soil.lateral += std::copysign(unramped, frame->v_y);
      soil.bulldozing -= unramped;
    }
    const Eigen::Vector3d point_velocity = in.motion->velocity + in.motion->angular_velocity.cross(r * c.e);
    f.deflection_rate = point_velocity.dot(c.e);
    // The soil's damping R v_z over the contact patch: b L under a wheel,
    // L = r (sin theta_1 - sin theta_2); the slices' sum under a ball.
    const double length = r * (std::sin(soil.entry_angle) - std::sin(soil.exit_angle));
    const double patch_damping =
        ball ? material.soil->damping * soil.patch_area : material.soil->damping * width * length;
    const double damped = std::max(0.0, soil.normal + patch_damping * f.deflection_rate);
    const double scale = soil.normal > 0.0 ? std::min(1.0, damped / soil.normal) : 0.0;

    // The soil as a spring about z for the stability report and the
    // engine-solved modes' normal row: Bekker's W ~ z^(n + 1/2) under a
    // wheel (the closed form of docs/soft-soil.md), W ~ z^(n + 1) under a
    // ball (wheel_soil.hpp), so dW/dz = e W / z with that exponent e, and
    // the depth at which that spring carries W is z / e. No stiffer than
    // the soil's reloading line over the patch, k_u A: in a rut the centre
    // line may barely enter the remembered surface (z ~ 1e-7 m) while the
    // rest of the patch carries W, and e W / z was a thousand times that.
    const double exponent = material.soil->n + (ball ? 1.0 : 0.5);
    const double z = profile ? r * (1.0 - std::cos(soil.entry_angle)) : sinkage;
    f.soil_sinkage = z;
    if (z > 0.0) {
      const double tangent = exponent * soil.normal / z;
      const double reload = material.soil->unloading_stiffness * (ball ? soil.patch_area : width * length);
      f.soil_stiffness = c.load_share * std::min(tangent, reload);
      f.soil_depth = tangent <= reload ? z / exponent : soil.normal / reload;
    }
    f.soil_damping = c.load_share * patch_damping;
    const double share = c.load_share * scale;
    const Eigen::Vector3d tangential = share * (soil.drawbar_pull * travel + soil.lateral * lateral);
    f.normal_force = c.load_share * damped;
    f.tangential_force = tangential;
    f.force = f.normal_force * n + tangential;
    f.slip_velocity = point_velocity - f.deflection_rate * c.e;
    f.slip_ratio = slip;
    f.mu = f.normal_force > 0.0 ? tangential.norm() / f.normal_force : 0.0;
    f.friction_limit = f.mu;
    // Less OP x R's moment about the axle (its sign cancels: +-a alike).
    const Eigen::Vector3d& spin_axis = frame->spin_axis;
    f.rolling_moment = -share * soil.torque * spin_axis - spin_axis.dot((r * c.e).cross(f.force)) * spin_axis;
    if (profile) {
      // A ball presses its whole round patch, radius a = sqrt(z (2 r - z))
      // (r from the equator down), across and along: its centre line's
      // entry may lie near the bottom while its sides press a rut's walls
      // (where the ball is above the remembered surface nothing changes).
      const double z_band = std::min(c.deflection, r);
      const double half = std::sqrt(z_band * (2.0 * r - z_band));
      pressNodes(*grid, *material.soil,
                 {.bottom = bottom, .travel = level, .radius = r, .width = ball ? 2.0 * half : width,
                  .depth = c.deflection, .entry_angle = ball ? std::asin(half / r) : soil.entry_angle,
                  .at_rest = symmetry, .ball = ball});
    }
  }
}

}  // namespace wtc::detail
