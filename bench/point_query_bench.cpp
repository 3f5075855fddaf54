// ns/query of wtc::queryPoint against Bullet, FCL and brute force, on the
// same pieces and query points (tests/support/scenarios.hpp).
//
// Runs:
//   PointQuery/<method>/<shape>/<set>      method: wtc, bullet, fcl, brute
//   PointQuery/wtc_maxdist/<shape>/<set>   max_distance = kWheelRadius, as the wheel queries
//   PointQuery/wtc_gjk/<shape>/<set>       feature_regions off: the plain modified GJK
//   PointQuery/wtc*/cell/<set>             the prism's cell as the terrain builders build it
//   PointQueryTolerance/<shape>/<tol>      plain GJK on the mixed set, relative_tolerance = tol
//                                          (with the region tests on, most queries never
//                                          reach GJK and the tolerance cannot act)
// Each run cycles through kPointsPerRun pre-generated points, one query per
// iteration, so the time per iteration is the time per query (throughput:
// consecutive queries are independent). Counters, measured once per run on
// all its points outside the timed loop, against the brute-force oracle:
//   max_error        max |signed distance - exact| / piece size
//   max_point_error  max |closest point - exact| / piece size, outside points
//                    (where the closest point is unique)
//   max_rel_error    max |signed distance - exact| / exact, outside points
//   failures         no finite answer or a failure status (both kept out of the
//                    error counters), the wrong side of the surface, or a
//                    "beyond" answer that is not a valid bound
//   mean_iterations  wtc only: GJK iterations per query
//
// Reproduce the README table:
//   build/bench/wtc_bench_query --benchmark_repetitions=5
//     --benchmark_report_aggregates_only=true --benchmark_format=json > bench.json
//   python3 tools/bench_table.py bench.json
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>
#include <benchmark/benchmark.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/distance.h>

#include "brute_force.hpp"
#include "scenarios.hpp"
#include "wtc/geometry/point_query.hpp"

namespace {

using wtc::testing::QuerySetId;
using wtc::testing::ShapeId;

constexpr int kPointsPerRun = 4096;    // a power of two: the index wraps with a mask
constexpr double kWheelRadius = 0.19;  // m, the max_distance a wheel of this radius uses
// Signed distances within this of zero (x size) may come out with either sign.
constexpr double kSideToleranceRelative = 1e-9;

// One method's answer, for the accuracy counters.
struct Answer {
  double signed_distance;
  Eigen::Vector3d closest_point;
  bool ok;          // the method reports success
  bool bound_only;  // signed_distance is only a lower bound (wtc's kBeyond)
  int iterations;   // GJK iterations, -1 when the method does not say
};

// The inputs of one (shape, set) pair, built on first use and shared by all methods.
struct Case {
  wtc::ConvexPolyhedron poly;
  std::vector<Eigen::Vector3d> points;
  std::vector<wtc::testing::BruteForceResult> exact;
};

// A shape by its run name: the shared scenarios' and "cell".
wtc::ConvexPolyhedron makeNamedShape(const std::string& name) {
  if (name == "cell") return wtc::testing::makeBuildersCell();
  return wtc::testing::makeShape(*wtc::testing::shapeFromString(name));
}

const Case& getCase(const std::string& shape, QuerySetId set) {
  static std::map<std::pair<std::string, QuerySetId>, std::unique_ptr<Case>> cases;
  auto& entry = cases[{shape, set}];
  if (!entry) {
    wtc::ConvexPolyhedron poly = makeNamedShape(shape);
    auto points = wtc::testing::makeQuerySet(poly, set, kPointsPerRun);
    const wtc::testing::BruteForceOracle oracle(poly);
    std::vector<wtc::testing::BruteForceResult> exact;
    for (const auto& p : points) exact.push_back(oracle.query(p));
    entry = std::make_unique<Case>(Case{std::move(poly), std::move(points), std::move(exact)});
  }
  return *entry;
}

// ---- One adapter per method: built from the piece (untimed), query(p) timed.

class WtcMethod {
 public:
  explicit WtcMethod(const wtc::ConvexPolyhedron& poly, const wtc::QueryOptions& options = {})
      : poly_(poly), options_(options) {}
  Answer query(const Eigen::Vector3d& p) const {
    const wtc::PointQuery q = wtc::queryPoint(poly_, p, options_);
    return {q.signed_distance, q.closest_point, q.status != wtc::QueryStatus::kIterationLimit,
            q.status == wtc::QueryStatus::kBeyond, q.iterations};
  }

