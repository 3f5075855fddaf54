// A user's own btRigidBody on soft soil through the Bullet plugin
// (Plugin::addSoilBody; wtc/tyre/body_soil.hpp): registered, a box dropped
// on sand settles at Bekker's plate sinkage (its rigid contacts with the
// sand dropped by the wrapped near callback); not registered, the sand is
// hard ground for it. Registration refuses what it cannot serve, and the
// plugin gives the dispatcher its near callback back.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include <BulletDynamics/Featherstone/btMultiBody.h>

#include "bullet_fixture.hpp"
#include "expect_refused.hpp"
#include "soil_plate.hpp"
#include "wtc/base/error.hpp"

namespace wtc::testing {
namespace bullet_soil_body_test {

constexpr double kMassKg = 150.0, kStepS = 4e-4;
const btVector3 kHalfM(0.25, 0.15, 0.05);  // a 0.5 m x 0.3 m belly, its edges on the 2 cm cells' edges

struct Box {
  explicit Box(btDiscreteDynamicsWorld& w) : world(w), shape(kHalfM) {
    btVector3 inertia;
    shape.calculateLocalInertia(kMassKg, inertia);
    motion = btDefaultMotionState(btTransform(btQuaternion::getIdentity(), btVector3(0, 0, kHalfM.z() + 0.01)));
    body = std::make_unique<btRigidBody>(kMassKg, &motion, &shape, inertia);
    world.addRigidBody(body.get());
  }
  ~Box() { world.removeRigidBody(body.get()); }
  btDiscreteDynamicsWorld& world;
  btBoxShape shape;
  btDefaultMotionState motion;
  std::unique_ptr<btRigidBody> body;
};

std::vector<ConvexPolyhedron> boxHull() {
  const Eigen::Vector3d half(kHalfM.x(), kHalfM.y(), kHalfM.z());
  return {ConvexPolyhedron::box(-half, half)};
}

double settledBottom(bool registered) {
  const Terrain sand = soilSlab("toyoura_sand", 4.0, 4.0);
  BulletWorld w(sand, ContactMode::kForce);
  Box box(w.world);
  if (registered) w.plugin->addSoilBody({.body = box.body.get(), .hulls = boxHull()});
  for (int k = 0; k < 3750; ++k) w.world.stepSimulation(kStepS, 0, kStepS);
  return box.body->getWorldTransform().getOrigin().z() - kHalfM.z();
}

TEST(BulletSoilBodyTest, ARegisteredBoxSettlesAtBekkersPlateSinkageAnOtherOnTheSurface) {
  const double bekker = bekkerPlateSinkage(*namedSoil("toyoura_sand"), kMassKg * kGravityMps2, 0.5, 0.3);
  EXPECT_NEAR(-settledBottom(true), bekker, 0.01 * bekker);
  // Bullet's own contact: its 1 mm terrain margin and its slop.
  EXPECT_NEAR(settledBottom(false), 0.0, 2e-3);
}

TEST(BulletSoilBodyTest, RegistrationRefusesWhatItCannotServeAndTheNearCallbackIsGivenBack) {
  const Terrain sand = soilSlab("toyoura_sand", 4.0, 4.0);
  BulletWorld w(sand, ContactMode::kForce);
  Box box(w.world);
  const auto refused = [&](const bullet::SoilBody& spec, const std::string& words) {
    expectRefused([&] { w.plugin->addSoilBody(spec); }, {words, "addSoilBody"});
  };
  refused({.hulls = boxHull()}, "no body");
  refused({.body = box.body.get(), .hulls = {}}, "at least one convex hull");
  btMultiBody multibody(0, 1.0, btVector3(1, 1, 1), false, false);
  refused({.body = box.body.get(), .multibody = &multibody, .hulls = boxHull()}, "give one");
  refused({.multibody = &multibody, .link = 3, .hulls = boxHull()}, "link 3");
  refused({.multibody = &multibody, .link = -1, .hulls = boxHull()}, "no collider");
  btBoxShape shape(kHalfM);
  btRigidBody fixed(0.0, nullptr, &shape);
  refused({.body = &fixed, .hulls = boxHull()}, "static body");
  BulletWheel& wheel = w.addWheelBody(10.0, btVector3(2, 0, 0.2));
  addWheel(w, wheel);
  refused({.body = wheel.body.get(), .hulls = boxHull()}, "registered wheel");
  EXPECT_EQ(w.plugin->addSoilBody({.body = box.body.get(), .hulls = boxHull()}), 0);
  refused({.body = box.body.get(), .hulls = boxHull()}, "already a soil body");
  EXPECT_NE(w.dispatcher.getNearCallback(), &btCollisionDispatcher::defaultNearCallback);
  EXPECT_THROW(w.plugin->soilForces(1), InvalidInputError);
  w.plugin.reset();
  EXPECT_EQ(w.dispatcher.getNearCallback(), &btCollisionDispatcher::defaultNearCallback);
}

}  // namespace bullet_soil_body_test
}  // namespace wtc::testing
