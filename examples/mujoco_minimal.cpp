// Adding WTC wheels to an existing MuJoCo program: the lines marked WTC are all it takes. A small
// four-wheeled robot, written here as MJCF, drives at 2 rad/s on its own velocity actuators toward
// the spec's 0.65 m ledge and stops with its front wheels against the face (two contacts each).
#include <mujoco/mujoco.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <wtc/io/terrain_file.hpp>  // WTC
#include <wtc/mujoco/plugin.hpp>    // WTC

// The robot, and the ledge again as MuJoCo's own ground for its chassis. The wheels' geoms collide
// with nothing (contype 0): their contact is WTC's, on the WTC terrain.
const char* const kRobot = R"(<mujoco model="four_wheeler">
  <option timestep="0.001" integrator="Euler"/>
  <default><geom contype="1" conaffinity="1"/></default>
  <worldbody>
    <geom name="approach" type="box" size="2 1.5 0.25" pos="-2 0 -0.25"/>
    <geom name="step" type="box" size="2 1.5 0.575" pos="2 0 0.075"/>
    <body name="chassis" pos="-1.5 0 0.19">
      <freejoint/>
      <geom type="box" size="0.3 0.2 0.04" mass="20"/>
      <body name="front_left" pos="0.25 0.28 0"><joint name="fl" axis="0 1 0"/>
        <geom type="cylinder" size="0.19 0.06" euler="90 0 0" mass="3.7" contype="0" conaffinity="0"/></body>
      <body name="front_right" pos="0.25 -0.28 0"><joint name="fr" axis="0 1 0"/>
        <geom type="cylinder" size="0.19 0.06" euler="90 0 0" mass="3.7" contype="0" conaffinity="0"/></body>
      <body name="rear_left" pos="-0.25 0.28 0"><joint name="rl" axis="0 1 0"/>
        <geom type="cylinder" size="0.19 0.06" euler="90 0 0" mass="3.7" contype="0" conaffinity="0"/></body>
      <body name="rear_right" pos="-0.25 -0.28 0"><joint name="rr" axis="0 1 0"/>
        <geom type="cylinder" size="0.19 0.06" euler="90 0 0" mass="3.7" contype="0" conaffinity="0"/></body>
    </body>
  </worldbody>
  <actuator>
    <velocity joint="fl" kv="5"/><velocity joint="fr" kv="5"/><velocity joint="rl" kv="5"/><velocity joint="rr" kv="5"/>
  </actuator>
</mujoco>)";

int main(int argc, char** argv) {
  // The model from a string, through MuJoCo's virtual file system (2.2.2 has no mj_addBufferVFS).
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  mj_makeEmptyFileVFS(vfs.get(), "robot.xml", static_cast<int>(std::strlen(kRobot)));
  std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), "robot.xml")], kRobot, std::strlen(kRobot));
  char error[1000] = "";
  mjModel* m = mj_loadXML("robot.xml", vfs.get(), error, sizeof error);
  mj_deleteVFS(vfs.get());
  if (m == nullptr) return std::printf("%s\n", error), 1;
  mjData* d = mj_makeData(m);

  // WTC: a terrain file given, or the ledge in WTC's data (WTC_DATA_DIR: README, "Using the library").
  const wtc::Terrain ground = wtc::io::loadTerrain(argc > 1 ? argv[1] : WTC_DATA_DIR "/terrains/ledge.yaml");
  std::vector<wtc::WheelId> wheels;
  {
    wtc::mujoco::Plugin plugin(*m, ground, wtc::ContactMode::kConstraint);  // WTC
    // WTC: the defaults describe these wheels (axle the body's y, r_f = 0.19 m, c = 1e5 N/m; mass, inertia: the
    // body's).
    for (const char* name : {"front_left", "front_right", "rear_left", "rear_right"}) {
      wtc::mujoco::Wheel wheel;
      wheel.body = mj_name2id(m, mjOBJ_BODY, name);
      wheels.push_back(plugin.addWheel(wheel));  // WTC
    }
    for (int k = 0; k < 6000; ++k) {  // 6 s at 1 ms
      for (int a = 0; a < m->nu; ++a) d->ctrl[a] = 2.0;
      plugin.step(*m, *d);  // WTC: instead of mj_step(m, d)
    }
    const double* front = d->xpos + 3 * mj_name2id(m, mjOBJ_BODY, "front_left");
    const wtc::WheelForces& f = plugin.applied(wheels[0]);  // what MuJoCo's solver applied at WTC's contacts
    std::printf("front wheel centre (%.4f, %.4f) m, WTC contacts %zu, force (%.1f, %.1f) N\n", front[0], front[2],
                f.contacts.size(), f.force.x(), f.force.z());
    if (!std::isfinite(front[0]) || front[0] > 0.0) return 1;
  }
  mj_deleteData(d);
  mj_deleteModel(m);
}
