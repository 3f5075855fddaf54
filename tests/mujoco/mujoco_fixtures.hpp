#pragma once
// What the wtc::mujoco tests share: an MJCF text as a MuJoCo model and its
// data, loaded through MuJoCo's virtual file system (MuJoCo 2.2.2 has no
// mj_addBufferVFS: an empty file is made and filled); a wheel of the
// default tyre on a body; the wheel on a slider. Flat WTC ground is
// wheel_sim.hpp's flatGround.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

#include <mujoco/mujoco.h>

#include "wheel_sim.hpp"
#include "wtc/mujoco/plugin.hpp"

namespace wtc::testing {

struct MjcfModel {
  explicit MjcfModel(const std::string& xml) {
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
  ~MjcfModel() {
    mj_deleteData(d);
    mj_deleteModel(m);
  }
  MjcfModel(const MjcfModel&) = delete;
  MjcfModel& operator=(const MjcfModel&) = delete;
  int body(const char* name) const { return mj_name2id(m, mjOBJ_BODY, name); }
  mjModel* m = nullptr;
  mjData* d = nullptr;
};

inline mujoco::Wheel mujocoWheel(int body, double radius_m, double width_m) {
  mujoco::Wheel w;
  w.body = body;
  w.description.geometry.free_radius = radius_m;
  w.description.geometry.tread_width = width_m;
  return w;
}

namespace slider_fixture {

constexpr double kRadiusM = 0.19, kWidthM = 0.12, kCarrierKg = 10.0, kWheelKg = 5.0;

// A carrier on a vertical slider, the wheel on a hinge about y below it
// (its cylinder, contype 0: no MuJoCo contact), and a box on a free joint
// that MuJoCo's own contact holds on the floor. `options`: <option>'s
// attributes.
inline std::string wheelOnSlider(const std::string& options = "timestep=\"0.0004\" integrator=\"Euler\"",
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

// The wheel on its slider with `options`, without wheels registered: after
// 2000 steps of mj_step and of the plugin's step in `mode`, the same qpos
// and qvel to the bit, with the box resting on MuJoCo's own contact.
inline void expectTheStepIsMujocosToTheBit(const std::string& options, ContactMode mode) {
  const Terrain ground = flatGround();
  MjcfModel a(wheelOnSlider(options));
  MjcfModel b(wheelOnSlider(options));
  mujoco::Plugin plugin(*b.m, ground, mode);
  for (int k = 0; k < 2000; ++k) {
    mj_step(a.m, a.d);
    plugin.step(*b.m, *b.d);
  }
  EXPECT_GT(a.d->ncon, 0) << "the box rests on MuJoCo's own contact";
  EXPECT_EQ(std::memcmp(a.d->qpos, b.d->qpos, sizeof(mjtNum) * a.m->nq), 0) << options;
  EXPECT_EQ(std::memcmp(a.d->qvel, b.d->qvel, sizeof(mjtNum) * a.m->nv), 0) << options;
}

}  // namespace slider_fixture

}  // namespace wtc::testing
