// wtc_bench_compact, the meshes: the bench field's surface as a triangle
// mesh (wtc::surfaceMesh: two triangles a cell), kept compact
// (MeshExtrusionOptions::compact) against stored prisms (addTriangleMesh)
// and Bullet's btBvhTriangleMeshShape over the same arrays. FCL's
// BVHModel of these same triangles is Build/fcl and Contacts/fcl
// (heightfield_engines_bench.cpp).
//
// Runs (<cells> as in compact_heightfield_bench.cpp; 2 <cells> triangles):
//   MeshBuild/compact/<cells>  addTriangleMesh (compact: welding, the
//       degenerate test, the index) and Terrain::build; counters
//       bytes_per_triangle (all in), index_bytes_per_triangle (its part).
//   MeshBuild/prisms/<cells>   the same, stored (up to 10^6 cells).
//   MeshBuild/bullet/<cells>   Bullet's quantized-BVH mesh shape over the
//       compact mesh's own arrays; counter bytes_per_triangle: the arrays
//       and Bullet's nodes.
//   MeshContacts/<store>/<cells>/<path>  the per-wheel contact step
//       (WheelContactFinder), rolling or cold, as Contacts/ for fields.
//   MeshContacts/bullet/<cells>/<path>   one collision pass of a cylinder
//       wheel against the mesh shape (as Contacts/bullet).
#include <benchmark/benchmark.h>

#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btTriangleIndexVertexArray.h>
#include <btBulletCollisionCommon.h>

#include <memory>
#include <string>
#include <vector>

#include <wtc/bullet/terrain_object.hpp>
#include <wtc/terrain/terrain.hpp>
#include <wtc/terrain/triangle_mesh.hpp>
#include <wtc/contact/wheel_contact.hpp>

#include "bench_field.hpp"
#include "bullet_cylinder.hpp"

namespace {

using namespace wtc::bench;

constexpr double kThicknessM = 0.4;  // extrusion depth (m), the fields' base depth

wtc::Terrain meshTerrain(const wtc::TriangleMesh& mesh, bool compact) {
  wtc::TerrainBuilder builder;
  wtc::addTriangleMesh(builder, mesh, builder.addMaterial({}), {.thickness = kThicknessM, .compact = compact});
  return std::move(builder).build();
}

void buildMesh(benchmark::State& state, bool compact) {
  const wtc::TriangleMesh mesh = wtc::surfaceMesh(makeField(state.range(0)));
  double bytes = 0.0, index = 0.0;
  for (auto _ : state) {
    const wtc::Terrain terrain = meshTerrain(mesh, compact);
    bytes = static_cast<double>(terrain.pieceMemoryBytes() + terrain.indexMemoryBytes());
    index = static_cast<double>(terrain.indexMemoryBytes());
  }
  const auto triangles = static_cast<double>(mesh.triangles.size());
  state.counters["bytes_per_triangle"] = bytes / triangles;
  state.counters["index_bytes_per_triangle"] = index / triangles;
}

// The compact mesh's arrays as Bullet's mesh shape, as wtc::bullet's
// TerrainObject makes it (in parts Bullet's quantized tree can index).
struct BulletMesh {
  explicit BulletMesh(const wtc::TriangleMesh& m)
      : arrays(wtc::bullet::makeMeshArrays(m)), shape(arrays.get(), /*useQuantizedAabbCompression=*/true) {
    object.setCollisionShape(&shape);
  }
  std::size_t bytes(const wtc::TriangleMesh& m) {  // Bullet's getters are not const
    btOptimizedBvh* bvh = shape.getOptimizedBvh();
    return m.vertices.size() * sizeof(Eigen::Vector3d) + m.triangles.size() * sizeof(m.triangles[0]) + sizeof(*this) +
           bvh->getQuantizedNodeArray().size() * sizeof(btQuantizedBvhNode) +
           bvh->getSubtreeInfoArray().size() * sizeof(btBvhSubtreeInfo);
  }
  std::unique_ptr<btTriangleIndexVertexArray> arrays;
  btBvhTriangleMeshShape shape;
  btCollisionObject object;
};

void buildBulletMesh(benchmark::State& state) {
  const wtc::TriangleMesh mesh = wtc::surfaceMesh(makeField(state.range(0)));
  std::size_t bytes = 0;
  for (auto _ : state) {
    const auto bullet = std::make_unique<BulletMesh>(mesh);
    bytes = bullet->bytes(mesh);
  }
  state.counters["bytes_per_triangle"] = static_cast<double>(bytes) / static_cast<double>(mesh.triangles.size());
}

void meshContacts(benchmark::State& state, bool compact, bool cold) {
  const wtc::Heightfield field = makeField(state.range(0));
  const std::vector<wtc::Aabb> boxes = wheelBoxes(field, cold);
  runContactSteps(state, meshTerrain(wtc::surfaceMesh(field), compact), boxes);
}

void bulletMeshContacts(benchmark::State& state, bool cold) {
  const wtc::Heightfield field = makeField(state.range(0));
  const std::vector<wtc::Aabb> boxes = wheelBoxes(field, cold);
  const wtc::TriangleMesh mesh = wtc::surfaceMesh(field);
  BulletMesh ground(mesh);
  runBulletCylinder(state, ground.object, boxes);
}

const bool kMeshRunsRegistered = [] {
  for (long cells : {10'000L, 100'000L, 1'000'000L, 10'000'000L}) {
    const std::string tail = join("/", std::to_string(cells));
    const bool stored_too = cells <= 1'000'000L;  // 10^7 cells stored: about 52 GB
    benchmark::RegisterBenchmark(join("MeshBuild/compact", tail).c_str(), buildMesh, true)
        ->Arg(cells)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
    if (stored_too) {
      benchmark::RegisterBenchmark(join("MeshBuild/prisms", tail).c_str(), buildMesh, false)
          ->Arg(cells)
          ->Unit(benchmark::kMillisecond)
          ->Iterations(1);
    }
    benchmark::RegisterBenchmark(join("MeshBuild/bullet", tail).c_str(), buildBulletMesh)
        ->Arg(cells)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
    for (bool cold : {false, true}) {
      const std::string path = cold ? "/cold" : "/rolling";
      benchmark::RegisterBenchmark(join("MeshContacts/compact", tail + path).c_str(), meshContacts, true, cold)
          ->Arg(cells);
      if (stored_too) {
        benchmark::RegisterBenchmark(join("MeshContacts/prisms", tail + path).c_str(), meshContacts, false, cold)
            ->Arg(cells);
      }
      benchmark::RegisterBenchmark(join("MeshContacts/bullet", tail + path).c_str(), bulletMeshContacts, cold)
          ->Arg(cells);
    }
  }
  return true;
}();

}  // namespace
