// The C++ answers the Python batch queries are checked against
// (test_terrain.py), computed here without the bindings or the terrain's
// index: every piece queried (queryPoint), the nearest within reach kept;
// and one WheelContactFinder stepped through the poses.
//
//   wtc_python_query_reference TERRAIN_FILE POINTS REACH RADIUS WIDTH OUT
// POINTS: N rows "x y z ax ay az" (a point, which is also a wheel centre,
// and an axle). OUT: per point "distance nx ny nz piece", then per contact
// "contact index gx gy gz deflection piece".
#include <cstdio>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <wtc/contact/wheel_contact.hpp>
#include <wtc/geometry/point_query.hpp>
#include <wtc/io/terrain_file.hpp>

int main(int argc, char** argv) {
  if (argc != 7) {
    std::fprintf(stderr, "usage: %s TERRAIN_FILE POINTS REACH RADIUS WIDTH OUT\n", argv[0]);
    return 2;
  }
  const wtc::Terrain terrain = wtc::io::loadTerrain(argv[1]);
  const double reach = std::stod(argv[3]);
  const wtc::WheelGeometry wheel{.free_radius = std::stod(argv[4]), .tread_width = std::stod(argv[5])};
  std::ifstream in(argv[2]);
  std::vector<Eigen::Vector3d> points, axles;
  double v[6];
  while (in >> v[0] >> v[1] >> v[2] >> v[3] >> v[4] >> v[5]) {
    points.emplace_back(v[0], v[1], v[2]);
    axles.emplace_back(v[3], v[4], v[5]);
  }
  std::FILE* out = std::fopen(argv[6], "w");
  if (out == nullptr) return 2;
  std::optional<wtc::ConvexPolyhedron> scratch;
  for (const Eigen::Vector3d& p : points) {
    double best = std::numeric_limits<double>::infinity();
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    long piece = -1;
    for (std::size_t id = 0; id < terrain.pieceCount(); ++id) {
      const wtc::PointQuery q = wtc::queryPoint(terrain.piece(static_cast<wtc::PieceId>(id), scratch), p);
      if (q.signed_distance > reach) continue;
      if (q.signed_distance < best) {
        best = q.signed_distance;
        normal = q.normal;
        piece = static_cast<long>(id);
      }
    }
    std::fprintf(out, "%.17g %.17g %.17g %.17g %ld\n", best, normal.x(), normal.y(), normal.z(), piece);
  }
  wtc::WheelContactFinder finder;
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (const wtc::WheelContact& c : finder.find(terrain, wheel, {.center = points[i], .axle = axles[i]})) {
      std::fprintf(out, "contact %zu %.17g %.17g %.17g %.17g %ld\n", i, c.ground_point.x(), c.ground_point.y(),
                   c.ground_point.z(), c.deflection, static_cast<long>(c.piece));
    }
  }
  std::fclose(out);
  return 0;
}
