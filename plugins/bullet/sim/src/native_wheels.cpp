#include "native_wheels.hpp"

#include <mutex>

#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include "src/conversions.hpp"

namespace wtc::bullet {
namespace {

// Bullet lets a collision object flagged CF_CUSTOM_MATERIAL_CALLBACK set
// the friction of each new contact point through one process-wide
// callback; only the native wheels' colliders carry the flag. The ground's
// wrapper is the child the wheel met: a hull, or a compact field's triangle
// (TerrainObject::pieceOf).
bool nativeWheelContactAdded(btManifoldPoint& point, const btCollisionObjectWrapper* a, int, int,
                             const btCollisionObjectWrapper* b, int, int) {
  const bool a_is_wheel =
      (a->getCollisionObject()->getCollisionFlags() & btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK) != 0;
  const btCollisionObjectWrapper* wheel = a_is_wheel ? a : b;
  const btCollisionObjectWrapper* ground = a_is_wheel ? b : a;
  const auto* g = static_cast<const NativeWheelGround*>(wheel->getCollisionObject()->getUserPointer());
  if (g == nullptr || ground->getCollisionObject() != &g->terrain->object()) return false;
  const Terrain& pieces = g->terrain->terrain();
  const PieceId piece = g->terrain->pieceOf(*ground);
  if (piece < 0 || piece >= static_cast<PieceId>(pieces.pieceCount())) return false;
  point.m_combinedFriction = g->mu[pieces.materialId(piece)];
  return true;
}

}  // namespace

NativeWheels::NativeWheels(const sim::Engine& engine, Plugin& plugin, btMultiBodyDynamicsWorld& world,
                           const Terrain& terrain, std::span<const WheelLink> links, sim::NativeWheelShape shape)
    : sim::NativeWheels<Plugin>(engine, plugin, shape), world_(world) {
  static std::once_flag installed;
  std::call_once(installed, [] { gContactAddedCallback = nativeWheelContactAdded; });
  ground_ = {.terrain = &plugin.terrainShapes(), .mu = sim::nativeWheelFrictions(terrain)};
  for (const WheelLink& link : links) {
    btMultiBodyLinkCollider& collider = *link.collider;
    collider.setCollisionFlags(collider.getCollisionFlags() | btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK);
    collider.setUserPointer(&ground_);
    colliders_.push_back(&collider);
  }
}

// The impulses Bullet's solver wrote back to each wheel-terrain point
// (normal, and each friction direction it used) over h, on the wheel.
void NativeWheels::stepped() {
  wheels().clear();
  const double h = engine().settings().step_seconds;
  const bool second = (world_.getSolverInfo().m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) != 0;
  const btCollisionObject* ground = &plugin().terrainObject();
  btDispatcher& dispatcher = *world_.getDispatcher();
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(m);
    const bool wheel_is_a = manifold.getBody1() == ground;
    if (!wheel_is_a && manifold.getBody0() != ground) continue;
    const btCollisionObject* other = wheel_is_a ? manifold.getBody0() : manifold.getBody1();
    const auto* collider = btMultiBodyLinkCollider::upcast(other);
    if (collider == nullptr || collider->m_link < 0) continue;
    const int wheel = wheelOf(collider);
    if (wheel < 0) continue;
    for (int k = 0; k < manifold.getNumContacts(); ++k) {
      const btManifoldPoint& p = manifold.getContactPoint(k);
      if (p.getDistance() > 0.0 && p.m_appliedImpulse == 0.0) continue;  // kept, not touching
      btVector3 impulse_on_a =
          p.m_normalWorldOnB * p.m_appliedImpulse + p.m_lateralFrictionDir1 * p.m_appliedImpulseLateral1;
      if (second) impulse_on_a += p.m_lateralFrictionDir2 * p.m_appliedImpulseLateral2;
      const btVector3 normal = wheel_is_a ? p.m_normalWorldOnB : -p.m_normalWorldOnB;  // out of the ground
      const btVector3 point = wheel_is_a ? p.getPositionWorldOnB() : p.getPositionWorldOnA();
      wheels()[wheel].add(toEigen(point), toEigen(normal), -p.getDistance(),
                          toEigen(wheel_is_a ? impulse_on_a : -impulse_on_a) / h);
    }
  }
  wheels().finish(engine());
}

int NativeWheels::wheelOf(const btMultiBodyLinkCollider* collider) const {
  for (std::size_t k = 0; k < colliders_.size(); ++k) {
    if (colliders_[k] == collider) return static_cast<int>(k);
  }
  return -1;
}

}  // namespace wtc::bullet
