// wtc_bench_wheel: the per-wheel contact query against terrain size, and the
// terrain index against FCL's and Bullet's broadphases in the same run.
//
//   build/bench/wtc_bench_wheel --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// Runs:
//   WheelQuery/<index>/<terrain>/<pieces>  candidates from <index> (wtc, fcl,
//       bullet), then the same point queries (max_distance = r_f): the work
//       of one wheel in one step, differing only in the index.
//   WheelIndex/<index>/<terrain>/<pieces>  the index alone.
//   WheelContacts/<terrain>/<pieces>       wtc::WheelContactFinder, the full
//       contact step (warm starts, seam rule, tread filter).
//   TerrainBuild/<terrain>/<pieces>        building pieces and index, once.
// <terrain>: heightfield (0.5 m cells, two prisms each) or mesh (a jittered
// triangulation extruded 0.3 m along -normal). The wheel (r_f = 0.19 m,
// w = 0.12 m, axle along y) is 2 mm deep in the ground, touching a few
// cells, and either rolls along an ellipse at 1 mm per query (a wheel at
// 1 m/s, 1 ms steps: what a simulation asks) or, with the suffix /cold,
// jumps to a random place every query (every access on cold memory: the
// worst case).
// Placement: at every position of both paths, the centre's height is found
// by bisection on the terrain itself, so that the deepest contact
// WheelContactFinder returns (the timed runs' wheel and options) is 2 mm
// deep (to 1e-8 m). The smooth relief the terrain samples is only the first
// guess: the flat cell triangles and the jittered mesh put the resting
// height up to 8 mm (heightfield) and 11 mm (mesh) away from it, so a wheel
// placed 2 mm into the relief often touched nothing. Placement runs once per
// terrain, before timing: about 23 contact searches per position, at most
// ~0.2 s (35,500 positions from 10^4 pieces up). If any depth is off by more
// than 1 um, every run of that terrain fails. Counter contacts_per_query
// (WheelContacts): contacts returned per query, >= 1 at every position by
// construction.
#include <benchmark/benchmark.h>

#include <BulletCollision/BroadphaseCollision/btDbvt.h>
#include <btBulletCollisionCommon.h>
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/box.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <wtc/terrain/heightfield.hpp>
#include <wtc/geometry/point_query.hpp>
#include <wtc/terrain/triangle_mesh.hpp>
#include <wtc/contact/wheel_contact.hpp>

#include "resting_centre.hpp"

