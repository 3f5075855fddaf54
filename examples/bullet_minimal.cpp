// Adding WTC wheels to an existing Bullet program: the lines marked WTC are
// all it takes. A 21 kg wheel drops onto the spec's 0.65 m ledge terrain,
// settles, and is driven forward until it presses against the ledge face
// (two contacts: the ground and the face).
#include <cstdio>

#include <btBulletDynamicsCommon.h>
#include <wtc/bullet/plugin.hpp>    // WTC
#include <wtc/io/terrain_file.hpp>  // WTC

int main(int argc, char** argv) {
  // An ordinary Bullet world and a wheel body (a cylinder, axle along y).
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
  world.setGravity(btVector3(0, 0, -9.81));
  btCylinderShape shape(btVector3(0.19, 0.06, 0.19));
  btDefaultMotionState motion(btTransform(btQuaternion::getIdentity(), btVector3(-1.0, 0, 0.25)));
  const double mass = 21.0, inertia = 0.5 * mass * 0.19 * 0.19;
  btRigidBody wheel(
      btRigidBody::btRigidBodyConstructionInfo(mass, &motion, &shape, btVector3(inertia, inertia, inertia)));
  wheel.setAngularFactor(btVector3(0, 1, 0));  // a lone wheel stays upright
  world.addRigidBody(&wheel);

  // WTC: the terrain (a file given, or the ledge in WTC's data: WTC_DATA_DIR, README "Using the library"),
  // the plugin, and the wheel registered with its tyre.
  const wtc::Terrain ground = wtc::io::loadTerrain(argc > 1 ? argv[1] : WTC_DATA_DIR "/terrains/ledge.yaml");
  {
    wtc::bullet::Plugin wtc_plugin(world, ground, wtc::ContactMode::kForce);
    wtc::bullet::RigidWheel spec;
    spec.body = &wheel;                          // axle: the body's y axis (the default)
    // r_f = 0.19 m, c = 1e5 N/m: the defaults; mass and inertia: read from the body
    const wtc::bullet::WheelId id = wtc_plugin.addWheel(spec);

    for (int k = 0; k < 5000; ++k) {                           // 5 s at 1 ms
      if (k >= 1000) wheel.applyTorque(btVector3(0, 3.0, 0));  // drive after 1 s
      world.stepSimulation(1e-3, 1, 1e-3);
      if (k % 1000 == 999) {
        const wtc::WheelForces& f = wtc_plugin.forces(id);  // WTC: per-wheel state
        const btVector3 p = wheel.getCenterOfMassPosition();
        std::printf("t = %.1f s  centre (%.3f, %.3f) m  contacts %zu  force (%.1f, %.1f) N\n", 1e-3 * (k + 1), p.x(),
                    p.z(), f.contacts.size(), f.force.x(), f.force.z());
      }
    }
  }  // the plugin goes before the bodies it points at
  world.removeRigidBody(&wheel);
  return 0;
}