 private:
  const wtc::ConvexPolyhedron& poly_;
  wtc::QueryOptions options_;
};

// btGjkEpaSolver2::SignedDistance: GJK, then EPA when the point is inside.
class BulletMethod {
 public:
  explicit BulletMethod(const wtc::ConvexPolyhedron& poly) {
    for (int i = 0; i < poly.vertexCount(); ++i) {
      const Eigen::Vector3d v = poly.vertex(i);
      hull_.addPoint(btVector3(v.x(), v.y(), v.z()), false);
    }
    hull_.recalcLocalAabb();
    hull_.setMargin(0.0);  // default 0.04 m would shift the surface
  }
  Answer query(const Eigen::Vector3d& p) const {
    btGjkEpaSolver2::sResults r;
    const btScalar d =
        btGjkEpaSolver2::SignedDistance(btVector3(p.x(), p.y(), p.z()), 0.0, &hull_, btTransform::getIdentity(), r);
    const btVector3& c = r.witnesses[0];
    return {d, {c.x(), c.y(), c.z()}, d != SIMD_INFINITY, false, -1};
  }

 private:
  btConvexHullShape hull_;
};

// fcl::distance with the libccd solver (default tolerances), the point as a
// tiny sphere. FCL's error grows with the radius (about r on every set), and
// radii from 1e-9 to 1e-6 m give the same rare GJK misses on the hulls; at
// 1e-5 m Debian's libfcl (built with assertions) aborts in its EPA on
// hull20/near. Hence 1e-9 m.
class FclMethod {
 public:
  explicit FclMethod(const wtc::ConvexPolyhedron& poly) {
    auto vertices = std::make_shared<std::vector<fcl::Vector3d>>();
    for (int i = 0; i < poly.vertexCount(); ++i) vertices->push_back(poly.vertex(i));
    auto faces = std::make_shared<std::vector<int>>();  // [n, i_0 .. i_n-1] per face
    for (int f = 0; f < poly.faceCount(); ++f) {
      const auto face = poly.faceVertices(f);
      faces->push_back(static_cast<int>(face.size()));
      faces->insert(faces->end(), face.begin(), face.end());
    }
    convex_ = std::make_unique<fcl::Convexd>(vertices, poly.faceCount(), faces);
    convex_->computeLocalAABB();
    request_.enable_nearest_points = true;
    request_.enable_signed_distance = true;  // else the inside answer is -1
    request_.gjk_solver_type = fcl::GST_LIBCCD;
  }
  Answer query(const Eigen::Vector3d& p) const {
    fcl::Transform3d at_p = fcl::Transform3d::Identity();
    at_p.translation() = p;
    fcl::DistanceResultd result;  // fresh: update() keeps the minimum
    const double d = fcl::distance(&sphere_, at_p, convex_.get(), fcl::Transform3d::Identity(), request_, result);
    return {d + kRadius, result.nearest_points[1], std::isfinite(d), false, -1};
  }

 private:
  static constexpr double kRadius = 1e-9;  // m; added back to the distance
  fcl::Sphered sphere_{kRadius};
  std::unique_ptr<fcl::Convexd> convex_;
  fcl::DistanceRequestd request_;
};

// The oracle itself (every face, long double), faces prepared once.
class BruteMethod {
 public:
  explicit BruteMethod(const wtc::ConvexPolyhedron& poly) : oracle_(poly) {}
  Answer query(const Eigen::Vector3d& p) const {
    const auto r = oracle_.query(p);
    return {r.signed_distance, r.closest_point, true, false, -1};
  }

