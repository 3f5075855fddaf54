#pragma once
// A convex body against a tile of a compact heightfield (internal to
// wtc::bullet): Bullet's convex-concave collision with one more test before
// each triangle's GJK.
//
// Bullet hands a body every triangle of the tile inside the body's box in
// the tile's frame, and runs GJK on each one that its plane does not
// already separate. A tilted body lying across a field's edge (the robot's
// arm on the sampled ledge) has a box far larger than itself: on a 1 cm
// field 9 in 10 of those GJK runs found nothing, and they were 30 % of the
// whole step (callgrind, docs/terrain.md). The test here is the body's own
// box in its own frame (three separating axes more): a triangle beyond it by
// more than the contact breaking threshold is farther from the body than
// any contact Bullet keeps (btManifoldResult::addContactPoint drops a point
// deeper than that), so leaving it out changes no contact. Every other
// triangle goes through what Bullet does, in Bullet's order. The tile's cells
// are walked as Bullet walks them (FieldTile::walkTriangles), less the rows'
// cells and the cells that the same box leaves out whole.
#include <BulletCollision/CollisionDispatch/btActivatingCollisionAlgorithm.h>
#include <btBulletCollisionCommon.h>

namespace wtc::bullet::detail {

class FieldBodyAlgorithm : public btActivatingCollisionAlgorithm {
 public:
  // Creates FieldBodyAlgorithm when the concave side is a FieldTile, and
  // the `fallback`'s algorithm (Bullet's own) for any other concave shape.
  class CreateFunc : public btCollisionAlgorithmCreateFunc {
   public:
    CreateFunc(btCollisionAlgorithmCreateFunc* fallback, bool swapped) : fallback_(fallback) { m_swapped = swapped; }
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                   const btCollisionObjectWrapper* body0,
                                                   const btCollisionObjectWrapper* body1) override;

   private:
    btCollisionAlgorithmCreateFunc* fallback_;
  };

  // Whether the plugin registers this algorithm for a body of `shape_type`
  // against a heightfield: every convex type but a WTC wheel's.
  static bool serves(int shape_type);

  FieldBodyAlgorithm(const btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper* body0,
                     const btCollisionObjectWrapper* body1, bool swapped);
  ~FieldBodyAlgorithm() override;

  void processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo& dispatch_info, btManifoldResult* result) override;
  // No continuous collision against a field (the bodies are not CCD bodies).
  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override {
    return 1;
  }
  void getAllContactManifolds(btManifoldArray& manifolds) override;

 private:
  btPersistentManifold* manifold_;
  bool swapped_;
};

}  // namespace wtc::bullet::detail
