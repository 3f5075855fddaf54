// The ODE plugin on a vehicle's axle: a body carrying two wheel bodies on
// hinge joints (the joints carry the bearing loads, the motors drive through
// them, the axle is each wheel's hub), 42 kg in all so that each wheel
// carries 21 kg like the robot's; every contact mode. The Bullet plugin's
// multibody axle scenes.
#include <cctype>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "ode_fixture.hpp"
#include "wtc/tyre/contact_mode.hpp"

namespace wtc {
namespace {

using testing::kGravityMps2;
using testing::OdeWorld;

constexpr double kRadius = 0.19;                      // r_f (m)
constexpr double kHalfTrack = 0.28;                   // wheel centres at y = +-0.28 m (the robot's track)
constexpr double kWheelMass = 3.7, kAxleMass = 34.6;  // (kg): 21 kg per wheel in all
constexpr double kTotalMass = kAxleMass + 2 * kWheelMass;
constexpr double kStiffness = 1e5;     // c (N/m)
constexpr double kStepSeconds = 1e-3;  // (s)

// The axle body (kept level by an angular motor: the rest of its vehicle)
// and its two wheels on hinges about y.
struct Axle {
  Axle(OdeWorld& w, double height) {
    body = dBodyCreate(w.world);
    dMass m;
    dMassSetBoxTotal(&m, kAxleMass, 0.2, 2 * kHalfTrack, 0.2);
    dBodySetMass(body, &m);
    dBodySetPosition(body, 0, 0, height);
    testing::lockRotation(w, body);
    for (int i = 0; i < 2; ++i) {
      const double y = i == 0 ? kHalfTrack : -kHalfTrack;
      const testing::OdeWheel wheel = w.addWheelBody(kWheelMass, {0, y, height});
      wheels[i] = wheel.body;
      // Body 1 the wheel: dJointAddHingeTorque turns it by +tau about the
      // axis and the axle by -tau.
      hinges[i] = dJointCreateHinge(w.world, nullptr);
      dJointAttach(hinges[i], wheel.body, body);
      dJointSetHingeAnchor(hinges[i], 0, y, height);
      dJointSetHingeAxis(hinges[i], 0, 1, 0);
      ode::RigidWheel spec;
      spec.body = wheel.body;
      spec.geom = wheel.geom;
      spec.description.inertia = {kWheelMass, 0.5 * kWheelMass * kRadius * kRadius};
      w.plugin->addWheel(spec);
    }
  }
  dBodyID body = nullptr;
  dBodyID wheels[2] = {nullptr, nullptr};
  dJointID hinges[2] = {nullptr, nullptr};
};

class OdeAxleTest : public ::testing::TestWithParam<ContactMode> {};

// Case: dropped 1 cm, the axle settles with each wheel at 21 g / c (2 %).
TEST_P(OdeAxleTest, AxleSettlesAtItsWeightOverStiffness) {
  const Terrain ground = testing::flatGround();
  OdeWorld w(ground, GetParam());
  const Axle axle(w, kRadius + 0.01);
  for (int k = 0; k < 3000; ++k) w.step(kStepSeconds);
  const double expected = 0.5 * kTotalMass * kGravityMps2 / kStiffness;
  EXPECT_NEAR(kRadius - testing::position(axle.body).z(), expected, 0.02 * expected);
  EXPECT_EQ(w.plugin->forces(0).contacts.size(), 1u);
  EXPECT_EQ(w.plugin->forces(1).contacts.size(), 1u);
}

// Case: hinge torques drive the axle; it accelerates as rolling without
// slip predicts, a = (2 tau / r - f_r M g r_0 / r) / (M + 2 I / r^2), within
// 5 %, over 1 s.
TEST_P(OdeAxleTest, DrivenAxleAcceleratesAsRollingPredicts) {
  const Terrain ground = testing::flatGround();
  OdeWorld w(ground, GetParam());
  const Axle axle(w, kRadius - 0.5 * kTotalMass * kGravityMps2 / kStiffness);
  const double torque = 5.0;  // per wheel (N m)
  for (int k = 0; k < 500; ++k) w.step(kStepSeconds);
  const double v0 = testing::velocity(axle.body).x();
  for (int k = 0; k < 1000; ++k) {
    for (const dJointID hinge : axle.hinges) dJointAddHingeTorque(hinge, torque);
    w.step(kStepSeconds);
  }
  const double acceleration = testing::velocity(axle.body).x() - v0;
  const double inertia = 0.5 * kWheelMass * kRadius * kRadius;
  const double expected = (2 * torque / kRadius - 0.018 * kTotalMass * kGravityMps2 * 0.97) /
                          (kTotalMass + 2 * inertia / (kRadius * kRadius));
  RecordProperty("acceleration_error", std::to_string(acceleration / expected - 1));
  EXPECT_NEAR(acceleration, expected, 0.05 * expected);
}

INSTANTIATE_TEST_SUITE_P(Modes, OdeAxleTest,
                         ::testing::Values(ContactMode::kForce, ContactMode::kConstraint, ContactMode::kImplicit),
                         [](const auto& info) {
                           std::string name(contactModeName(info.param));
                           name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
                           return name;
                         });

}  // namespace
}  // namespace wtc
