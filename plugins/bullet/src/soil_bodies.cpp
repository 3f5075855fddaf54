// The plugin's bodies on soft soil (soil_bodies.hpp).
#include "soil_bodies.hpp"

#include <algorithm>
#include <mutex>
#include <shared_mutex>
#include <string>

#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include "plugin_state.hpp"
#include "wtc/base/error.hpp"

namespace wtc::bullet {
namespace {

[[noreturn]] void fail(const std::string& what) {
  throw InvalidInputError("wtc::bullet::Plugin::addSoilBody: " + what);
}

// Bullet's near callback is a plain function per dispatcher: it finds the
// plugin's soil bodies by the dispatcher it is called for.
std::shared_mutex& registryLock() {
  static std::shared_mutex lock;
  return lock;
}
std::vector<std::pair<const btCollisionDispatcher*, const SoilBodies*>>& registry() {
  static std::vector<std::pair<const btCollisionDispatcher*, const SoilBodies*>> owners;
  return owners;
}

void soilNearCallback(btBroadphasePair& pair, btCollisionDispatcher& dispatcher, const btDispatcherInfo& info) {
  const SoilBodies* owner = nullptr;
  {
    const std::shared_lock<std::shared_mutex> lock(registryLock());
    for (const auto& [d, bodies] : registry()) {
      if (d == &dispatcher) owner = bodies;
    }
  }
  if (owner == nullptr) {
    btCollisionDispatcher::defaultNearCallback(pair, dispatcher, info);
    return;
  }
  owner->previousNearCallback()(pair, dispatcher, info);
  owner->dropSoilContacts(pair);
}

}  // namespace

SoilBodies::~SoilBodies() {
  if (previous_ == nullptr) return;
  plugin_.dispatcher->setNearCallback(previous_);
  const std::unique_lock<std::shared_mutex> lock(registryLock());
  std::erase_if(registry(), [this](const auto& entry) { return entry.second == this; });
}

SoilBodyId SoilBodies::add(const SoilBody& spec) {
  if ((spec.body == nullptr) == (spec.multibody == nullptr)) {
    fail(spec.body == nullptr ? "no body: give a btRigidBody or a btMultiBody" : "a body and a multibody: give one");
  }
  btCollisionObject* collider = spec.body;
  double mass = 0.0;
  if (spec.body != nullptr) {
    mass = spec.body->getInvMass() > 0.0 ? 1.0 / spec.body->getInvMass() : 0.0;
  } else {
    if (spec.link < -1 || spec.link >= spec.multibody->getNumLinks()) {
      fail("link " + std::to_string(spec.link) + " is not the base (-1) or a link of the multibody (it has " +
           std::to_string(spec.multibody->getNumLinks()) + ")");
    }
    collider = spec.link < 0 ? spec.multibody->getBaseCollider() : spec.multibody->getLinkCollider(spec.link);
    if (collider == nullptr) fail("link " + std::to_string(spec.link) + " has no collider");
    mass = spec.link < 0 ? spec.multibody->getBaseMass() : spec.multibody->getLinkMass(spec.link);
  }
  if (!(mass > 0.0)) fail("a static body (no mass) is not moved by the soil");
  if (plugin_.wheelOf(collider) >= 0) fail("this body is a registered wheel: the soil meets it as one");
  if (of_collider_.count(collider) != 0) fail("this body is already a soil body");
  auto b = std::make_unique<Body>(Body{.rigid = spec.body,
                                       .multibody = spec.multibody,
                                       .link = spec.link,
                                       .collider = collider,
                                       .soil = BodyOnSoil(spec.hulls, mass, "wtc::bullet::Plugin::addSoilBody"),
                                       .last = {}});
  if (previous_ == nullptr) {
    previous_ = plugin_.dispatcher->getNearCallback();
    {
      const std::unique_lock<std::shared_mutex> lock(registryLock());
      registry().emplace_back(plugin_.dispatcher, this);
    }
    plugin_.dispatcher->setNearCallback(&soilNearCallback);
  }
  const auto id = static_cast<SoilBodyId>(bodies_.size());
  of_collider_.emplace(collider, id);
  bodies_.push_back(std::move(b));
  return id;
}

BodySoilMotion SoilBodies::motion(const Body& b) {
  BodySoilMotion m;
  if (b.rigid != nullptr) {
    const btTransform& t = b.rigid->getWorldTransform();
    m.pose.linear() = toEigen(t.getBasis());
    m.pose.translation() = toEigen(t.getOrigin());
    m.velocity = toEigen(b.rigid->getLinearVelocity());
    m.angular_velocity = toEigen(b.rigid->getAngularVelocity());
    return m;
  }
  const btMultiBody& mb = *b.multibody;
  if (b.link < 0) {
    m.pose.linear() = toEigen(btMatrix3x3(mb.getWorldToBaseRot().inverse()));
    m.pose.translation() = toEigen(mb.getBasePos());
    m.velocity = toEigen(mb.getBaseVel());
    m.angular_velocity = toEigen(mb.getBaseOmega());
    return m;
  }
  // The link's frame is its collider's; its velocities are in that frame.
  const btTransform& t = b.collider->getWorldTransform();
  const LinkVelocities& v = plugin_.linkVelocities(mb);
  m.pose.linear() = toEigen(t.getBasis());
  m.pose.translation() = toEigen(t.getOrigin());
  m.velocity = toEigen(t.getBasis() * v.linear[b.link + 1]);
  m.angular_velocity = toEigen(t.getBasis() * v.angular[b.link + 1]);
  return m;
}

void SoilBodies::step(double h) {
  const Terrain& terrain = plugin_.terrain.terrain();
  GroundMemory* memory = plugin_.ground_memory.regionCount() > 0 ? &plugin_.ground_memory : nullptr;
  for (const auto& b : bodies_) {
    b->last = b->soil.step(terrain, memory, motion(*b), h);
    if (b->last.nodes == 0) continue;
    const btVector3 force = toBt(b->last.force), torque = toBt(b->last.torque);
    if (b->rigid != nullptr) {
      b->rigid->applyCentralImpulse(force * h);
      b->rigid->applyTorqueImpulse(torque * h);
    } else if (b->link < 0) {
      b->multibody->addBaseForce(force);
      b->multibody->addBaseTorque(torque);
    } else {
      b->multibody->addLinkForce(b->link, force);
      b->multibody->addLinkTorque(b->link, torque);
    }
    b->link_force = force;
    b->link_torque = torque;
  }
}

void SoilBodies::stepped() {
  for (const auto& b : bodies_) {
#ifdef BT_USE_VIRTUAL_CLEARFORCES_AND_GRAVITY
    // As the wheels' wrench (PluginState::postTick): this Bullet clears
    // multibody forces once per stepSimulation, not per substep.
    if (b->multibody != nullptr && b->link < 0) {
      b->multibody->addBaseForce(-b->link_force);
      b->multibody->addBaseTorque(-b->link_torque);
    } else if (b->multibody != nullptr) {
      b->multibody->addLinkForce(b->link, -b->link_force);
      b->multibody->addLinkTorque(b->link, -b->link_torque);
    }
#endif
    b->link_force.setZero();
    b->link_torque.setZero();
  }
}

const BodySoilForces& SoilBodies::forces(SoilBodyId id) const {
  if (id < 0 || static_cast<std::size_t>(id) >= bodies_.size()) {
    throw InvalidInputError("wtc::bullet::Plugin::soilForces: soil body " + std::to_string(id) +
                            " is not registered (" + std::to_string(bodies_.size()) + " soil bodies)");
  }
  return bodies_[static_cast<std::size_t>(id)]->last;
}

void SoilBodies::dropSoilContacts(btBroadphasePair& pair) const {
  if (pair.m_algorithm == nullptr) return;
  const btCollisionObject* ground = &plugin_.terrain.object();
  const auto* a = static_cast<const btCollisionObject*>(pair.m_pProxy0->m_clientObject);
  const auto* b = static_cast<const btCollisionObject*>(pair.m_pProxy1->m_clientObject);
  const btCollisionObject* other = a == ground ? b : b == ground ? a : nullptr;
  if (other == nullptr || of_collider_.count(other) == 0) return;
  const Terrain& terrain = plugin_.terrain.terrain();
  btManifoldArray manifolds;
  pair.m_algorithm->getAllContactManifolds(manifolds);
  for (int m = 0; m < manifolds.size(); ++m) {
    btPersistentManifold& manifold = *manifolds[m];
    const bool ground_is_a = manifold.getBody0() == ground;
    for (int k = manifold.getNumContacts() - 1; k >= 0; --k) {
      const btManifoldPoint& p = manifold.getContactPoint(k);
      const Eigen::Vector3d on_ground = toEigen(ground_is_a ? p.getPositionWorldOnA() : p.getPositionWorldOnB());
      const PieceId piece =
          terrain.nearestPiece(on_ground, 0, static_cast<PieceId>(terrain.pieceCount()), kSoilContactReachM);
      if (piece >= 0 && terrain.material(piece).soil) manifold.removeContactPoint(k);
    }
  }
}

}  // namespace wtc::bullet
