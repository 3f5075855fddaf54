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
#include "wheel_sim.hpp"
#include "wtc/mujoco/plugin.hpp"
#include "wtc/terrain/terrain_primitives.hpp"

namespace wtc::testing {
namespace mujoco_plugin_test {

constexpr double kRadiusM = 0.19, kWidthM = 0.12, kCarrierKg = 10.0, kWheelKg = 5.0;

// A carrier on a vertical slider, the wheel on a hinge about y below it
// (its cylinder, contype 0: no MuJoCo contact), and a box on a free joint
// that MuJoCo's own contact holds on the floor. `options`: <option>'s
// attributes.
std::string model(const std::string& options = "timestep=\"0.0004\" integrator=\"Euler\"",
                  const std::string& tyre_bits = "contype=\"0\" conaffinity=\"0\"") {
  return R"(<mujoco model="wheel_on_slider">
  <option )" +
         options + R"(/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <body name="carrier" pos="0 0 0.2">
      <joint name="lift" type="slide" axis="0 0 1"/>
      <inertial pos="0 0 0" mass="10" diaginertia="0.1 0.1 0.1"/>
      <body name="wheel">
        <joint name="axle" type="hinge" axis="0 1 0"/>
        <geom name="tyre" type="cylinder" size="0.19 0.06" euler="90 0 0" mass="5" )" +
         tyre_bits + R"(/>
      </body>
    </body>
    <body name="box" pos="1 0 0.3">
      <freejoint/>
      <geom name="crate" type="box" size="0.1 0.1 0.1" mass="2"/>
    </body>
  </worldbody>
</mujoco>)";
}

// An MJCF text as a model, through MuJoCo's virtual file system.
struct Model {
  explicit Model(const std::string& xml) {
    auto vfs = std::make_unique<mjVFS>();
    mj_defaultVFS(vfs.get());
    mj_makeEmptyFileVFS(vfs.get(), "model.xml", static_cast<int>(xml.size()));
    std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), "model.xml")], xml.data(), xml.size());
    char error[1000] = "";
    m = mj_loadXML("model.xml", vfs.get(), error, sizeof error);
    mj_deleteVFS(vfs.get());
    if (m == nullptr) throw std::runtime_error(std::string("mj_loadXML: ") + error);
    d = mj_makeData(m);
  }
  ~Model() {
    mj_deleteData(d);
    mj_deleteModel(m);
  }
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;
  int body(const char* name) const { return mj_name2id(m, mjOBJ_BODY, name); }
  mjModel* m = nullptr;
  mjData* d = nullptr;
};

Terrain flat() {
  TerrainBuilder builder;
  SlabParams slab;
  slab.size_x = slab.size_y = 10.0;
  addSlab(builder, slab, builder.addMaterial(Material{}));
  return std::move(builder).build();
}

mujoco::Wheel wheelOn(int body) {
  mujoco::Wheel w;
  w.body = body;
  w.description.geometry.free_radius = kRadiusM;
  w.description.geometry.tread_width = kWidthM;
  return w;
}

TEST(MujocoPluginTest, AWheelOnASliderSettlesAtTheStaticDeflection) {
  const Terrain ground = flat();
  Model x(model());
  mujoco::Plugin plugin(*x.m, ground);
  const mujoco::Wheel spec = wheelOn(x.body("wheel"));
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
  const Terrain ground = flat();
  for (const char* integrator : {"Euler", "implicit"}) {
    Model a(model(std::string("timestep=\"0.0004\" integrator=\"") + integrator + "\""));
    Model b(model(std::string("timestep=\"0.0004\" integrator=\"") + integrator + "\""));
    mujoco::Plugin plugin(*b.m, ground);
    for (int k = 0; k < 2000; ++k) {
      mj_step(a.m, a.d);
      plugin.step(*b.m, *b.d);
    }
    EXPECT_GT(a.d->ncon, 0) << "the box rests on MuJoCo's own contact";
    EXPECT_EQ(std::memcmp(a.d->qpos, b.d->qpos, sizeof(mjtNum) * a.m->nq), 0) << integrator;
    EXPECT_EQ(std::memcmp(a.d->qvel, b.d->qvel, sizeof(mjtNum) * a.m->nv), 0) << integrator;
  }
}

TEST(MujocoPluginTest, TheUsersOwnAppliedForceOnAWheelBodySurvivesTheStep) {
  const Terrain ground = flat();
  Model x(model());
  mujoco::Plugin plugin(*x.m, ground);
  const int wheel = x.body("wheel");
  plugin.addWheel(wheelOn(wheel));
  const mjtNum users[6] = {0.1, -2.5, 3.75, 0.01, 0.2, -0.3};
  std::memcpy(x.d->xfrc_applied + 6 * wheel, users, sizeof users);
  for (int k = 0; k < 100; ++k) plugin.step(*x.m, *x.d);
  EXPECT_EQ(std::memcmp(x.d->xfrc_applied + 6 * wheel, users, sizeof users), 0);
}

TEST(MujocoPluginTest, WhatTheAdapterCannotServeIsRefusedWithItsReason) {
  const Terrain ground = flat();
  Model x(model());
  expectRefused([&] { mujoco::Plugin(*x.m, ground, ContactMode::kConstraint); }, {"constraint", "force mode"});
  Model rk4(model("timestep=\"0.0004\" integrator=\"RK4\""));
  expectRefused([&] { mujoco::Plugin(*rk4.m, ground); }, {"RK4", "Euler"});
  mujoco::Plugin plugin(*x.m, ground);
  expectRefused([&] { plugin.addWheel(wheelOn(0)); }, {"the world"});
  expectRefused([&] { plugin.addWheel(wheelOn(99)); }, {"body 99", "not a body of the model"});
  mujoco::Wheel no_axle = wheelOn(x.body("wheel"));
  no_axle.axle_local.setZero();
  expectRefused([&] { plugin.addWheel(no_axle); }, {"axle"});
  Model touching(model("timestep=\"0.0004\"", ""));
  mujoco::Plugin other(*touching.m, ground);
  expectRefused([&] { other.addWheel(wheelOn(touching.body("wheel"))); }, {"'tyre'", "'floor'", "twice"});
  plugin.addWheel(wheelOn(x.body("wheel")));
  expectRefused([&] { plugin.addWheel(wheelOn(x.body("wheel"))); }, {"'wheel'", "already"});
  expectRefused([&] { plugin.step(*rk4.m, *rk4.d); }, {"a model other than the plugin's"});
}

}  // namespace mujoco_plugin_test
}  // namespace wtc::testing
