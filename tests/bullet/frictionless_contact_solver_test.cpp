// FrictionlessContactSolver (wtc/bullet/frictionless_contact_solver.hpp) against Bullet's own
// btMultiBodyConstraintSolver: a frictionless contact's friction rows are
// not made, and the motion is bit for bit Bullet's, for a frictionless
// multibody and, in the same world, one with friction.
#include <gtest/gtest.h>

#include <array>
#include <memory>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <btBulletDynamicsCommon.h>

#include "wtc/bullet/frictionless_contact_solver.hpp"

namespace frictionless_contact_solver_test {

constexpr double kStepS = 1e-3;

// Two boxes, each a multibody with no links, dropped onto a static ground
// sliding sideways and spinning: box 0 frictionless (friction 0), box 1
// with friction 0.6 (the combined friction is the product: the ground's
// is 1). Tall boxes tip and touch on edges and corners: up to four
// points a manifold.
class Boxes {
 public:
  explicit Boxes(std::unique_ptr<btMultiBodyConstraintSolver> solver)
      : solver_(std::move(solver)), world_(&dispatcher_, &broadphase_, solver_.get(), &configuration_) {
    world_.setGravity(btVector3(0, 0, -9.81));
    world_.getSolverInfo().m_numIterations = 50;
    world_.getSolverInfo().m_leastSquaresResidualThreshold = 1e-6;
    world_.getSolverInfo().m_solverMode |= SOLVER_ENABLE_FRICTION_DIRECTION_CACHING;  // as WTC's plugin sets it
    ground_.setCollisionShape(&ground_shape_);
    ground_.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(0, 0, -0.5)));
    ground_.setFriction(1.0);
    world_.addCollisionObject(&ground_, btBroadphaseProxy::StaticFilter,
                              btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
    for (int i = 0; i < 2; ++i) {
      btVector3 inertia;
      box_shape_.calculateLocalInertia(2.0, inertia);
      bodies_[i] = std::make_unique<btMultiBody>(0, 2.0, inertia, false, false);
      bodies_[i]->setBasePos(btVector3(3.0 * i, 0, 0.35));
      bodies_[i]->setWorldToBaseRot(btQuaternion(btVector3(1, 1, 0).normalized(), 0.2));
      bodies_[i]->finalizeMultiDof();  // sizes the velocities
      bodies_[i]->setBaseVel(btVector3(1.5, 0.5, 0));
      bodies_[i]->setBaseOmega(btVector3(0.3, -2.0, 1.0));
      world_.addMultiBody(bodies_[i].get());
      colliders_[i] = std::make_unique<btMultiBodyLinkCollider>(bodies_[i].get(), -1);
      colliders_[i]->setCollisionShape(&box_shape_);
      colliders_[i]->setWorldTransform(
          btTransform(bodies_[i]->getWorldToBaseRot().inverse(), bodies_[i]->getBasePos()));
      colliders_[i]->setFriction(i == 0 ? 0.0 : 0.6);
      world_.addCollisionObject(colliders_[i].get(), btBroadphaseProxy::DefaultFilter, btBroadphaseProxy::AllFilter);
      bodies_[i]->setBaseCollider(colliders_[i].get());
    }
  }
  ~Boxes() {
    for (int i = 0; i < 2; ++i) {
      world_.removeCollisionObject(colliders_[i].get());
      world_.removeMultiBody(bodies_[i].get());
    }
    world_.removeCollisionObject(&ground_);
  }

  void step() { world_.stepSimulation(kStepS, 0, kStepS); }
  // The normal impulse (N s) the last step's contact points of box i
  // report, summed.
  double normalImpulse(int i) {
    double sum = 0.0;
    btDispatcher& d = *world_.getDispatcher();
    for (int k = 0; k < d.getNumManifolds(); ++k) {
      const btPersistentManifold& m = *d.getManifoldByIndexInternal(k);
      if (m.getBody0() != colliders_[i].get() && m.getBody1() != colliders_[i].get()) continue;
      for (int j = 0; j < m.getNumContacts(); ++j) sum += m.getContactPoint(j).m_appliedImpulse;
    }
    return sum;
  }
  const btMultiBody& body(int i) const { return *bodies_[i]; }

 private:
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_{&configuration_};
  btDbvtBroadphase broadphase_;
  std::unique_ptr<btMultiBodyConstraintSolver> solver_;
  btMultiBodyDynamicsWorld world_;
  btBoxShape ground_shape_{btVector3(10, 10, 0.5)};
  btCollisionObject ground_;
  btBoxShape box_shape_{btVector3(0.1, 0.15, 0.3)};
  std::array<std::unique_ptr<btMultiBody>, 2> bodies_;
  std::array<std::unique_ptr<btMultiBodyLinkCollider>, 2> colliders_;
};

TEST(FrictionlessContactSolverTest, SkipsOnlyFrictionlessRowsAndMovesBitForBitAsBullet) {
  Boxes bullets(std::make_unique<btMultiBodyConstraintSolver>());
  auto solver = std::make_unique<wtc::bullet::FrictionlessContactSolver>();
  const wtc::bullet::FrictionlessContactSolver& ours_solver = *solver;
  Boxes ours(std::move(solver));
  int skipped = 0;
  for (int n = 0; n < 2000; ++n) {
    bullets.step();
    ours.step();
    skipped += ours_solver.skippedFrictionRows();
    for (int i = 0; i < 2; ++i) {
      for (int k = 0; k < 3; ++k) {
        ASSERT_EQ(ours.body(i).getBasePos()[k], bullets.body(i).getBasePos()[k]) << "step " << n << " box " << i;
        ASSERT_EQ(ours.body(i).getBaseVel()[k], bullets.body(i).getBaseVel()[k]) << "step " << n << " box " << i;
        ASSERT_EQ(ours.body(i).getBaseOmega()[k], bullets.body(i).getBaseOmega()[k]) << "step " << n << " box " << i;
      }
    }
  }
  // The frictionless box had its contacts' friction rows left out (two a
  // point); the one with friction kept its: it stopped, the other slides on.
  EXPECT_GT(skipped, 600);
  EXPECT_LT(ours.body(1).getBaseVel().length(), 0.05);
  EXPECT_GT(ours.body(0).getBaseVel().length(), 0.5);
}

// With its warm start, the frictionless box's normal rows start from the
// last step's impulses: the solver does fewer sweeps to the same residual,
// the motion stays Bullet's within what the residual allows, and the
// impulse the points report is the whole of it (the box's weight at rest),
// the start included.
TEST(FrictionlessContactSolverTest, WarmStartedRowsReachBulletsMotionAndReportTheWholeImpulse) {
  Boxes bullets(std::make_unique<btMultiBodyConstraintSolver>());
  auto solver = std::make_unique<wtc::bullet::FrictionlessContactSolver>(true);
  const wtc::bullet::FrictionlessContactSolver& ours_solver = *solver;
  Boxes ours(std::move(solver));
  int warm = 0;
  for (int n = 0; n < 2000; ++n) {
    bullets.step();
    ours.step();
    warm += ours_solver.warmStartedRows();
  }
  EXPECT_GT(warm, 1000);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(ours.body(0).getBasePos()[k], bullets.body(0).getBasePos()[k], 1e-3) << k;
    EXPECT_NEAR(ours.body(0).getBaseVel()[k], bullets.body(0).getBaseVel()[k], 1e-3) << k;
  }
  EXPECT_NEAR(ours.normalImpulse(0), 2.0 * 9.81 * kStepS, 1e-3 * 2.0 * 9.81 * kStepS);
}

}  // namespace frictionless_contact_solver_test
