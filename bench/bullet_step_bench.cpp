// wtc_bench_bullet: what WTC costs inside a Bullet step, against Bullet's own
// wheel contact, in the same run.
//
//   build/bench/wtc_bench_bullet --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// Scene (bench/engine_step_scene.hpp, shared with wtc_bench_ode): six 21 kg
// wheels driven across the rough ground of scenario 3, its pieces mirrored
// into Bullet as convex hulls. The motions differ (WTC has the soil's
// rolling resistance, Bullet has none): the runs compare the cost of a step,
// not the trajectories. One item = one stepSimulation of 1 ms for the whole
// scene. Runs:
//   BulletStep/native          no WTC: Bullet's cylinder-against-hull contacts
//                              (GJK/EPA through the compound), Bullet friction
//   BulletStep/wtc_force       WTC in force mode (full tyre model)
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

#include "engine_step_scene.hpp"

namespace {

using namespace wtc::bench;

struct Scene {
  Scene(const std::string& kind, int wheels) {
    world.setGravity(btVector3(0, 0, -9.81));
    if (kind == "native") {
      native_terrain = std::make_unique<wtc::bullet::TerrainObject>(roughGround());
      world.addCollisionObject(&native_terrain->object(), btBroadphaseProxy::StaticFilter,
                               btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
    }
    const double inertia = 0.5 * kMass * kRadius * kRadius;
    for (int i = 0; i < wheels; ++i) {
      const btVector3 start(startX(i), laneY(i, wheels), kStartZ);
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
        plugin->addWheel(spec);
      }
    }
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
  double speed() const { return bodies.front()->getLinearVelocity().x(); }
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

}  // namespace

int main(int argc, char** argv) {
  registerScenes<Scene>("Bullet");
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
