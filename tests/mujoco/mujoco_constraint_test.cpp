// WTC's contacts solved by MuJoCo (wtc::mujoco, constraint mode), checked
// against MuJoCo 2.2.2's own constraint equations (engine_core_constraint.c)
// and statics: each contact's row is the implicit Euler step of the tyre's
// spring-damper (R = 1 / (h (h c + b)), B = 1 / h, K I = c R); a wheel
// settles at W / c at a step where force mode's explicit spring diverges;
// friction creeps at h R_t F, the speed MuJoCo's soft cone gives; with no
// wheels the hand-run stages are mj_step to the bit; what the mode cannot
// serve is refused with its reason.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include <mujoco/mujoco.h>

#include "expect_refused.hpp"
#include "mujoco_fixtures.hpp"
#include "wheel_sim.hpp"
#include "wtc/mujoco/plugin.hpp"
#include "wtc/tyre/tyre_parameters.hpp"

namespace wtc::testing {
namespace mujoco_constraint_test {

using namespace slider_fixture;

std::string options(double step_s, const char* cone, double impratio = 1.0) {
  return "timestep=\"" + std::to_string(step_s) + "\" integrator=\"Euler\" cone=\"" + cone + "\" impratio=\"" +
         std::to_string(impratio) + "\"";
}

// R* = 1 / (h (h c + b)): the implicit step's regularizer (1/kg).
double targetRegularizer(const TyreParameters& tyre, double h) {
  return 1.0 / (h * (h * tyre.radial_stiffness + tyre.radial_damping));
}

TEST(MujocoConstraintTest, WithoutWheelsTheHandRunStagesAreMujocosStepToTheBit) {
  for (const char* cone : {"pyramidal", "elliptic"}) {
    expectTheStepIsMujocosToTheBit(options(0.0004, cone), ContactMode::kConstraint);
  }
}

// The wheel on its slider, in both cones, at 0.4 ms and at 20 ms: there
// h sqrt(c / m) = 1.63 is past force mode's limit 2 (sqrt(1 + z^2) - z) =
// 1.39 (m = 15 kg, z = b / (2 sqrt(c m)) = 0.37), and MuJoCo's implicit
// spring still settles at W / c.
TEST(MujocoConstraintTest, AWheelSettlesAtTheStaticDeflectionAtAnyStep) {
  const Terrain ground = flatGround();
  for (const char* cone : {"pyramidal", "elliptic"}) {
    for (const double h : {0.0004, 0.02}) {
      SCOPED_TRACE(std::string(cone) + ", h = " + std::to_string(h));
      MjcfModel x(wheelOnSlider(options(h, cone)));
      mujoco::Plugin plugin(*x.m, ground, ContactMode::kConstraint);
      const mujoco::Wheel spec = mujocoWheel(x.body("wheel"), kRadiusM, kWidthM);
      plugin.addWheel(spec);
      const int steps = static_cast<int>(std::lround(3.0 / h));
      for (int k = 0; k < steps; ++k) plugin.step(*x.m, *x.d);
      const TyreParameters& tyre = spec.description.tyre;
      const double load = (kCarrierKg + kWheelKg) * kGravityMps2;
      const double expected = load / tyre.radial_stiffness;
      const double deflection = kRadiusM - x.d->xpos[3 * spec.body + 2];
      RecordProperty(std::string("deflection_mm_") + cone + "_" + std::to_string(h), std::to_string(1e3 * deflection));
      EXPECT_NEAR(deflection, expected, 1e-4 * expected);
      EXPECT_NEAR(plugin.applied(0).force.z(), load, 1e-4 * load);
      EXPECT_LT(plugin.forces(0).force.norm(), 2.0 * load) << "the explicit model's answer is kept too";
      // The row MuJoCo built: R* (the normal's share of a pyramid's common
      // R: 4 edges carry it), B = 1 / h, K I = c R*.
      int wtc_contact = -1;
      for (int i = 0; i < x.d->ncon; ++i) {
        if (x.m->geom_bodyid[x.d->contact[i].geom2] == spec.body) wtc_contact = i;
      }
      ASSERT_GE(wtc_contact, 0);
      const int row = x.d->contact[wtc_contact].efc_address;
      const bool pyramid = std::string(cone) == "pyramidal";
      const double normal_r = pyramid ? x.d->efc_R[row] / 4.0 : x.d->efc_R[row];
      EXPECT_NEAR(normal_r, targetRegularizer(tyre, h), 1e-9 * targetRegularizer(tyre, h));
      EXPECT_NEAR(x.d->efc_KBIP[4 * row + 1], 1.0 / h, 1e-9 / h);
      EXPECT_NEAR(x.d->efc_KBIP[4 * row] * x.d->efc_KBIP[4 * row + 2],
                  tyre.radial_stiffness * targetRegularizer(tyre, h),
                  1e-9 * tyre.radial_stiffness * targetRegularizer(tyre, h));
    }
  }
}

TEST(MujocoConstraintTest, ForceModesExplicitSpringDoesNotSettleAtTheLargeStep) {
  // The other half of the comparison above: the same wheel at 20 ms in
  // force mode keeps moving (bouncing on its explicit spring).
  const Terrain ground = flatGround();
  MjcfModel x(wheelOnSlider(options(0.02, "elliptic")));
  mujoco::Plugin plugin(*x.m, ground);
  const mujoco::Wheel spec = mujocoWheel(x.body("wheel"), kRadiusM, kWidthM);
  plugin.addWheel(spec);
  const double expected = (kCarrierKg + kWheelKg) * kGravityMps2 / spec.description.tyre.radial_stiffness;
  double worst = 0.0;
  for (int k = 0; k < 150; ++k) {
    plugin.step(*x.m, *x.d);
    if (k >= 100) worst = std::max(worst, std::abs(kRadiusM - x.d->xpos[3 * spec.body + 2] - expected));
  }
  RecordProperty("force_mode_worst_error_mm", std::to_string(1e3 * worst));
  EXPECT_GT(worst, 0.5 * expected);
}

// A sled (the wheel body cannot spin) pushed along x by F = 0.1 W, within
// any friction coefficient: MuJoCo's friction row solves
// f (A + R_t) = -v / h - a_0, so at a steady speed v = h R_t F, with
// R_t = R_0 / impratio, R_0 the normal row's R before a pyramid's rescaling:
// R* on an elliptic cone, 2 R* impratio / mu^2 on a pyramidal one
// (soft_contact.hpp).
std::string sled(const std::string& option) {
  return R"(<mujoco model="sled">
  <option )" +
         option + R"(/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1" contype="0" conaffinity="0"/>
    <body name="sled" pos="0 0 0.19">
      <joint name="x" type="slide" axis="1 0 0"/>
      <joint name="z" type="slide" axis="0 0 1"/>
      <geom name="tyre" type="cylinder" size="0.19 0.06" euler="90 0 0" mass="20" contype="0" conaffinity="0"/>
    </body>
  </worldbody>
</mujoco>)";
}

