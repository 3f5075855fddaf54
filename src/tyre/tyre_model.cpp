// Assembly of the tyre model and the wheel step (design note in
// include/wtc/tyre/tyre_model.hpp).
#include "wtc/tyre/tyre_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "base/scratch_capacity.hpp"
#include "soil_contact.hpp"
#include "tyre_kernels.hpp"
#include "wtc/base/error.hpp"
#include "wtc/base/tolerances.hpp"

namespace wtc {
namespace {

void requireFiniteMotion(const WheelMotion& motion, double step_seconds, const char* where) {
  if (!isFinite(motion.velocity) || !isFinite(motion.angular_velocity)) {
    throw InvalidInputError(std::string(where) +
                            ": wheel motion is not finite: velocity = " + formatVector(motion.velocity) +
                            ", angular_velocity = " + formatVector(motion.angular_velocity));
  }
  if (!(std::isfinite(step_seconds) && step_seconds > 0.0)) {
    throw InvalidInputError(std::string(where) + ": step_seconds = " + formatNumber(step_seconds) +
                            " must be finite and > 0 (s)");
  }
}

Eigen::Vector3d unitAxle(const Eigen::Vector3d& axle, const char* where) {
  const double norm = axle.norm();
  if (!std::isfinite(norm) || norm < tolerance::kMinAxleNorm) {
    throw InvalidInputError(std::string(where) + ": wheel axle = " + formatVector(axle) + " is not finite or is zero");
  }
  return axle / norm;
}

}  // namespace

WheelState::WheelState() {
  forces_.reserve(kReservedContacts);
  tread_.reserve(kReservedContacts);
  next_tread_.reserve(kReservedContacts);
}

TyreModel::TyreModel(EffectSet effects, ContactMode mode) : effects_(effects), mode_(mode) {
  const bool slip = effects.has(Effect::kSlipTraction);
  const bool coulomb = effects.has(Effect::kCoulombFriction);
  if (slip && coulomb) {
    throw InvalidInputError("wtc::TyreModel: effects '" + effects.toString() +
                            "' ask for two traction laws; choose slip_traction or coulomb_friction");
  }
  const detail::Traction traction =
      slip ? detail::Traction::kSlipLaw : (coulomb ? detail::Traction::kCoulomb : detail::Traction::kNone);
  kernel_ =
      detail::selectKernel(effects.has(Effect::kNormalDamping), traction, effects.has(Effect::kRollingResistance));
  contact_options_.multiple_contacts = effects.has(Effect::kMultipleContacts);
  contact_options_.tread_truncation = effects.has(Effect::kTreadTruncation);
}

const WheelForces& TyreModel::step(const Terrain& terrain, const WheelDescription& wheel, const WheelPose& pose,
                                   const WheelMotion& motion, double step_seconds, WheelState& state) const {
  const std::span<const WheelContact> contacts = state.finder_.find(terrain, wheel.geometry, pose, contact_options_);
  return forces(terrain.materials(), wheel, pose, motion, step_seconds, contacts, state);
}

const WheelForces& TyreModel::stepInEngine(const Terrain& terrain, const WheelDescription& wheel, const WheelPose& pose,
                                           const WheelMotion& motion, double step_seconds, WheelState& state) const {
  const bool finite =
      isFinite(pose.center) && isFinite(pose.axle) && isFinite(motion.velocity) && isFinite(motion.angular_velocity);
  state.last_skipped_ = !finite;
  if (finite) return step(terrain, wheel, pose, motion, step_seconds, state);
  ++state.non_finite_steps_;
  state.tread_.clear();
  state.forces_.clear();
  state.result_ = WheelForces{};
  return state.result_;
}

const WheelForces& TyreModel::forces(std::span<const Material> materials, const WheelDescription& wheel,
                                     const WheelPose& pose, const WheelMotion& motion, double step_seconds,
                                     std::span<const WheelContact> contacts, WheelState& state) const {
  static constexpr const char* kWhere = "wtc::TyreModel::forces";
  validate(wheel, kWhere);
  requireFiniteMotion(motion, step_seconds, kWhere);
  const TyreParameters& tyre = wheel.tyre;
  const WheelInertia& inertia = wheel.inertia;
  const double h = step_seconds;

  detail::KernelInputs in;
  in.materials = materials;
  in.motion = &motion;
  in.axle = unitAxle(pose.axle, kWhere);
  in.free_radius = wheel.geometry.free_radius;
  in.rolling_radius = tyre.rolling_radius_ratio * wheel.geometry.free_radius;
  in.stiffness = tyre.radial_stiffness;
  in.damping = tyre.radial_damping;
  in.step = h;
  in.transport_speed = motion.velocity.norm();
  in.slip_speed_floor = tyre.slip_speed_floor;
  in.sticking = std::max(0.0, 1.0 - in.transport_speed / tyre.slip_speed_floor);
  in.implicit_tread = mode_ == ContactMode::kImplicit;
  // The mass the tread moves along each axis: along the axle the wheel's,
  // m; along the ground an unbraked wheel's contact moves the wheel and
  // turns it, 1 / (1/m + r_f^2 / I) (m/3 for a disc; 1.7 kg for the robot's
  // wheel even under 21 kg); one whose spin a drive or brake holds moves m
  // or more. Capped for m, the free wheel chattered (issue 11, defect 1).
  const double r_f = wheel.geometry.free_radius;
  const double m = inertia.effective_mass;
  const double free_spin = 1.0 / (1.0 / m + r_f * r_f / inertia.axial_inertia);
  const std::array<double, 2> light = {inertia.spin_held ? m : free_spin, m};
  // Force mode: k_i <= (kappa/h)^2 m_i keeps h sqrt(k_i/m_i) <= kappa, the
  // tread force being applied explicitly; the damping b_i = k_i tau_i is
  // critical for m, 2 zeta_t sqrt(k_i m), but at most 2 zeta_t kappa m_i / h:
  // h^2 k_i + 2 h b_i <= (kappa^2 + 4 zeta_t kappa) m_i < 4 m_i, the explicit
  // step's stability for the lighter mass, while a braked wheel keeps its
  // damping. Constraint mode: the engine's friction holds the wheel within
  // the step and the tread state only sets its coefficient (integrated
  // exactly), so the tread keeps its own k_t: capped, its relaxation length
  // grew as h^2 and a parked wheel slid 108 mm at 50 ms (issue 11, defect 2).
  const double kappa = tyre.stability_fraction, zeta = tyre.standstill_damping_ratio;
  const double fade = std::max(0.0, 1.0 - in.transport_speed / tyre.standstill_speed);
  const bool force_mode = mode_ == ContactMode::kForce;
  for (const int i : {detail::kRolling, detail::kLateral}) {
    const double k = force_mode ? std::min(tyre.tangential_stiffness, kappa * kappa * light[i] / (h * h))
                                : tyre.tangential_stiffness;
    const double root_km = force_mode ? std::min(std::sqrt(k * m), kappa * light[i] / h) : std::sqrt(k * m);
    in.tread_stiffness[i] = k;
    in.tread_damping_time[i] = 2.0 * zeta * root_km / k * fade;
  }
  in.spin_ramp_gain = h / (kappa * inertia.axial_inertia);
  in.spin_floor = tyre.spin_floor;
  in.travel_ramp_gain = h / (kappa * m);

  state.forces_.resize(contacts.size());
  state.next_tread_.clear();
  detail::kernel(kernel_)(in, contacts, state.tread_, state.next_tread_, state.forces_.data());
  if (effects_.has(Effect::kSoftSoil)) {
    detail::applySoil(in, wheel.geometry.tread_width, contacts, state.ground_memory_, state.forces_.data());
    // Sunk to the axle: the soil cannot carry the wheel (the stresses are
    // those of z = r beyond; steadyWheelOnSoil names the most it carries).
    const auto sunk = [&](const ContactForce& f) { return f.soft_soil && f.soil_sinkage >= in.free_radius; };
    if (std::any_of(state.forces_.begin(), state.forces_.end(), sunk)) ++state.sunk_steps_;
  }
  std::swap(state.tread_, state.next_tread_);

  // Totals about O and the axial/bearing split (wheel_forces.hpp).
  WheelForces& result = state.result_;
  result.force.setZero();
  Eigen::Vector3d contact_moment = Eigen::Vector3d::Zero(), rolling_moment = Eigen::Vector3d::Zero();
  for (const ContactForce& f : state.forces_) {
    result.force += f.force;
    contact_moment += (in.free_radius * f.contact.e).cross(f.force);
    rolling_moment += f.rolling_moment;
  }
  const Eigen::Vector3d axial_contact = in.axle.dot(contact_moment) * in.axle;
  result.rolling_moment = rolling_moment;
  result.torque = contact_moment + rolling_moment;
  result.axial_moment = axial_contact + rolling_moment;
  result.bearing_moment = contact_moment - axial_contact;
  result.contacts = state.forces_;

  // The springs of several contacts act in parallel on the wheel: their
  // load shares add (two full contacts in a V-valley double c and b). A
  // contact on soft soil adds the soil's spring instead (soil_contact.cpp);
  // the report is the spring nearer its limit.
  double shares = 0.0, soil_stiffness = 0.0, soil_damping = 0.0;
  bool tyre_contact = false;
  for (const ContactForce& f : state.forces_) {
    if (f.soft_soil) {
      soil_stiffness += f.soil_stiffness;
      soil_damping += f.soil_damping;
    } else {
      shares += f.contact.load_share;
      tyre_contact = true;
    }
  }
  shares = std::max(shares, 1.0);
  const double damping = effects_.has(Effect::kNormalDamping) ? tyre.radial_damping : 0.0;
  SpringStability& stability = result.normal_stability;
  stability = explicitSpringStability(shares * tyre.radial_stiffness, shares * damping, inertia.effective_mass, h);
  if (soil_stiffness > 0.0) {
    SpringStability soil = explicitSpringStability(soil_stiffness, soil_damping, inertia.effective_mass, h);
    soil.soil = true;
    if (!tyre_contact || soil.step_number / soil.limit > stability.step_number / stability.limit) stability = soil;
  }
  if (engineSolvesContacts(mode_)) stability.limit = std::numeric_limits<double>::infinity();
  ++state.steps_;
  state.first_unstable_ = !result.normal_stability.stable() && state.unstable_steps_ == 0;
  if (!result.normal_stability.stable()) ++state.unstable_steps_;
  return result;
}

}  // namespace wtc
