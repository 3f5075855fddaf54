#pragma once
// The collision algorithm the plugin registers for WheelShape against every
// shape type (internal to wtc::bullet). Wheel against the WTC terrain: the
// contacts WTC found in this step's pre-tick go into the pair's manifold
// (constraint mode), or none at all (force mode: the forces are applied in
// the pre-tick). Anything else: Bullet's own algorithm for the wheel's
// original shape.
#include <btBulletCollisionCommon.h>

#include "wtc/adapter/solver_contact.hpp"
#include "wtc/bullet/plugin.hpp"

namespace wtc::bullet {

struct Wheel;

class WheelTerrainAlgorithm : public btCollisionAlgorithm {
 public:
  class CreateFunc : public btCollisionAlgorithmCreateFunc {
   public:
    explicit CreateFunc(detail::PluginState& state) : state_(state) {}
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                   const btCollisionObjectWrapper* body0,
                                                   const btCollisionObjectWrapper* body1) override;

   private:
    detail::PluginState& state_;
  };

  WheelTerrainAlgorithm(const btCollisionAlgorithmConstructionInfo& info, detail::PluginState& state);
  ~WheelTerrainAlgorithm() override;

  void processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo& dispatch_info, btManifoldResult* result) override;
  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override {
    return 1;
  }
  void getAllContactManifolds(btManifoldArray& manifolds) override;

 private:
  void writeWtcContacts(int wheel, bool wheel_is_body0, const btCollisionObjectWrapper* body0,
                        const btCollisionObjectWrapper* body1, const btDispatcherInfo& dispatch_info,
                        btManifoldResult* result);
  void setSpring(btManifoldPoint& point, const SolverContact& contact, double step_seconds) const;
  void setTreadRows(btManifoldPoint& point, const SolverContact& contact, bool wheel_is_body0,
                    double step_seconds) const;
  static SolverContact mergedContact(const SolverContact& earlier, const SolverContact& later);
  void writeCapContacts(const Wheel& wheel, const btCollisionObjectWrapper* body0,
                        const btCollisionObjectWrapper* body1, const btDispatcherInfo& dispatch_info,
                        btManifoldResult* result);
  void delegate(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                const btDispatcherInfo& dispatch_info, btManifoldResult* result);
  void collideOriginals(btCollisionAlgorithm*& child, btPersistentManifold* shared,
                        const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo& dispatch_info, btManifoldResult* result,
                        const btCollisionObject* replaced = nullptr, const btCollisionShape* replacement = nullptr);

  detail::PluginState& state_;
  btPersistentManifold* manifold_ = nullptr;
  btCollisionAlgorithm* child_ = nullptr;      // other pairs: Bullet's algorithm for the originals
  btCollisionAlgorithm* cap_child_ = nullptr;  // wheel-terrain caps: the same, into manifold_
};

}  // namespace wtc::bullet
