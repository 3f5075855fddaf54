#include "wtc/sim/energy_balance.hpp"

#include "wtc/base/constants.hpp"
#include "wtc/vehicle/hitch_law.hpp"

namespace wtc::sim {

EnergyBalance::EnergyBalance(const vehicle::VehicleDescription& vehicle, double step_seconds)
    : vehicle_(vehicle), wheels_(vehicle.wheels()), h_(step_seconds) {}

double EnergyBalance::energyOf(const vehicle::VehicleState& state,
                               std::span<const WheelForces* const> wheel_forces) const {
  double e = 0.0;
  for (std::size_t i = 0; i < vehicle_.bodies.size(); ++i) {
    const vehicle::Body& body = vehicle_.bodies[i];
    const vehicle::BodyKinematics& k = state.bodies[i];
    const Eigen::Vector3d w_body = k.pose.linear().transpose() * k.angular_velocity;  // R^T w
    e += 0.5 * body.mass * k.linear_velocity.squaredNorm() + 0.5 * w_body.dot(body.inertia.cwiseProduct(w_body)) +
         body.mass * kGravityMps2 * k.pose.translation().z();
  }
  for (const int w : wheels_) {
    const double c = vehicle_.bodies[w].wheel->tyre.radial_stiffness;
    for (const ContactForce& f : wheel_forces[w]->contacts) e += 0.5 * c * f.contact.deflection * f.contact.deflection;
  }
  if (vehicle_.hitch) {
    const vehicle::Hitch& h = *vehicle_.hitch;
    const Eigen::Vector3d delta =
        vehicle::hitchForce(h, state.bodies[h.body_a], state.bodies[h.body_b], /*damping_on=*/false).deflection;
    e += 0.5 * delta.dot(h.stiffness.cwiseProduct(delta));
  }
  return e;
}

void EnergyBalance::step(const vehicle::VehicleState& state, std::span<const WheelForces* const> wheel_forces,
                         std::span<const vehicle::DriveReport> drives, double rig_work) {
  energy_ = energyOf(state, wheel_forces);
  if (!started_) {
    initial_ = energy_;
    started_ = true;
    return;
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
