// wtc_bench_compact, the engines' side: the same fields and wheel places as
// compact_heightfield_bench.cpp, in Bullet's btHeightfieldTerrainShape and
// in an FCL triangle mesh (FCL 0.7 has no heightfield), each asked what an
// engine asks of its ground for a wheel: the contacts of a cylinder (r_f =
// 0.19 m, 0.12 m wide, axle along y, 2 mm into the surface).
//
// Runs (<cells> as in compact_heightfield_bench.cpp):
//   Build/bullet/<cells>   the shape over the caller's samples (Bullet
//       copies nothing; the min/max scan it needs is timed); counter
//       bytes_per_cell: the samples and the shape.
//   Build/fcl/<cells>      a BVHModel<OBBRSS> of the field's triangles (up
//       to 10^6 cells); counter bytes_per_cell: vertices, triangles and
//       nodes.
//   Contacts/bullet/<cells>/<path>  one collision pass of a two-object
//       btCollisionWorld (the wheel moved, its persistent manifold with the
//       heightfield refreshed): an engine's per-wheel cost for a cylinder
//       wheel on a heightfield.
//   Contacts/fcl/<cells>/<path>     fcl::collide of the cylinder and the mesh,
//       contacts on (up to 16).
#include <benchmark/benchmark.h>

#include <BulletCollision/CollisionShapes/btHeightfieldTerrainShape.h>
#include <btBulletCollisionCommon.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/narrowphase/collision.h>

#include <algorithm>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "bench_field.hpp"
#include "bullet_cylinder.hpp"

namespace {

using namespace wtc::bench;

constexpr std::size_t kFclMaxContacts = 16;  // contacts fcl::collide may return (count)

// The field as Bullet's heightfield shape, placed (like wtc::bullet's
// TerrainObject) so that its samples sit where the field says.
struct BulletField {
  explicit BulletField(const wtc::Heightfield& f) {
    const auto [lo, hi] = std::minmax_element(f.heights.begin(), f.heights.end());
    shape = std::make_unique<btHeightfieldTerrainShape>(f.cols, f.rows, f.heights.data(), *lo, *hi, 2, true);
    shape->setLocalScaling(btVector3(f.spacing_x, f.spacing_y, 1.0));
    object.setCollisionShape(shape.get());
    object.setWorldTransform(btTransform(
        btQuaternion::getIdentity(), btVector3(f.origin.x() + 0.5 * (f.cols - 1) * f.spacing_x,
                                               f.origin.y() + 0.5 * (f.rows - 1) * f.spacing_y, 0.5 * (*lo + *hi))));
  }
  std::unique_ptr<btHeightfieldTerrainShape> shape;
  btCollisionObject object;
};

std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> fclMesh(const wtc::Heightfield& f) {
  const wtc::TriangleMesh m = wtc::surfaceMesh(f);
  const std::vector<fcl::Vector3d> points(m.vertices.begin(), m.vertices.end());
  std::vector<fcl::Triangle> triangles;
  triangles.reserve(m.triangles.size());
  for (const auto& t : m.triangles) triangles.emplace_back(t[0], t[1], t[2]);
  auto mesh = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
  mesh->beginModel(static_cast<int>(triangles.size()), static_cast<int>(points.size()));
  mesh->addSubModel(points, triangles);
  mesh->endModel();
  return mesh;
}

void buildBullet(benchmark::State& state) {
  const wtc::Heightfield field = makeField(state.range(0));
  for (auto _ : state) {
    BulletField bullet(field);
    benchmark::DoNotOptimize(bullet.shape.get());
  }
  const double bytes = static_cast<double>(field.heights.size() * sizeof(double) + sizeof(btHeightfieldTerrainShape));
  state.counters["bytes_per_cell"] = bytes / cellsOf(field);
}

void buildFcl(benchmark::State& state) {
  const wtc::Heightfield field = makeField(state.range(0));
  std::size_t bytes = 0;
  for (auto _ : state) {
    const auto mesh = fclMesh(field);
    // What BVHModel::memUsage sums (it returns BVH_OK, not the sum, in FCL
    // 0.7), with its nodes counted whole and its primitive indices added.
    bytes = sizeof(*mesh) + mesh->getNumBVs() * sizeof(fcl::BVNode<fcl::OBBRSSd>) +
            mesh->num_tris * (sizeof(fcl::Triangle) + sizeof(unsigned int)) +
            mesh->num_vertices * sizeof(fcl::Vector3d);
    benchmark::DoNotOptimize(bytes);
  }
  state.counters["bytes_per_cell"] = static_cast<double>(bytes) / cellsOf(field);
}

void contactsBullet(benchmark::State& state, bool cold) {
  const wtc::Heightfield field = makeField(state.range(0));
  BulletField ground(field);
  runBulletCylinder(state, ground.object, wheelBoxes(field, cold));
}

void contactsFcl(benchmark::State& state, bool cold) {
  const wtc::Heightfield field = makeField(state.range(0));
  const std::vector<wtc::Aabb> boxes = wheelBoxes(field, cold);
  const fcl::CollisionObjectd ground(fclMesh(field));
  // FCL's cylinder has its axis along z: turned onto y.
  const fcl::Matrix3d axle_y(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitX()));
  fcl::CollisionObjectd wheel(std::make_shared<fcl::Cylinderd>(kRadius, kWheelWidthM));
  const fcl::CollisionRequestd request(kFclMaxContacts, true);
  std::size_t i = 0;
  long found = 0, queries = 0;
  for (auto _ : state) {
    wheel.setTransform(axle_y, boxes[i].center());
    wheel.computeAABB();
    i = i + 1 == boxes.size() ? 0 : i + 1;
    fcl::CollisionResultd result;
    fcl::collide(&wheel, &ground, request, result);
    found += static_cast<long>(result.numContacts());
    ++queries;
  }
  state.counters["contacts_per_query"] = static_cast<double>(found) / static_cast<double>(queries);
}

const bool kEngineRunsRegistered = [] {
  for (const long cells : kFieldCells) {
    const std::string tail = join("/", std::to_string(cells));
    benchmark::RegisterBenchmark(join("Build/bullet", tail).c_str(), buildBullet)
        ->Arg(cells)
        ->Unit(benchmark::kMillisecond);
    if (cells <= 1'000'000L) {
      benchmark::RegisterBenchmark(join("Build/fcl", tail).c_str(), buildFcl)
          ->Arg(cells)
          ->Unit(benchmark::kMillisecond)
          ->Iterations(1);
    }
    for (bool cold : {false, true}) {
      const std::string path = cold ? "/cold" : "/rolling";
      benchmark::RegisterBenchmark(join("Contacts/bullet", tail + path).c_str(), contactsBullet, cold)->Arg(cells);
      if (cells <= 1'000'000L) {
        benchmark::RegisterBenchmark(join("Contacts/fcl", tail + path).c_str(), contactsFcl, cold)->Arg(cells);
      }
    }
  }
  return true;
}();

}  // namespace
