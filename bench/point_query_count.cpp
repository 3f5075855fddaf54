// Instructions per point query, counted by callgrind (docs/point-query.md):
//   wtc_count_query <shape> <rounds> [set] [answers.bin]
// queries each of the benchmark's 4096 points of <set> (default mixed) on
// <shape> (box, prism, hull20, hull64, or cell: the builders' prism) <rounds>
// times with the default options; tools/query_instructions.sh takes the
// difference of two round counts, so set-up cancels. With answers.bin it
// also writes every answer's bits (three option sets, with and without a
// cache) for a byte-for-byte comparison of two builds.
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenarios.hpp"
#include "wtc/geometry/point_query.hpp"

namespace {

constexpr int kPoints = 4096;  // wtc_bench_query's points per run

wtc::ConvexPolyhedron namedShape(const std::string& name) {
  if (name == "cell") return wtc::testing::makeBuildersCell();
  const auto id = wtc::testing::shapeFromString(name);
  if (!id) throw std::invalid_argument("wtc_count_query: unknown shape " + name);
  return wtc::testing::makeShape(*id);
}

void writeAnswers(const wtc::ConvexPolyhedron& poly, const std::vector<Eigen::Vector3d>& points, FILE* out) {
  auto put = [&](const void* data, std::size_t bytes) { std::fwrite(data, 1, bytes, out); };
  const wtc::QueryOptions options[] = {{}, {.max_distance = 0.19}, {.feature_regions = false}};
  for (const wtc::QueryOptions& o : options) {
    wtc::QueryCache cache;
    for (const Eigen::Vector3d& p : points) {
      const wtc::PointQuery plain = wtc::queryPoint(poly, p, o);
      const wtc::PointQuery cached = wtc::queryPoint(poly, p, o, cache);
      for (const wtc::PointQuery* a : {&plain, &cached}) {
        put(&a->signed_distance, sizeof(double));
        put(a->closest_point.data(), 3 * sizeof(double));
        put(a->direction.data(), 3 * sizeof(double));
        put(a->normal.data(), 3 * sizeof(double));
        put(&a->iterations, sizeof(int));
        put(&a->status, sizeof(a->status));
      }
      put(&cache.count, sizeof(cache.count));
      put(cache.vertex, sizeof(cache.vertex));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s <shape> <rounds> [set] [answers.bin]\n", argv[0]);
    return 2;
  }
  const wtc::ConvexPolyhedron poly = namedShape(argv[1]);
  const int rounds = std::atoi(argv[2]);
  const auto set = wtc::testing::querySetFromString(argc > 3 ? argv[3] : "mixed");
  if (!set) {
    std::fprintf(stderr, "unknown query set %s\n", argv[3]);
    return 2;
  }
  const std::vector<Eigen::Vector3d> points = wtc::testing::makeQuerySet(poly, *set, kPoints);
  double sum = 0.0;  // read, so that no query is optimised away
  for (int r = 0; r < rounds; ++r) {
    for (const Eigen::Vector3d& p : points) sum += wtc::queryPoint(poly, p, {}).signed_distance;
  }
  std::printf("%s: %d x %d queries, sum %.17g\n", argv[1], rounds, kPoints, sum);
  if (argc > 4) {
    FILE* out = std::fopen(argv[4], "wb");
    if (out == nullptr) return 1;
    writeAnswers(poly, points, out);
    std::fclose(out);
  }
  return 0;
}