 private:
  wtc::testing::BruteForceOracle oracle_;
};

// ---- Accuracy against the oracle, and the run itself.

struct Accuracy {
  double max_error = 0.0;        // x size
  double max_point_error = 0.0;  // x size
  double max_rel_error = 0.0;    // x exact distance
  int failures = 0;
  double mean_iterations = -1.0;  // -1: not reported
};

template <class Method>
Accuracy measure(const Method& method, const Case& c, double max_distance) {
  const double size = c.poly.size();
  const double side = kSideToleranceRelative * size;
  Accuracy acc;
  double iterations = 0.0;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const Answer a = method.query(c.points[i]);
    iterations += a.iterations;
    const double exact = c.exact[i].signed_distance;
    const double error = std::abs(a.signed_distance - exact);
    if (!a.ok || !std::isfinite(a.signed_distance) || !a.closest_point.allFinite()) {
      ++acc.failures;  // no answer: counted, kept out of the error figures
      continue;
    }
    bool failed = false;
    if (a.bound_only) {  // a valid early exit: exact beyond max_distance, bound below it
      failed = exact < max_distance - side || a.signed_distance > exact + side;
    } else {
      failed = (exact > side && a.signed_distance < 0) || (exact < -side && a.signed_distance > 0);
      acc.max_error = std::max(acc.max_error, error / size);
      if (exact > side) {
        acc.max_rel_error = std::max(acc.max_rel_error, error / exact);
        const double point_error = (a.closest_point - c.exact[i].closest_point).norm();
        acc.max_point_error = std::max(acc.max_point_error, point_error / size);
      }
    }
    if (failed) ++acc.failures;
  }
  if (iterations >= 0.0) acc.mean_iterations = iterations / static_cast<double>(c.points.size());
  return acc;
}

// Registers `name`: `Method(poly, extra...)` timed on the points of (shape, set).
template <class Method, class... Extra>
void registerRun(const std::string& name, const std::string& shape, QuerySetId set, double max_distance,
                 Extra... extra) {
  auto accuracy = std::make_shared<std::optional<Accuracy>>();  // measured on the first call
  benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
    const Case& c = getCase(shape, set);
    const Method method(c.poly, extra...);
    if (!*accuracy) *accuracy = measure(method, c, max_distance);
    std::size_t i = 0;
    for (auto _ : state) {
      benchmark::DoNotOptimize(method.query(c.points[i]));
      i = (i + 1) & (kPointsPerRun - 1);
    }
    state.SetItemsProcessed(state.iterations());
    // Queries per second, inverted: seconds per query (printed as e.g. "21.3ns").
    state.counters["time_per_query"] = benchmark::Counter(static_cast<double>(state.iterations()),
                                                          benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["max_error"] = (*accuracy)->max_error;
    state.counters["max_point_error"] = (*accuracy)->max_point_error;
    state.counters["max_rel_error"] = (*accuracy)->max_rel_error;
    state.counters["failures"] = (*accuracy)->failures;
    if ((*accuracy)->mean_iterations >= 0.0) state.counters["mean_iterations"] = (*accuracy)->mean_iterations;
  });
}

void registerAll() {
  constexpr double kNoLimit = std::numeric_limits<double>::infinity();
  for (ShapeId id : wtc::testing::kAllShapes) {
    const std::string shape = toString(id);
    for (QuerySetId set : wtc::testing::kAllQuerySets) {
      const std::string suffix = "/" + shape + "/" + toString(set);
      registerRun<WtcMethod>("PointQuery/wtc" + suffix, shape, set, kNoLimit);
      registerRun<BulletMethod>("PointQuery/bullet" + suffix, shape, set, kNoLimit);
      registerRun<FclMethod>("PointQuery/fcl" + suffix, shape, set, kNoLimit);
      registerRun<BruteMethod>("PointQuery/brute" + suffix, shape, set, kNoLimit);
      registerRun<WtcMethod>("PointQuery/wtc_maxdist" + suffix, shape, set, kWheelRadius,
                             wtc::QueryOptions{.max_distance = kWheelRadius});
      registerRun<WtcMethod>("PointQuery/wtc_gjk" + suffix, shape, set, kNoLimit,
                             wtc::QueryOptions{.feature_regions = false});
    }
  }
  // The prism's cell as the terrain builders make it: WTC's runs only (the
  // other methods see the same vertices as the prism's).
  for (QuerySetId set : wtc::testing::kAllQuerySets) {
    const std::string suffix = std::string("/cell/") + toString(set);
    registerRun<WtcMethod>("PointQuery/wtc" + suffix, "cell", set, kNoLimit);
    registerRun<WtcMethod>("PointQuery/wtc_maxdist" + suffix, "cell", set, kWheelRadius,
                           wtc::QueryOptions{.max_distance = kWheelRadius});
  }
  for (ShapeId id : wtc::testing::kAllShapes) {
    const std::string shape = toString(id);
    for (int exponent = 3; exponent <= 12; ++exponent) {
      const double tolerance = std::pow(10.0, -exponent);
      registerRun<WtcMethod>("PointQueryTolerance/" + shape + "/1e-" + std::to_string(exponent), shape,
                             QuerySetId::kMixed, kNoLimit,
                             wtc::QueryOptions{.relative_tolerance = tolerance, .feature_regions = false});
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  registerAll();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
