#include "wtc/sim/energy_balance.hpp"

#include "wtc/base/constants.hpp"
#include "wtc/vehicle/hitch_law.hpp"

namespace wtc::sim {

EnergyBalance::EnergyBalance(const vehicle::VehicleDescription& vehicle, double step_seconds)
    : vehicle_(vehicle), wheels_(vehicle.wheels()), h_(step_seconds), gravity_(kGravityMps2) {}

double EnergyBalance::bodiesEnergy(const vehicle::VehicleState& state) const {
  double e = 0.0;
  for (std::size_t i = 0; i < vehicle_.bodies.size(); ++i) {
    const vehicle::Body& body = vehicle_.bodies[i];
    const vehicle::BodyKinematics& k = state.bodies[i];
    const Eigen::Vector3d w_body = k.pose.linear().transpose() * k.angular_velocity;  // R^T w
    e += 0.5 * body.mass * k.linear_velocity.squaredNorm() + 0.5 * w_body.dot(body.inertia.cwiseProduct(w_body)) +
         body.mass * gravity_ * k.pose.translation().dot(up_);
  }
  if (vehicle_.hitch) {
    const vehicle::Hitch& h = *vehicle_.hitch;
    const Eigen::Vector3d delta =
        vehicle::hitchForce(h, state.bodies[h.body_a], state.bodies[h.body_b], /*damping_on=*/false).deflection;
    e += 0.5 * delta.dot(h.stiffness.cwiseProduct(delta));
  }
  return e;
}

double EnergyBalance::tyresEnergy(std::span<const WheelForces* const> wheel_forces) const {
  double e = 0.0;
  for (const int w : wheels_) {
    const double c = vehicle_.bodies[w].wheel->tyre.radial_stiffness;
    for (const ContactForce& f : wheel_forces[w]->contacts) {
      // Soft soil stores nothing: its W(z) does work on the way down that it
      // gives back at most in part (damping), counted as lost (docs/soft-soil.md).
      if (!f.soft_soil) e += 0.5 * c * f.contact.deflection * f.contact.deflection;
    }
  }
  return e;
}

void EnergyBalance::start(const vehicle::VehicleState& state) { start_ = bodiesEnergy(state); }

void EnergyBalance::setGravity(const Eigen::Vector3d& g_W, const vehicle::VehicleState& state) {
  const double gravity = g_W.norm();
  const Eigen::Vector3d up = -g_W / gravity;
  double source = 0.0;
  for (std::size_t i = 0; i < vehicle_.bodies.size(); ++i) {
    const Eigen::Vector3d& x = state.bodies[i].pose.translation();
    source += vehicle_.bodies[i].mass * (gravity * up.dot(x) - gravity_ * up_.dot(x));
  }
  if (!started_) {
    if (start_) *start_ += source;  // turned before the first step: E_0 is in the new field
  } else {
    rig_work_ += source;
  }
  gravity_ = gravity;
  up_ = up;
}

void EnergyBalance::step(const vehicle::VehicleState& state, std::span<const WheelForces* const> wheel_forces,
                         std::span<const vehicle::DriveReport> drives, double rig_work) {
  const double tyres = tyresEnergy(wheel_forces);
  energy_ = bodiesEnergy(state) + tyres;
  if (!started_) {
    started_ = true;
    initial_ = start_ ? *start_ + tyres : energy_;
    if (!start_) return;  // no start state: the balance starts after this step
  }
  const double h = h_;
  for (std::size_t i = 0; i < drives.size(); ++i) drive_work_ += drives[i].last_effort * state.joint_rate[i] * h;
  rig_work_ += rig_work;
  if (growth() > max_growth_) {
    max_growth_ = growth();
    max_growth_time_ = state.time;
  }
}

}  // namespace wtc::sim
