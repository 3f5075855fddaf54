// The Bullet plugin in a btMultiBodyDynamicsWorld: an axle (a floating base)
// with two wheel links on revolute joints, 42 kg in all, so each wheel
// carries 21 kg like the robot's; every contact mode.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>
#include <string>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "bullet_fixture.hpp"
#include "wtc/base/error.hpp"
#include "wtc/bullet/contact_solver.hpp"

namespace wtc {
namespace {

constexpr double kRadius = 0.19, kWidth = 0.12;       // r_f, tread (m)
constexpr double kHalfTrack = 0.28;                   // wheel centres at y = +-0.28 m (the robot's track)
constexpr double kWheelMass = 3.7, kBaseMass = 34.6;  // (kg): 21 kg per wheel in all
constexpr double kStiffness = 1e5;                    // c (N/m)

struct Axle {
  Axle(const Terrain& terrain, ContactMode mode, double height) {
    world.setGravity(btVector3(0, 0, -testing::kGravityMps2));
    const btVector3 wheel_inertia(0.25 * kWheelMass * kRadius * kRadius + kWheelMass * kWidth * kWidth / 12,
                                  0.5 * kWheelMass * kRadius * kRadius,
                                  0.25 * kWheelMass * kRadius * kRadius + kWheelMass * kWidth * kWidth / 12);
    multibody = std::make_unique<btMultiBody>(2, kBaseMass, btVector3(1.0, 0.1, 1.0), false, false);
    multibody->setBasePos(btVector3(0, 0, height));
    for (int i = 0; i < 2; ++i) {
      const btVector3 offset(0, i == 0 ? kHalfTrack : -kHalfTrack, 0);
      multibody->setupRevolute(i, kWheelMass, wheel_inertia, -1, btQuaternion::getIdentity(), btVector3(0, 1, 0),
                               offset, btVector3(0, 0, 0), true);
    }
    multibody->finalizeMultiDof();
    world.addMultiBody(multibody.get());
    for (int i = 0; i < 2; ++i) {
      colliders[i] = std::make_unique<btMultiBodyLinkCollider>(multibody.get(), i);
      colliders[i]->setCollisionShape(&shape);
      colliders[i]->setWorldTransform(
          btTransform(btQuaternion::getIdentity(), btVector3(0, i == 0 ? kHalfTrack : -kHalfTrack, height)));
      // A dynamic link's filters (btDiscreteDynamicsWorld's default for a plain
      // collision object is the static group, which never meets the terrain).
      world.addCollisionObject(colliders[i].get(), btBroadphaseProxy::DefaultFilter, btBroadphaseProxy::AllFilter);
      multibody->getLink(i).m_collider = colliders[i].get();
    }
    plugin = std::make_unique<bullet::Plugin>(world, terrain, mode);
    for (int i = 0; i < 2; ++i) {
      bullet::MultiBodyWheel spec;
      spec.multibody = multibody.get();
      spec.link = i;
      spec.description.inertia = {kWheelMass, wheel_inertia.y()};
      plugin->addWheel(spec);
    }
  }
  ~Axle() {
    plugin.reset();
    for (auto& c : colliders) world.removeCollisionObject(c.get());
    world.removeMultiBody(multibody.get());
  }
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  bullet::ContactSolver solver;  // Bullet's, with implicit mode's bounds (identical in the other modes)
  btMultiBodyDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
  btCylinderShape shape{btVector3(kRadius, 0.5 * kWidth, kRadius)};
  std::unique_ptr<btMultiBody> multibody;
  std::unique_ptr<btMultiBodyLinkCollider> colliders[2];
  std::unique_ptr<bullet::Plugin> plugin;
};

class BulletMultiBodyTest : public ::testing::TestWithParam<ContactMode> {};

// Case: dropped 1 cm, the axle settles with each wheel at 21 g / c.
TEST_P(BulletMultiBodyTest, AxleSettlesAtItsWeightOverStiffness) {
  const Terrain ground = testing::flatGround();
  Axle axle(ground, GetParam(), kRadius + 0.01);
  for (int k = 0; k < 3000; ++k) axle.world.stepSimulation(1e-3, 1, 1e-3);
  const double expected = 0.5 * (kBaseMass + 2 * kWheelMass) * testing::kGravityMps2 / kStiffness;
  EXPECT_NEAR(kRadius - axle.multibody->getBasePos().z(), expected, 0.02 * expected);
  EXPECT_EQ(axle.plugin->forces(0).contacts.size(), 1u);
  EXPECT_EQ(axle.plugin->forces(1).contacts.size(), 1u);
}

// Case: joint torques drive the axle; it accelerates as rolling without
// slip predicts, a = (2 tau / r - f_r M g r_0 / r) / (M + 2 I / r^2),
// within 5 %, over 1 s, with 4 substeps per stepSimulation.
TEST_P(BulletMultiBodyTest, DrivenAxleAcceleratesAsRollingPredicts) {
  const Terrain ground = testing::flatGround();
  const double total = kBaseMass + 2 * kWheelMass;
  Axle axle(ground, GetParam(), kRadius - 0.5 * total * testing::kGravityMps2 / kStiffness);
  const double torque = 5.0;  // per wheel (N m)
  for (int k = 0; k < 125; ++k) axle.world.stepSimulation(4e-3, 4, 1e-3);
  const double v0 = axle.multibody->getBaseVel().x();
  // The motor torque for every substep. Bullet may keep joint torques across
  // substeps (Debian's does), so set it rather than add it again.
  axle.plugin->setPreTickCallback([&](double) {
    for (int i = 0; i < 2; ++i) axle.multibody->addJointTorque(i, torque - axle.multibody->getJointTorque(i));
  });
  for (int k = 0; k < 250; ++k) axle.world.stepSimulation(4e-3, 4, 1e-3);
  const double acceleration = axle.multibody->getBaseVel().x() - v0;
  const double inertia = 0.5 * kWheelMass * kRadius * kRadius;
  const double expected = (2 * torque / kRadius - 0.018 * total * testing::kGravityMps2 * 0.97) /
                          (total + 2 * inertia / (kRadius * kRadius));
  EXPECT_NEAR(acceleration, expected, 0.05 * expected);
}

// Case: the wheels' drives solved in closed form through the post-wheels
// callback (docs/bullet-plugin.md, Wheel drives), 4 substeps per
// stepSimulation. At every substep the callback comes after the wheels:
// axleTorque is the tyre's torque of that substep about the axle, with
// nothing of the last substep's drive torque left in it (addAxleTorque's is
// taken back after its substep); the drives bring the wheels from rest to
// their rate, at the cap first, and hold it against the tyres.
TEST(BulletMultiBodyDriveTest, WheelDrivesSolvedAfterTheWheelsHoldTheirRate) {
  constexpr double kRateRadps = 6.0, kCapNm = 20.0;
  constexpr double kTorqueTolerance = 1e-12;  // N m: the same sum, read back
  constexpr double kRateTolerance = 5e-3;  // rad/s (0.1 % of the rate): the carrier's share the closed form leaves out
  constexpr double kCarrierPitchInertia = 10.0;  // kg m^2
  const Terrain ground = testing::flatGround();
  const double total = kBaseMass + 2 * kWheelMass;
  Axle axle(ground, ContactMode::kForce, kRadius - 0.5 * total * testing::kGravityMps2 / kStiffness);
  // A carrier that resists pitching as a chassis does: the closed form
  // leaves out the carrier's share of the spin, I / I_carrier (here 0.7 %;
  // on the axle's own 0.1 kg m^2 the drives' reaction would tumble it).
  axle.multibody->setBaseInertia(btVector3(1.0, kCarrierPitchInertia, 1.0));
  const double inertia = 0.5 * kWheelMass * kRadius * kRadius;
  int calls = 0, capped = 0;
  double worst = 0.0, peak_tyre = 0.0;
  axle.plugin->setPostWheelsCallback([&](double h) {
    ++calls;
    for (int i = 0; i < 2; ++i) {
      const btVector3 axle_W = axle.colliders[i]->getWorldTransform().getBasis() * btVector3(0, 1, 0);
      const Eigen::Vector3d& t = axle.plugin->forces(i).torque;  // about the centre, on the axle
      const double tyre = axle_W.x() * t.x() + axle_W.y() * t.y() + axle_W.z() * t.z();
      worst = std::max(worst, std::abs(axle.plugin->axleTorque(i) - tyre));
      peak_tyre = std::max(peak_tyre, std::abs(tyre));
      const double wanted = inertia * (kRateRadps - axle.multibody->getJointVel(i)) / h - tyre;
      const double torque = std::clamp(wanted, -kCapNm, kCapNm);
      if (torque != wanted) ++capped;
      axle.plugin->addAxleTorque(i, torque);
    }
  });
  for (int k = 0; k < 250; ++k) axle.world.stepSimulation(4e-3, 4, 1e-3);
  EXPECT_EQ(calls, 1000);
  EXPECT_LT(worst, kTorqueTolerance);
  EXPECT_GT(peak_tyre, 1.0) << "the tyres must load the wheels (N m)";
  EXPECT_GT(capped, 0) << "the drives must start at their cap";
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(axle.multibody->getJointVel(i), kRateRadps, kRateTolerance);
  EXPECT_GT(axle.multibody->getBaseVel().x(), 0.5 * kRateRadps * kRadius) << "the axle rolls";
}

// Case: the drive's torque belongs to a wheel that is a link on a revolute
// joint; anything else is refused by name.
TEST(BulletMultiBodyDriveTest, AxleTorqueRefusesAWheelItDoesNotHave) {
  const Terrain ground = testing::flatGround();
  Axle axle(ground, ContactMode::kForce, kRadius);
  EXPECT_THAT(
      [&] { (void)axle.plugin->axleTorque(2); },
      ::testing::ThrowsMessage<InvalidInputError>(::testing::HasSubstr("wheel 2 is not registered (2 wheels)")));
  EXPECT_THAT([&] { axle.plugin->addAxleTorque(-1, 1.0); },
              ::testing::ThrowsMessage<InvalidInputError>(::testing::HasSubstr("wheel -1 is not registered")));
  testing::BulletWorld rigid(ground, ContactMode::kForce);
  const bullet::WheelId id = testing::addWheel(rigid, rigid.addWheelBody(kWheelMass, btVector3(0, 0, kRadius)));
  EXPECT_THAT([&] { (void)rigid.plugin->axleTorque(id); },
              ::testing::ThrowsMessage<InvalidInputError>(::testing::HasSubstr("wheel 0 is a rigid body")));
}

INSTANTIATE_TEST_SUITE_P(Modes, BulletMultiBodyTest,
                         ::testing::Values(ContactMode::kForce, ContactMode::kConstraint, ContactMode::kImplicit),
                         [](const auto& info) {
                           std::string name(contactModeName(info.param));
                           name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
                           return name;
                         });

}  // namespace
}  // namespace wtc