namespace {

using Eigen::Vector3d;

constexpr double kRadius = 0.19;   // r_f (m)
constexpr double kTreadM = 0.12;   // w (m)
constexpr double kCellM = 0.5;     // cell size (m)
constexpr double kDepthM = 0.002;  // wheel sinkage (m)
constexpr double kStepM = 0.001;   // rolling: 1 m/s at a 1 ms step (m)
constexpr double kMaxLoopM = 5.0;  // rolling: semi-axis cap of the loop (m)
constexpr int kColdPoints = 4096;  // cold: random positions
// Placement (see the header). The deepest depth changes by at most 1 m per
// metre of height (distance is 1-Lipschitz), so a height bracket of
// wtc::bench::kBisectionM pins the depth to 1e-8 m, 100x inside kDepthToleranceM.
constexpr double kDepthToleranceM = 1e-6;  // accepted error of the deepest contact's depth (m)

const wtc::WheelGeometry kWheel{kRadius, kTreadM};
const Vector3d kAxle = Vector3d::UnitY();

double relief(double x, double y) {
  return 0.05 * std::sin(0.7 * x) * std::cos(0.9 * y) + 0.02 * std::sin(2.3 * x + 1.1 * y);
}

// cells_x x cells_y = pieces / 2, as square as the divisors allow.
std::pair<int, int> gridFor(long pieces) {
  const long cells = pieces / 2;
  long cx = static_cast<long>(std::sqrt(static_cast<double>(cells)));
  while (cells % cx != 0) --cx;
  return {static_cast<int>(cx), static_cast<int>(cells / cx)};
}

wtc::Terrain makeTerrain(const std::string& kind, long pieces) {
  const auto [cx, cy] = gridFor(pieces);
  wtc::TerrainBuilder builder;
  builder.reserve(pieces);
  const auto material = builder.addMaterial({});
  if (kind == "heightfield") {
    wtc::Heightfield field;
    field.cols = cx + 1;
    field.rows = cy + 1;
    field.spacing_x = field.spacing_y = kCellM;
    field.heights.resize(static_cast<std::size_t>(field.rows) * field.cols);
    for (int r = 0; r < field.rows; ++r)
      for (int c = 0; c < field.cols; ++c) field.heights[r * field.cols + c] = relief(c * kCellM, r * kCellM);
    wtc::addHeightfield(builder, field, material);
  } else {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> jitter(-0.15 * kCellM, 0.15 * kCellM);
    wtc::TriangleMesh mesh;
    mesh.name = "bench mesh";
    for (int r = 0; r <= cy; ++r) {
      for (int c = 0; c <= cx; ++c) {
        const bool border = r == 0 || c == 0 || r == cy || c == cx;
        const double x = c * kCellM + (border ? 0.0 : jitter(rng));
        const double y = r * kCellM + (border ? 0.0 : jitter(rng));
        mesh.vertices.emplace_back(x, y, relief(x, y));
      }
    }
    for (int r = 0; r < cy; ++r) {
      for (int c = 0; c < cx; ++c) {
        const int v00 = r * (cx + 1) + c, v01 = v00 + 1, v10 = v00 + cx + 1, v11 = v10 + 1;
        mesh.triangles.push_back({v00, v01, v11});
        mesh.triangles.push_back({v00, v11, v10});
      }
    }
    wtc::MeshExtrusionOptions options;
    options.thickness = 0.3;
    wtc::addTriangleMesh(builder, mesh, material, options);
  }
  return std::move(builder).build();
}

// Depth of the deepest contact of kWheel with its centre at `centre` (m), 0
// when nothing touches.
// The three indexes over the same piece boxes, and the wheel's path.
struct Fixture {
  std::string kind;
  long pieces = 0;
  double build_seconds = 0.0;
  std::unique_ptr<wtc::Terrain> terrain;
  std::vector<Vector3d> rolling;
  std::vector<Vector3d> cold;
  double placement_error = 0.0;  // worst |deepest depth - kDepthM| over both paths (m)
  const std::vector<Vector3d>& path(const std::string& motion) const { return motion == "cold" ? cold : rolling; }
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> fcl_objects;
  std::unique_ptr<fcl::DynamicAABBTreeCollisionManagerd> fcl_manager;
  btDbvt bullet_tree;
};

Fixture& fixture(const std::string& kind, long pieces) {
  static std::unique_ptr<Fixture> f;
  if (f && f->kind == kind && f->pieces == pieces) return *f;
  f.reset();  // one fixture alive at a time: 10^6 pieces in three indexes
  f = std::make_unique<Fixture>();
  f->kind = kind;
  f->pieces = pieces;
  const auto start = std::chrono::steady_clock::now();
  f->terrain = std::make_unique<wtc::Terrain>(makeTerrain(kind, pieces));
  f->build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // Rolling: an ellipse at 1 mm steps (what consecutive steps of one wheel
  // see). Cold: random positions anywhere (every query on cold memory).
  const wtc::Aabb& b = f->terrain->bounds();
  const Vector3d centre = b.center();
  const double ax = std::min(0.4 * b.extent().x(), kMaxLoopM), ay = std::min(0.4 * b.extent().y(), kMaxLoopM);
  const int rolling = static_cast<int>(2.0 * M_PI * std::sqrt(0.5 * (ax * ax + ay * ay)) / kStepM);
  wtc::WheelContactFinder placer;
  auto onGround = [&](double x, double y) {
    const wtc::bench::Placement p = wtc::bench::restingCentre(*f->terrain, placer, kWheel, kAxle, {}, x, y,
                                                              relief(x, y) + kRadius - kDepthM, kDepthM);
    f->placement_error = std::max(f->placement_error, std::abs(p.depth - kDepthM));
    return p.centre;
  };
  for (int k = 0; k < rolling; ++k) {
    const double t = 2.0 * M_PI * k / rolling;
    f->rolling.push_back(onGround(centre.x() + ax * std::cos(t), centre.y() + ay * std::sin(t)));
  }
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> ux(b.min.x() + kRadius, b.max.x() - kRadius);
  std::uniform_real_distribution<double> uy(b.min.y() + kRadius, b.max.y() - kRadius);
  for (int k = 0; k < kColdPoints; ++k) f->cold.push_back(onGround(ux(rng), uy(rng)));

  return *f;
}

// FCL's and Bullet's indexes over the same piece boxes, built the first time
// a run asks for them: the wtc-only runs (WheelContacts, the wtc columns)
// then skip building 10^6 objects twice.
void buildOtherIndexes(Fixture& f) {
  if (f.fcl_manager) return;
  std::vector<fcl::CollisionObjectd*> raw;
  for (wtc::PieceId id = 0; id < static_cast<wtc::PieceId>(f.terrain->pieceCount()); ++id) {
    const wtc::Aabb& box = f.terrain->piece(id).bounds();
    auto shape = std::make_shared<fcl::Boxd>(box.extent());
    auto object = std::make_unique<fcl::CollisionObjectd>(shape, fcl::Transform3d(Eigen::Translation3d(box.center())));
    object->setUserData(reinterpret_cast<void*>(static_cast<std::intptr_t>(id)));
    raw.push_back(object.get());
    f.fcl_objects.push_back(std::move(object));
    f.bullet_tree.insert(btDbvtVolume::FromMM(btVector3(box.min.x(), box.min.y(), box.min.z()),
                                              btVector3(box.max.x(), box.max.y(), box.max.z())),
                         reinterpret_cast<void*>(static_cast<std::intptr_t>(id)));
  }
  f.fcl_manager = std::make_unique<fcl::DynamicAABBTreeCollisionManagerd>();
  f.fcl_manager->registerObjects(raw);
  f.fcl_manager->setup();
  f.bullet_tree.optimizeTopDown();  // the best static tree Bullet offers
}

// Candidate gathering, one adapter per index.
struct Gather {
  explicit Gather(Fixture& fixture) : f(fixture) {}
  Fixture& f;
  std::vector<wtc::PieceId> out;
  std::unique_ptr<fcl::CollisionObjectd> fcl_wheel =
      std::make_unique<fcl::CollisionObjectd>(std::make_shared<fcl::Boxd>(2 * kRadius, 2 * kRadius, 2 * kRadius));
  btAlignedObjectArray<const btDbvtNode*> bullet_stack;

