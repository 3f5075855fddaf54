// The main demo, for now: build a few pieces of ground and query points,
// printing what the wheel contact will use (signed distance, closest point,
// direction) and what each query cost (GJK iterations).
#include <cmath>
#include <cstdio>
#include <vector>

#include <wtc/convex_polyhedron.hpp>
#include <wtc/point_query.hpp>

namespace {

void show(const char* name, const wtc::ConvexPolyhedron& poly, const std::vector<Eigen::Vector3d>& points) {
  std::printf("\n%s: %d vertices, %d faces, size %.3f m\n", name, poly.vertexCount(), poly.faceCount(),
              poly.size());
  std::printf("  %-28s %12s  %-28s  %-24s %5s  %s\n", "query point (m)", "signed d (m)", "closest point (m)",
              "direction", "iters", "status");
  for (const auto& p : points) {
    const wtc::PointQuery r = wtc::queryPoint(poly, p);
    std::printf("  (%7.3f, %7.3f, %7.3f)  %12.6f  (%7.3f, %7.3f, %7.3f)  (%6.3f, %6.3f, %6.3f) %5d  %s\n", p.x(),
                p.y(), p.z(), r.signed_distance, r.closest_point.x(), r.closest_point.y(), r.closest_point.z(),
                r.direction.x(), r.direction.y(), r.direction.z(), r.iterations, wtc::toString(r.status));
  }
}

}  // namespace

int main() {
  // The spec's ledge: a 0.65 m step, its top edge at x = 0. A 0.19 m wheel
  // against its face and its edge.
  const auto ledge = wtc::ConvexPolyhedron::box({0.0, -2.0, -0.5}, {3.0, 2.0, 0.65});
  show("ledge block (0.65 m high)", ledge,
       {{-0.19, 0.0, 0.19}, {-0.10, 0.0, 0.70}, {0.5, 0.0, 0.80}, {-0.15, 0.0, 0.75}, {0.5, 0.0, 0.6}});

  // A heightfield cell: the triangle of ground extruded down to a base.
  const auto cell = wtc::ConvexPolyhedron::fromPoints(
      {{0, 0, 0.02}, {0.5, 0, 0.05}, {0, 0.5, 0.0}, {0, 0, -1}, {0.5, 0, -1}, {0, 0.5, -1}});
  show("heightfield prism", cell, {{0.1, 0.1, 0.2}, {0.6, 0.6, 0.1}, {0.1, 0.1, -0.5}});

  // A rock: the hull of points on a rough ellipsoid, computed by Qhull.
  std::vector<Eigen::Vector3d> rock;
  for (int i = 0; i < 40; ++i) {
    const double t = 2.399963 * i;  // golden-angle spiral
    const double z = 1.0 - 2.0 * (i + 0.5) / 40.0;
    const double r = std::sqrt(1.0 - z * z) * (1.0 + 0.1 * std::sin(3.0 * t));
    rock.emplace_back(0.4 * r * std::cos(t), 0.3 * r * std::sin(t), 0.2 * z);
  }
  show("rock (hull of 40 points)", wtc::ConvexPolyhedron::fromPoints(rock),
       {{0.0, 0.0, 0.5}, {0.5, 0.5, 0.0}, {0.0, 0.0, 0.0}});
  return 0;
}
