// Builds a box with the installed WTC and queries one point, and reads a
// terrain file through wtc::io: returns 0 only when both answers are right,
// so the install test fails on a broken package.
#include <cmath>
#include <cstdio>
#include <exception>
#include <wtc/convex_polyhedron.hpp>
#include <wtc/io/terrain_file.hpp>
#include <wtc/point_query.hpp>

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
  try {
    wtc::io::loadTerrain("no/such/terrain.yaml");
  } catch (const std::exception& error) {
    std::printf("wtc::io: %s\n", error.what());
    return 0;
  }
  return 1;
}