  void wtc(const Vector3d& o) { f.terrain->overlapping({o.array() - kRadius, o.array() + kRadius}, out); }
  void fcl(const Vector3d& o) {
    fcl_wheel->setTranslation(o);
    fcl_wheel->computeAABB();
    f.fcl_manager->collide(fcl_wheel.get(), this, [](fcl::CollisionObjectd* a, fcl::CollisionObjectd* b, void* data) {
      auto* self = static_cast<Gather*>(data);
      const fcl::CollisionObjectd* piece = a == self->fcl_wheel.get() ? b : a;  // FCL may pass either first
      self->out.push_back(static_cast<wtc::PieceId>(reinterpret_cast<std::intptr_t>(piece->getUserData())));
      return false;
    });
  }
  void bullet(const Vector3d& o) {
    struct Collect : btDbvt::ICollide {
      std::vector<wtc::PieceId>* out;
      void Process(const btDbvtNode* leaf) override {
        out->push_back(static_cast<wtc::PieceId>(reinterpret_cast<std::intptr_t>(leaf->data)));
      }
    } collect;
    collect.out = &out;
    const btVector3 c(o.x(), o.y(), o.z());
    f.bullet_tree.collideTVNoStackAlloc(f.bullet_tree.m_root, btDbvtVolume::FromCR(c, kRadius), bullet_stack, collect);
  }
  void run(const std::string& index, const Vector3d& o) {
    out.clear();
    if (index == "wtc")
      wtc(o);
    else if (index == "fcl")
      fcl(o);
    else
      bullet(o);
  }
};

void addCounters(benchmark::State& state, const Fixture& f, double candidates, double contacts) {
  const double n = static_cast<double>(state.iterations());
  state.SetItemsProcessed(state.iterations());
  state.counters["candidates"] = candidates / n;
  state.counters["contacts"] = contacts / n;
  state.counters["piece_bytes"] = static_cast<double>(f.terrain->pieceMemoryBytes()) / f.pieces;
  state.counters["index_bytes"] = static_cast<double>(f.terrain->indexMemoryBytes()) / f.pieces;
}

// False (and the run skipped) if some centre is not kDepthM deep: the
// timings would not be those of a wheel on the ground.
bool placed(benchmark::State& state, const Fixture& f) {
  if (f.placement_error <= kDepthToleranceM) return true;
  std::ostringstream message;
  message << "wheel placement: a deepest contact misses " << kDepthM << " m by " << f.placement_error << " m";
  state.SkipWithError(message.str().c_str());
  return false;
}

void wheelQuery(benchmark::State& state, std::string index, std::string kind, long pieces, bool queries,
                std::string motion) {
  Fixture& f = fixture(kind, pieces);
  if (!placed(state, f)) return;
  if (index != "wtc") buildOtherIndexes(f);
  const std::vector<Vector3d>& path = f.path(motion);
  Gather gather(f);
  wtc::QueryOptions options;
  options.max_distance = kRadius;
  double candidates = 0, contacts = 0;
  std::size_t k = 0;
  for (auto _ : state) {
    const Vector3d& o = path[k++ % path.size()];
    gather.run(index, o);
    candidates += gather.out.size();
    if (queries) {
      for (const wtc::PieceId id : gather.out) {
        const wtc::PointQuery q = wtc::queryPoint(f.terrain->piece(id), o, options);
        contacts += q.signed_distance < kRadius && q.status != wtc::QueryStatus::kBeyond;
      }
    }
    benchmark::DoNotOptimize(gather.out.data());
  }
  addCounters(state, f, candidates, contacts);
}

void wheelContacts(benchmark::State& state, std::string kind, long pieces, std::string motion) {
  Fixture& f = fixture(kind, pieces);
  if (!placed(state, f)) return;
  const std::vector<Vector3d>& path = f.path(motion);
  wtc::WheelContactFinder finder;
  double candidates = 0, contacts = 0;
  std::size_t k = 0;
  for (auto _ : state) {
    const auto found = finder.find(*f.terrain, kWheel, {path[k++ % path.size()], kAxle});
    contacts += found.size();
    candidates += finder.candidates().size();
    benchmark::DoNotOptimize(found.data());
  }
  addCounters(state, f, candidates, contacts);
  state.counters["contacts_per_query"] = benchmark::Counter(contacts, benchmark::Counter::kAvgIterations);
}

void terrainBuild(benchmark::State& state, std::string kind, long pieces) {
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const wtc::Terrain terrain = makeTerrain(kind, pieces);
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    state.counters["pieces"] = static_cast<double>(terrain.pieceCount());
  }
}

const bool kRegistered = [] {
  for (const std::string kind : {"heightfield", "mesh"}) {
    for (const long pieces : {100L, 1000L, 10000L, 100000L, 1000000L}) {
      const std::string suffix = "/" + kind + "/" + std::to_string(pieces);
      for (const std::string motion : {"rolling", "cold"}) {
        const std::string tail = suffix + (motion == "rolling" ? "" : "/cold");
        for (const std::string index : {"wtc", "fcl", "bullet"}) {
          benchmark::RegisterBenchmark(("WheelQuery/" + index + tail).c_str(), wheelQuery, index, kind, pieces, true,
                                       motion);
          benchmark::RegisterBenchmark(("WheelIndex/" + index + tail).c_str(), wheelQuery, index, kind, pieces, false,
                                       motion);
        }
        benchmark::RegisterBenchmark(("WheelContacts" + tail).c_str(), wheelContacts, kind, pieces, motion);
      }
      benchmark::RegisterBenchmark(("TerrainBuild" + suffix).c_str(), terrainBuild, kind, pieces)
          ->UseManualTime()
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
    }
  }
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
