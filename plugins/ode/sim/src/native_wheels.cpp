#include "native_wheels.hpp"

#include <array>

#include "src/conversions.hpp"
#include "wtc/sim/sim_constants.hpp"

namespace wtc::ode {

NativeWheels::NativeWheels(const sim::Engine& engine, Plugin& plugin, dWorldID world, dJointGroupID contacts,
                           const Terrain& terrain, std::span<const WheelBody> bodies, sim::NativeWheelShape shape)
    : sim::NativeWheels<Plugin, OdeWheels>(engine, plugin, shape),
      world_(world),
      contacts_(contacts),
      terrain_(terrain),
      mu_(sim::nativeWheelFrictions(terrain)) {
  for (const WheelBody& b : bodies) geoms_.push_back(b.geom);
}

int NativeWheels::wheelOf(dGeomID geom) const {
  for (std::size_t k = 0; k < geoms_.size(); ++k) {
    if (geoms_[k] == geom) return static_cast<int>(k);
  }
  return -1;
}

// Only a pair of two geoms, one a wheel's and the other of no body (a
// terrain piece): spaces go on to the engine's callback, which collides
// their geoms and comes back here for each pair.
bool NativeWheels::collide(dGeomID a, dGeomID b) {
  if (dGeomIsSpace(a) || dGeomIsSpace(b)) return false;
  const dBodyID body_a = dGeomGetBody(a), body_b = dGeomGetBody(b);
  if ((body_a == nullptr) == (body_b == nullptr)) return false;
  const dGeomID wheel_geom = body_a != nullptr ? a : b;
  const int wheel = wheelOf(wheel_geom);
  if (wheel < 0) return false;
  collideWheel(wheel, wheel_geom, body_a != nullptr ? b : a);
  return true;
}

// ODE's contacts, each with its feedback, the wheel as body 1 (the normal
// then points out of the ground, toward the wheel).
void NativeWheels::collideWheel(int wheel, dGeomID wheel_geom, dGeomID ground) {
  std::array<dContact, kMaxContactsPerPair> contact{};
  const int n = dCollide(wheel_geom, ground, kMaxContactsPerPair, &contact[0].geom, sizeof(dContact));
  for (int k = 0; k < n; ++k) {
    const PieceId piece = plugin().terrainGeoms().piece(ground, toEigen(contact[k].geom.pos));
    contact[k].surface.mode = dContactApprox1;
    contact[k].surface.mu = piece >= 0 ? mu_[terrain_.materialId(piece)] : sim::kBodyGroundFriction;
    // Stable addresses: ODE keeps a pointer to the feedback until the step.
    if (recorded_ == recorded_contacts_.size()) recorded_contacts_.emplace_back();
    RecordedContact& r = recorded_contacts_[recorded_++];
    r.wheel = wheel;
    r.geom = contact[k].geom;
    const dJointID joint = dJointCreateContact(world_, contacts_, &contact[k]);
    dJointAttach(joint, dGeomGetBody(wheel_geom), nullptr);
    dJointSetFeedback(joint, &r.feedback);
  }
}

void NativeWheels::stepped() {
  wheels().clear();
  for (std::size_t k = 0; k < recorded_; ++k) {
    const RecordedContact& r = recorded_contacts_[k];
    wheels()[r.wheel].add(toEigen(r.geom.pos), toEigen(r.geom.normal), r.geom.depth, toEigen(r.feedback.f1));
  }
  wheels().finish(engine());
  recorded_ = 0;  // the next step's contacts start over
}

}  // namespace wtc::ode
