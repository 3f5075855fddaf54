// WTC wheels in a user's own MuJoCo model (wtc::mujoco, force mode): a
// wheel on a vertical slider settles at the static deflection W / c; with
// no wheels the plugin's step is mj_step to the bit; the user's own
// xfrc_applied on a wheel body survives the step to the bit; and what the
// adapter cannot serve is refused with its reason.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

#include <mujoco/mujoco.h>

#include "expect_refused.hpp"
#include "mujoco_fixtures.hpp"
#include "wheel_sim.hpp"
#include "wtc/mujoco/plugin.hpp"

namespace wtc::testing {
namespace mujoco_plugin_test {

using namespace slider_fixture;

TEST(MujocoPluginTest, AWheelOnASliderSettlesAtTheStaticDeflection) {
  const Terrain ground = flatGround();
  MjcfModel x(wheelOnSlider());
  mujoco::Plugin plugin(*x.m, ground);
  const mujoco::Wheel spec = mujocoWheel(x.body("wheel"), kRadiusM, kWidthM);
  plugin.addWheel(spec);
  for (int k = 0; k < 5000; ++k) plugin.step(*x.m, *x.d);  // 2 s
  const double load = (kCarrierKg + kWheelKg) * kGravityMps2;
  const double expected = load / spec.description.tyre.radial_stiffness;
  const double deflection = kRadiusM - x.d->xpos[3 * spec.body + 2];
  RecordProperty("deflection_mm", std::to_string(1e3 * deflection));
  RecordProperty("w_over_c_mm", std::to_string(1e3 * expected));
  EXPECT_NEAR(deflection, expected, 1e-4 * expected);
  EXPECT_NEAR(plugin.forces(0).force.z(), load, 1e-4 * load);
  EXPECT_GT(plugin.contactSeconds(), 0.0);
}

TEST(MujocoPluginTest, WithoutWheelsTheStepIsMujocosStepToTheBit) {
  for (const char* integrator : {"Euler", "implicit"}) {
    expectTheStepIsMujocosToTheBit(std::string("timestep=\"0.0004\" integrator=\"") + integrator + "\"",
                                   ContactMode::kForce);
  }
}

TEST(MujocoPluginTest, TheUsersOwnAppliedForceOnAWheelBodySurvivesTheStep) {
  const Terrain ground = flatGround();
  MjcfModel x(wheelOnSlider());
  mujoco::Plugin plugin(*x.m, ground);
  const int wheel = x.body("wheel");
  plugin.addWheel(mujocoWheel(wheel, kRadiusM, kWidthM));
  const mjtNum users[6] = {0.1, -2.5, 3.75, 0.01, 0.2, -0.3};
  std::memcpy(x.d->xfrc_applied + 6 * wheel, users, sizeof users);
  for (int k = 0; k < 100; ++k) plugin.step(*x.m, *x.d);
  EXPECT_EQ(std::memcmp(x.d->xfrc_applied + 6 * wheel, users, sizeof users), 0);
}

TEST(MujocoPluginTest, WhatTheAdapterCannotServeIsRefusedWithItsReason) {
  const Terrain ground = flatGround();
  MjcfModel x(wheelOnSlider());
  expectRefused([&] { mujoco::Plugin(*x.m, ground, ContactMode::kImplicit); }, {"implicit", "target velocity"});
  MjcfModel rk4(wheelOnSlider("timestep=\"0.0004\" integrator=\"RK4\""));
  expectRefused([&] { mujoco::Plugin(*rk4.m, ground); }, {"RK4", "Euler"});
  mujoco::Plugin plugin(*x.m, ground);
  expectRefused([&] { plugin.addWheel(mujocoWheel(0, kRadiusM, kWidthM)); }, {"the world"});
  expectRefused([&] { plugin.addWheel(mujocoWheel(99, kRadiusM, kWidthM)); }, {"body 99", "not a body of the model"});
  mujoco::Wheel no_axle = mujocoWheel(x.body("wheel"), kRadiusM, kWidthM);
  no_axle.axle_local.setZero();
  expectRefused([&] { plugin.addWheel(no_axle); }, {"axle"});
  MjcfModel touching(wheelOnSlider("timestep=\"0.0004\"", ""));
  mujoco::Plugin other(*touching.m, ground);
  expectRefused([&] { other.addWheel(mujocoWheel(touching.body("wheel"), kRadiusM, kWidthM)); },
                {"'tyre'", "'floor'", "twice"});
  plugin.addWheel(mujocoWheel(x.body("wheel"), kRadiusM, kWidthM));
  expectRefused([&] { plugin.addWheel(mujocoWheel(x.body("wheel"), kRadiusM, kWidthM)); }, {"'wheel'", "already"});
  expectRefused([&] { plugin.step(*rk4.m, *rk4.d); }, {"a model other than the plugin's"});
  // Soil bodies: the world, a wheel, a body twice, an integrator but Euler.
  const auto crate = [&](int body) {
    return mujoco::SoilBody{.body = body, .hulls = {ConvexPolyhedron::box({-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1})}};
  };
  expectRefused([&] { plugin.addSoilBody(crate(0)); }, {"the world"});
  expectRefused([&] { plugin.addSoilBody(crate(x.body("wheel"))); }, {"a registered wheel's"});
  plugin.addSoilBody(crate(x.body("box")));
  expectRefused([&] { plugin.addSoilBody(crate(x.body("box"))); }, {"already a soil body"});
  expectRefused([&] { plugin.addWheel(mujocoWheel(x.body("box"), kRadiusM, kWidthM)); }, {"is a soil body"});
  MjcfModel implicit(wheelOnSlider("timestep=\"0.0004\" integrator=\"implicit\""));
  mujoco::Plugin on_implicit(*implicit.m, ground);
  expectRefused([&] { on_implicit.addSoilBody(crate(implicit.body("box"))); }, {"Euler"});
}

}  // namespace mujoco_plugin_test
}  // namespace wtc::testing
