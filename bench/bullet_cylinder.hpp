#pragma once
// What an engine pays for a cylinder wheel on its own ground shape, the
// Bullet side of wtc_bench_compact: one collision pass of a two-object
// btCollisionWorld per wheel place (the wheel moved, its persistent
// manifold with the ground refreshed).
#include <benchmark/benchmark.h>

#include <btBulletCollisionCommon.h>

#include <vector>

#include <wtc/geometry/aabb.hpp>

#include "bench_field.hpp"

namespace wtc::bench {

// The timed loop: the cylinder (r_f, kWheelWidthM wide, axle along y) at
// each box's centre in turn against `ground`; counter contacts_per_query.
inline void runBulletCylinder(benchmark::State& state, btCollisionObject& ground, const std::vector<Aabb>& boxes) {
  btCylinderShape cylinder(btVector3(kRadius, 0.5 * kWheelWidthM, kRadius));  // axis y
  btCollisionObject wheel;
  wheel.setCollisionShape(&cylinder);
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  btCollisionWorld world(&dispatcher, &broadphase, &config);
  world.addCollisionObject(&ground, btBroadphaseProxy::StaticFilter, btBroadphaseProxy::AllFilter);
  world.addCollisionObject(&wheel);
  std::size_t i = 0;
  long found = 0, queries = 0;
  for (auto _ : state) {
    const Eigen::Vector3d c = boxes[i].center();
    wheel.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(c.x(), c.y(), c.z())));
    i = i + 1 == boxes.size() ? 0 : i + 1;
    world.performDiscreteCollisionDetection();
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m)
      found += dispatcher.getManifoldByIndexInternal(m)->getNumContacts();
    ++queries;
  }
  state.counters["contacts_per_query"] = static_cast<double>(found) / static_cast<double>(queries);
  world.removeCollisionObject(&wheel);
  world.removeCollisionObject(&ground);
}

}  // namespace wtc::bench