TEST(MujocoConstraintTest, FrictionCreepsAtTheSpeedMujocosSoftConeGives) {
  const Terrain ground = flatGround();
  struct Case {
    const char* cone;
    double impratio;
  };
  for (const Case c : {Case{"elliptic", 1.0}, Case{"elliptic", 10.0}, Case{"pyramidal", 1.0}}) {
    SCOPED_TRACE(std::string(c.cone) + ", impratio " + std::to_string(c.impratio));
    const double h = 0.001;
    MjcfModel x(sled(options(h, c.cone, c.impratio)));
    mujoco::Plugin plugin(*x.m, ground, ContactMode::kConstraint);
    const mujoco::Wheel spec = mujocoWheel(x.body("sled"), kRadiusM, kWidthM);
    plugin.addWheel(spec);
    const double push = 0.1 * 20.0 * kGravityMps2;
    x.d->xfrc_applied[6 * spec.body] = push;
    for (int k = 0; k < 3000; ++k) plugin.step(*x.m, *x.d);
    ASSERT_EQ(x.d->ncon, 1);
    const double mu = x.d->contact[0].friction[0];
    const double r_star = targetRegularizer(spec.description.tyre, h);
    const double r_t = std::string(c.cone) == "pyramidal" ? 2.0 * r_star / (mu * mu) : r_star / c.impratio;
    const double expected = h * r_t * push;
    RecordProperty(std::string("creep_mm_s_") + c.cone + "_" + std::to_string(c.impratio),
                   std::to_string(1e3 * x.d->qvel[0]));
    EXPECT_NEAR(x.d->qvel[0], expected, 1e-3 * expected);
    EXPECT_NEAR(plugin.applied(0).force.x(), -push, 1e-3 * push);
  }
}

TEST(MujocoConstraintTest, WhatConstraintModeCannotServeIsRefusedWithItsReason) {
  const Terrain ground = flatGround();
  MjcfModel implicit(wheelOnSlider("timestep=\"0.0004\" integrator=\"implicit\""));
  expectRefused([&] { mujoco::Plugin(*implicit.m, ground, ContactMode::kConstraint); },
                {"implicit integrator", "mj_implicit", "Euler"});
  MjcfModel off(wheelOnSlider());
  off.m->opt.disableflags |= mjDSBL_CONTACT;  // <flag contact="disable"/>
  expectRefused([&] { mujoco::Plugin(*off.m, ground, ContactMode::kConstraint); }, {"contacts are disabled"});
  const std::string no_floor = R"(<mujoco><worldbody><body name="wheel"><joint type="slide" axis="0 0 1"/>
    <geom type="sphere" size="0.19" contype="0" conaffinity="0"/></body></worldbody></mujoco>)";
  MjcfModel bare(no_floor);
  expectRefused([&] { mujoco::Plugin(*bare.m, ground, ContactMode::kConstraint); }, {"a geom of the world body"});
  const std::string no_geom = R"(<mujoco><worldbody><geom type="plane" size="1 1 1"/><body name="wheel">
    <joint type="slide" axis="0 0 1"/><inertial pos="0 0 0" mass="5" diaginertia="0.1 0.1 0.1"/></body>
    </worldbody></mujoco>)";
  MjcfModel hollow(no_geom);
  mujoco::Plugin plugin(*hollow.m, ground, ContactMode::kConstraint);
  expectRefused([&] { plugin.addWheel(mujocoWheel(hollow.body("wheel"), kRadiusM, kWidthM)); },
                {"'wheel'", "has no geom"});
  // A contact list one long, which the crate fills when it lands.
  MjcfModel full(std::string(wheelOnSlider())
                     .insert(std::string("<mujoco model=\"wheel_on_slider\">").size(), "<size nconmax=\"1\"/>"));
  mujoco::Plugin tight(*full.m, ground, ContactMode::kConstraint);
  tight.addWheel(mujocoWheel(full.body("wheel"), kRadiusM, kWidthM));
  expectRefused(
      [&] {
        for (int k = 0; k < 2000; ++k) tight.step(*full.m, *full.d);
      },
      {"nconmax (1", "raise"});
}

}  // namespace mujoco_constraint_test
}  // namespace wtc::testing
