// Adding WTC wheels to an existing ODE program: the lines marked WTC are all it takes. The robot's
// 3.7 kg wheel drops onto the spec's 0.65 m ledge, settles, and is driven against its face (two contacts).
#include <cstdio>
#include <numbers>
#include <ode/ode.h>
#include <wtc/io/terrain_file.hpp>  // WTC
#include <wtc/ode/plugin.hpp>       // WTC

struct Sim { dWorldID world; dSpaceID space; dJointGroupID contacts; wtc::ode::Plugin* wtc; };

void nearCallback(void* data, dGeomID a, dGeomID b) {
  const Sim& sim = *static_cast<Sim*>(data);
  if (sim.wtc->handlePair(a, b, sim.contacts)) return;  // WTC: wheel-terrain pairs are WTC's
  if (dGeomIsSpace(a) || dGeomIsSpace(b)) return dSpaceCollide2(a, b, data, &nearCallback);
  dContact c[8] = {};
  for (int i = 0, n = dCollide(a, b, 8, &c[0].geom, sizeof(dContact)); i < n; ++i) {
    c[i].surface = {dContactApprox1, 0.8};
    dJointAttach(dJointCreateContact(sim.world, sim.contacts, &c[i]), dGeomGetBody(a), dGeomGetBody(b));
  }
}

int main(int argc, char** argv) {
  dInitODE2(0);
  Sim sim{dWorldCreate(), dHashSpaceCreate(nullptr), dJointGroupCreate(0), nullptr};
  dWorldSetGravity(sim.world, 0, 0, -9.81);
  const dBodyID wheel = dBodyCreate(sim.world);  // a cylinder, its axis (local z) turned to the world's y
  dMass mass;
  dMassSetCylinderTotal(&mass, 3.7, 3, 0.19, 0.12);
  dBodySetMass(wheel, &mass);
  const dQuaternion turn = {std::numbers::sqrt2 / 2, -std::numbers::sqrt2 / 2, 0, 0};  // -90 deg about x
  dBodySetQuaternion(wheel, turn);
  dBodySetPosition(wheel, -1.0, 0, 0.25);  // balanced on its tread: nothing here pushes it sideways
  const dGeomID tyre = dCreateCylinder(sim.space, 0.19, 0.12);
  dGeomSetBody(tyre, wheel);

  // WTC: a terrain file given, or the ledge in WTC's data (WTC_DATA_DIR: README, "Using the library").
  const wtc::Terrain ground = wtc::io::loadTerrain(argc > 1 ? argv[1] : WTC_DATA_DIR "/terrains/ledge.yaml");
  {
    wtc::ode::Plugin plugin(sim.world, sim.space, ground, wtc::ContactMode::kConstraint);  // WTC
    // WTC: the defaults describe this wheel (axle the body's z, r_f = 0.19 m, 3.7 kg, c = 1e5 N/m).
    const wtc::ode::WheelId id = plugin.addWheel({.body = wheel, .geom = tyre});
    sim.wtc = &plugin;  // WTC
    for (int k = 0; k < 5000; ++k) {  // 5 s at 1 ms, driven after 1 s
      if (k >= 1000) dBodyAddTorque(wheel, 0, 3.0, 0);
      plugin.beginStep(1e-3);  // WTC: every step, before collision detection
      dSpaceCollide(sim.space, &sim, &nearCallback);
      dWorldQuickStep(sim.world, 1e-3);
      dJointGroupEmpty(sim.contacts);
    }
    const dReal* p = dBodyGetPosition(wheel);  // against the face: x = -(0.19 m - the tyre's deflection)
    std::printf("centre (%.4f, %.4f) m, WTC contacts %zu\n", p[0], p[2], plugin.forces(id).contacts.size());
  }  // the plugin goes before the space it lives in
  dJointGroupDestroy(sim.contacts);
  dSpaceDestroy(sim.space);
  dWorldDestroy(sim.world);
  dCloseODE();
}
