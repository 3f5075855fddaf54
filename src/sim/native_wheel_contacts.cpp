#include "native_wheel_contacts.hpp"

#include <algorithm>

#include "base/scratch_capacity.hpp"

namespace wtc::sim {

NativeWheelContacts::NativeWheelContacts() { contacts_.reserve(kReservedContacts); }

void NativeWheelContacts::clear() {
  contacts_.clear();
  forces_ = WheelForces{};
}

void NativeWheelContacts::add(const Eigen::Vector3d& ground_point, const Eigen::Vector3d& normal, double depth,
                              const Eigen::Vector3d& force) {
  ContactForce& c = contacts_.emplace_back();
  c.contact.ground_point = ground_point;
  c.contact.point = ground_point;
  c.contact.e = -normal;
  c.contact.deflection = std::max(depth, 0.0);
  c.normal_force = std::max(force.dot(normal), 0.0);
  c.force = force;
  c.tangential_force = force - force.dot(normal) * normal;
  c.mu = c.normal_force > 0.0 ? c.tangential_force.norm() / c.normal_force : 0.0;
}

void NativeWheelContacts::finish(const Eigen::Vector3d& centre, const Eigen::Vector3d& axle) {
  for (const ContactForce& c : contacts_) {
    forces_.force += c.force;
    forces_.torque += (c.contact.ground_point - centre).cross(c.force);
  }
  forces_.axial_moment = axle * axle.dot(forces_.torque);
  forces_.bearing_moment = forces_.torque - forces_.axial_moment;
  forces_.contacts = contacts_;
}

NativeWheelSet::NativeWheelSet(const vehicle::VehicleDescription& vehicle)
    : wheels_(vehicle.wheels().size()), bodies_(vehicle.wheels()) {}

void NativeWheelSet::clear() {
  for (NativeWheelContacts& w : wheels_) w.clear();
}

void NativeWheelSet::finish(const Engine& engine) {
  for (std::size_t k = 0; k < wheels_.size(); ++k) {
    const vehicle::BodyKinematics b = engine.body(bodies_[k]);
    wheels_[k].finish(b.pose.translation(), b.pose.linear() * engine.vehicle().bodies[bodies_[k]].wheel->axle);
  }
}

}  // namespace wtc::sim
