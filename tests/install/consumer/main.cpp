// Builds a box with the installed WTC and queries one point, reads a
// terrain file through wtc::io, plugs WTC into a Bullet world through
// wtc::bullet and wtc::ode, and runs an installed scene (found through
// WTC_DATA_DIR, its terrain and vehicle by relative paths) in both engines
// through wtc::sim_engines: returns 0 only when every answer is right, so
// the install test fails on a broken package. Built as README.md's project
// (tests/install/run_consumer.cmake).
#include <btBulletDynamicsCommon.h>
#include <cmath>
#include <cstdio>
#include <exception>
#include <wtc/bullet/plugin.hpp>
#include <wtc/geometry/convex_polyhedron.hpp>
#include <wtc/sim/scene_file.hpp>
#include <wtc/io/terrain_file.hpp>
#include <wtc/ode/plugin.hpp>
#include <wtc/geometry/point_query.hpp>
#include <wtc/sim/engine_table.hpp>
#include <wtc/sim/scene_run.hpp>
#include <wtc/terrain/terrain_primitives.hpp>

int main() {
  const wtc::ConvexPolyhedron box = wtc::ConvexPolyhedron::box(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 1, 1));
  // 0.5 m above the middle of the top face.
  const wtc::PointQuery q = wtc::queryPoint(box, Eigen::Vector3d(1.0, 0.5, 1.5));
  const bool ok = q.status == wtc::QueryStatus::kOutside && std::abs(q.signed_distance - 0.5) < 1e-12 &&
                  (q.closest_point - Eigen::Vector3d(1.0, 0.5, 1.0)).norm() < 1e-12;
  std::printf("signed distance %.17g m, status %s: %s\n", q.signed_distance, wtc::toString(q.status),
              ok ? "ok" : "WRONG");
  if (!ok) return 1;
  // wtc::io: a terrain file that does not exist is a clear error, not a crash.
  bool io_ok = false;
  try {
    wtc::io::loadTerrain("no/such/terrain.yaml");
  } catch (const std::exception& error) {
    std::printf("wtc::io: %s\n", error.what());
    io_ok = true;
  }
  if (!io_ok) return 1;
  // wtc::bullet: a 3.7 kg wheel settles on a slab at m g / c = 0.36 mm.
  wtc::TerrainBuilder builder;
  wtc::addSlab(builder, {}, builder.addMaterial({}));
  const wtc::Terrain ground = std::move(builder).build();
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
  world.setGravity(btVector3(0, 0, -9.81));
  btSphereShape sphere(0.19);
  btDefaultMotionState motion(btTransform(btQuaternion::getIdentity(), btVector3(0, 0, 0.2)));
  btRigidBody wheel(btRigidBody::btRigidBodyConstructionInfo(3.7, &motion, &sphere, btVector3(0.07, 0.07, 0.07)));
  world.addRigidBody(&wheel);
  double deflection = 0.0;
  {
    wtc::bullet::Plugin plugin(world, ground);
    wtc::bullet::RigidWheel spec;
    spec.body = &wheel;
    plugin.addWheel(spec);
    for (int k = 0; k < 2000; ++k) world.stepSimulation(1e-3, 1, 1e-3);
    deflection = 0.19 - wheel.getCenterOfMassPosition().z();
  }
  world.removeRigidBody(&wheel);
  const double expected = 3.7 * 9.81 / 1e5;
  const bool bullet_ok = std::abs(deflection - expected) < 0.02 * expected;
  std::printf("wtc::bullet: settled deflection %.4g m: %s\n", deflection, bullet_ok ? "ok" : "WRONG");

  // wtc::ode: the same wheel in ODE (force mode: no near callback needed).
  dInitODE2(0);
  const dWorldID ode_world = dWorldCreate();
  dWorldSetGravity(ode_world, 0, 0, -9.81);
  const dSpaceID space = dHashSpaceCreate(nullptr);
  const dBodyID body = dBodyCreate(ode_world);
  dMass mass;
  dMassSetSphereTotal(&mass, 3.7, 0.19);
  dBodySetMass(body, &mass);
  dBodySetPosition(body, 0, 0, 0.2);
  const dGeomID geom = dCreateSphere(space, 0.19);
  dGeomSetBody(geom, body);
  {
    wtc::ode::Plugin plugin(ode_world, space, ground);
    plugin.addWheel({.body = body, .geom = geom, .axle_local = Eigen::Vector3d::UnitY()});  // horizontal axle
    for (int k = 0; k < 2000; ++k) {
      plugin.beginStep(1e-3);
      dWorldStep(ode_world, 1e-3);
    }
    deflection = 0.19 - dBodyGetPosition(body)[2];
  }
  dSpaceDestroy(space);
  dWorldDestroy(ode_world);
  dCloseODE();
  const bool ode_ok = std::abs(deflection - expected) < 0.02 * expected;
  std::printf("wtc::ode: settled deflection %.4g m: %s\n", deflection, ode_ok ? "ok" : "WRONG");

  // wtc::sim_engines: the installed robot_straight scene, 0.2 s (500 steps of 0.4 ms) in each engine.
  bool scenes_ok = true;
  for (const char* engine : {"bullet", "ode"}) {
    const wtc::sim::Override overrides[] = {{"engine", engine}, {"duration", "0.2"}};
    const wtc::sim::Scene scene = wtc::sim::loadScene(WTC_DATA_DIR "/scenes/robot_straight.yaml", overrides);
    const auto sim = wtc::sim::makeEngine(scene.engine, *scene.terrain, scene.vehicle, scene.placement);
    const wtc::sim::RunSummary run = wtc::sim::runScene(scene, *sim);
    const bool ok = run.steps == 500 && !run.nan && !run.diverged;
    std::printf("wtc::sim_engines: %s in %s, %llu steps: %s\n", run.scene.c_str(), engine,
                static_cast<unsigned long long>(run.steps), ok ? "ok" : "WRONG");
    scenes_ok = scenes_ok && ok;
  }
  return bullet_ok && ode_ok && scenes_ok ? 0 : 1;
}
