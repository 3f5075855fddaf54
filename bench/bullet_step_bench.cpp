// wtc_bench_bullet: what WTC costs inside a Bullet step, against Bullet's own
// wheel contact, in the same run.
//
//   build/bench/wtc_bench_bullet --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// Scene: the rough ground of scenario 3 (terrains/rough_ground.yaml: 7200
// heightfield prisms and rocks, mirrored into Bullet as convex hulls) and six
// 21 kg wheels (cylinders r = 0.19 m, w = 0.12 m, kept upright), each on its
// own line, driven by 3 N m from rest for 2 s of warm-up and 10 s of timed
// steps. The motions differ (WTC has the soil's rolling resistance, Bullet
// has none): the runs compare the cost of a step, not the trajectories. One item = one stepSimulation of 1 ms
// for the whole scene. Runs:
//   BulletStep/native       no WTC: Bullet's cylinder-against-hull contacts
//                           (GJK/EPA through the compound), Bullet friction
//   BulletStep/wtc_force    WTC in force mode (full tyre model)
//   BulletStep/wtc_constraint  WTC in constraint mode
// Counters: wheels, contacts (WTC contacts, or Bullet manifold points, per
// step over all wheels).
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include <btBulletDynamicsCommon.h>
#include <wtc/bullet/plugin.hpp>
#include <wtc/bullet/terrain_object.hpp>
#include <wtc/io/terrain_file.hpp>

namespace {

constexpr int kWheels = 6;
constexpr double kRadius = 0.19, kWidth = 0.12;   // (m)
constexpr double kMass = 21.0;                    // a sixth of the robot (kg)
constexpr double kStepSeconds = 1e-3;             // (s)
constexpr double kDriveTorque = 3.0;              // per wheel (N m): twice the soil's rolling resistance
constexpr double kLaneSpacingM = 1.5;             // between the wheels' lines (m)
constexpr double kStartX = -12.0, kDropM = 0.05;  // start (m) and height above the ground (m)
constexpr int kWarmupSteps = 2000;                // settle and spin up
// Steps per run: 10 s, so that every wheel stays on the 30 m ground (m).
constexpr int kTimedSteps = 10000;

const wtc::Terrain& roughGround() {
  static const wtc::Terrain terrain = wtc::io::loadTerrain(WTC_SOURCE_DIR "/terrains/rough_ground.yaml");
  return terrain;
}

struct Scene {
  explicit Scene(const std::string& kind) {
    world.setGravity(btVector3(0, 0, -9.81));
    if (kind == "native") {
      native_terrain = std::make_unique<wtc::bullet::TerrainObject>(roughGround());
      world.addCollisionObject(&native_terrain->object(), btBroadphaseProxy::StaticFilter,
                               btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
    }
    const double inertia = 0.5 * kMass * kRadius * kRadius;
    for (int i = 0; i < kWheels; ++i) {
      const btVector3 start(kStartX, (i - 0.5 * (kWheels - 1)) * kLaneSpacingM, 0.15 + kRadius + kDropM);
      motions.push_back(std::make_unique<btDefaultMotionState>(btTransform(btQuaternion::getIdentity(), start)));
      btRigidBody::btRigidBodyConstructionInfo info(kMass, motions.back().get(), &shape,
                                                    btVector3(inertia, inertia, inertia));
      info.m_friction = 0.8;
      bodies.push_back(std::make_unique<btRigidBody>(info));
      bodies.back()->setAngularFactor(btVector3(0, 1, 0));
      bodies.back()->setActivationState(DISABLE_DEACTIVATION);
      world.addRigidBody(bodies.back().get());
    }
    if (kind != "native") {
      plugin = std::make_unique<wtc::bullet::Plugin>(
          world, roughGround(), kind == "wtc_force" ? wtc::ContactMode::kForce : wtc::ContactMode::kConstraint);
      for (auto& body : bodies) {
        wtc::bullet::RigidWheel spec;
        spec.body = body.get();
        spec.description.geometry = {kRadius, kWidth};
        spec.description.inertia = {kMass, inertia};
        plugin->addWheel(spec);
      }
    }
    for (int k = 0; k < kWarmupSteps; ++k) step();
  }
  ~Scene() {
    plugin.reset();
    for (auto& body : bodies) world.removeRigidBody(body.get());
    if (native_terrain) world.removeCollisionObject(&native_terrain->object());
  }
  void step() {
    for (auto& body : bodies) body->applyTorque(btVector3(0, kDriveTorque, 0));
    world.stepSimulation(kStepSeconds, 1, kStepSeconds);
  }
  int contacts() {
    if (plugin) {
      int n = 0;
      for (int i = 0; i < plugin->wheelCount(); ++i) n += static_cast<int>(plugin->forces(i).contacts.size());
      return n;
    }
    int n = 0;
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m)
      n += dispatcher.getManifoldByIndexInternal(m)->getNumContacts();
    return n;
  }

  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
  btCylinderShape shape{btVector3(kRadius, 0.5 * kWidth, kRadius)};
  std::unique_ptr<wtc::bullet::TerrainObject> native_terrain;
  std::vector<std::unique_ptr<btDefaultMotionState>> motions;
  std::vector<std::unique_ptr<btRigidBody>> bodies;
  std::unique_ptr<wtc::bullet::Plugin> plugin;
};

void bulletStep(benchmark::State& state, const std::string& kind) {
  Scene scene(kind);
  long contacts = 0, steps = 0;
  for (auto _ : state) {
    scene.step();
    contacts += scene.contacts();
    ++steps;
  }
  state.SetItemsProcessed(steps);
  state.counters["wheels"] = kWheels;
  state.counters["contacts"] = steps > 0 ? static_cast<double>(contacts) / steps : 0.0;
  state.counters["speed_mps"] = scene.bodies.front()->getLinearVelocity().x();
}

}  // namespace

BENCHMARK_CAPTURE(bulletStep, native, std::string("native"))
    ->Name("BulletStep/native")
    ->Iterations(kTimedSteps)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(bulletStep, wtc_force, std::string("wtc_force"))
    ->Name("BulletStep/wtc_force")
    ->Iterations(kTimedSteps)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(bulletStep, wtc_constraint, std::string("wtc_constraint"))
    ->Name("BulletStep/wtc_constraint")
    ->Iterations(kTimedSteps)
    ->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
