// Validation scenes of the Bullet plugin (issue: Bullet plugin, part 4),
// each against its analytic or expected value, in both contact modes.
#include "wtc/bullet/plugin.hpp"

#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "bullet_fixture.hpp"

namespace wtc {
namespace {

using testing::BulletWorld;
using testing::flatGround;
using testing::kGravityMps2;
using testing::WheelBody;

class BulletModeTest : public ::testing::TestWithParam<ContactMode> {};

std::string modeName(const ::testing::TestParamInfo<ContactMode>& info) {
  return info.param == ContactMode::kForce ? "Force" : "Constraint";
}

// Case: a wheel (and a loaded wheel) dropped on flat ground settles at
// m g / c within 2 %.
TEST_P(BulletModeTest, DroppedWheelSettlesAtWeightOverStiffness) {
  const Terrain ground = flatGround();
  for (const double mass : {3.7, 21.0}) {
    BulletWorld w(ground, GetParam());
    WheelBody& wheel = w.addWheelBody(mass, btVector3(0, 0, 0.19 + 0.01));
    const bullet::WheelId id = testing::addWheel(w, wheel);
    for (int k = 0; k < 3000; ++k) w.world.stepSimulation(1e-3, 1, 1e-3);
    const double deflection = 0.19 - wheel.body->getCenterOfMassPosition().z();
    EXPECT_NEAR(deflection, mass * kGravityMps2 / 1e5, 0.02 * mass * kGravityMps2 / 1e5) << "m = " << mass;
    EXPECT_EQ(w.plugin->forces(id).contacts.size(), 1u);
  }
}

INSTANTIATE_TEST_SUITE_P(Modes, BulletModeTest, ::testing::Values(ContactMode::kForce, ContactMode::kConstraint),
                         modeName);

}  // namespace
}  // namespace wtc
