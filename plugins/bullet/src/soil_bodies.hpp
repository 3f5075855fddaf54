#pragma once
// The plugin's bodies on soft soil (internal to wtc::bullet; design note in
// include/wtc/bullet/plugin.hpp, addSoilBody): each step, every body's
// soil force (wtc::BodyOnSoil) goes on it as the wheels' wrench does, and
// the dispatcher's near callback drops its rigid contacts on soil pieces.
#include <memory>
#include <unordered_map>
#include <vector>

#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <btBulletDynamicsCommon.h>

#include "wtc/bullet/plugin.hpp"
#include "wtc/tyre/body_soil.hpp"

namespace wtc::bullet {
namespace detail {
struct PluginState;
}  // namespace detail

/// How far from a rigid contact's point on the terrain its piece is looked
/// for (m): Bullet's points lie on the piece's surface within its margin
/// and the penetration, millimetres; 5 cm leaves room for a deep one.
inline constexpr double kSoilContactReachM = 0.05;

class SoilBodies {
 public:
  explicit SoilBodies(detail::PluginState& plugin) : plugin_(plugin) {}
  /// Restores the near callback it wrapped.
  ~SoilBodies();
  SoilBodies(const SoilBodies&) = delete;
  SoilBodies& operator=(const SoilBodies&) = delete;

  SoilBodyId add(const SoilBody& spec);
  /// Every body's soil force for a step of h, on the body (the pre-tick).
  void step(double h);
  /// Takes back a multibody's force of the substep (the post-tick; see
  /// PluginState::postTick).
  void stepped();
  const BodySoilForces& forces(SoilBodyId id) const;
  int count() const { return static_cast<int>(bodies_.size()); }

  /// The near callback's second half: drops the pair's manifold points on
  /// a soil piece when the pair is a soil body's against the terrain.
  void dropSoilContacts(btBroadphasePair& pair) const;
  btNearCallback previousNearCallback() const { return previous_; }

 private:
  struct Body {
    btRigidBody* rigid = nullptr;
    btMultiBody* multibody = nullptr;
    int link = -1;
    btCollisionObject* collider = nullptr;
    BodyOnSoil soil;
    BodySoilForces last;
    btVector3 link_force{0, 0, 0}, link_torque{0, 0, 0};  // multibody: what this substep added
  };
  BodySoilMotion motion(const Body& body);

  detail::PluginState& plugin_;
  std::vector<std::unique_ptr<Body>> bodies_;
  std::unordered_map<const btCollisionObject*, int> of_collider_;
  btNearCallback previous_ = nullptr;  // set once the near callback is wrapped
};

}  // namespace wtc::bullet
