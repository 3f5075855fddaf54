// The main demo, for now: build a few pieces of ground and query points,
// printing what the wheel contact uses (signed distance, closest point,
// direction) and what each query cost (GJK iterations); then load the
// spec's ledge terrain and move a 0.19 m wheel up its face and over its top
// edge, printing every contact and the tyre model's forces on a wheel
// driven forward at 0.5 m/s with 5 % slip.
//
//   build/apps/wtc_demo [terrains/ledge.yaml]
#include <cmath>
#include <cstdio>
#include <vector>

#include <wtc/geometry/convex_polyhedron.hpp>
#include <wtc/io/terrain_file.hpp>
#include <wtc/geometry/point_query.hpp>
#include <wtc/tyre/tyre_model.hpp>
#include <wtc/contact/wheel_contact.hpp>

namespace {

void show(const char* name, const wtc::ConvexPolyhedron& poly, const std::vector<Eigen::Vector3d>& points) {
  std::printf("\n%s: %d vertices, %d faces, size %.3f m\n", name, poly.vertexCount(), poly.faceCount(), poly.size());
  std::printf("  %-28s %12s  %-28s  %-24s %5s  %s\n", "query point (m)", "signed d (m)", "closest point (m)",
              "direction", "iters", "status");
  for (const auto& p : points) {
    const wtc::PointQuery r = wtc::queryPoint(poly, p);
    std::printf("  (%7.3f, %7.3f, %7.3f)  %12.6f  (%7.3f, %7.3f, %7.3f)  (%6.3f, %6.3f, %6.3f) %5d  %s\n", p.x(), p.y(),
                p.z(), r.signed_distance, r.closest_point.x(), r.closest_point.y(), r.closest_point.z(),
                r.direction.x(), r.direction.y(), r.direction.z(), r.iterations, wtc::toString(r.status));
  }
}

// The wheel's centre climbs the ledge face (x = 0, 0.65 m high) and rolls
// onto the top, 2 mm into the ground where it touches.
void climbLedge(const char* path) {
  const wtc::Terrain ledge = wtc::io::loadTerrain(path);
  std::printf("\n%s: %zu pieces; a wheel r_f = 0.19 m, tread 0.12 m climbs the face and rolls over the edge\n", path,
              ledge.pieceCount());
  const wtc::WheelGeometry wheel{0.19, 0.12};
  wtc::WheelContactFinder finder;
  const std::vector<Eigen::Vector3d> centres = {{-0.40, 0, 0.188}, {-0.188, 0, 0.188}, {-0.188, 0, 0.40},
                                                {-0.188, 0, 0.65}, {-0.10, 0, 0.80},   {-0.02, 0, 0.838},
                                                {0.20, 0, 0.838}};
  std::printf("  %-24s %s\n", "wheel centre (m)", "contacts: piece, deflection (mm), e (toward the ground)");
  for (const auto& o : centres) {
    const auto contacts = finder.find(ledge, wheel, {o, Eigen::Vector3d::UnitY()});
    std::printf("  (%6.3f, %5.2f, %6.3f)   %zu:", o.x(), o.y(), o.z(), contacts.size());
    for (const auto& c : contacts) {
      std::printf("  [%d, %5.2f, (%5.2f, %5.2f, %5.2f)]", c.piece, 1e3 * c.deflection, c.e.x(), c.e.y(), c.e.z());
    }
    std::printf("\n");
  }

  // The same places with the full tyre model: a wheel rolling forward
  // (+x) at 0.5 m/s, spinning 5 % faster than rolling (driven), held there
  // for 0.3 s so that the tread reaches its steady state (docs/tyre-model.md).
  const wtc::TyreModel model(wtc::EffectSet::full());
  const wtc::WheelDescription description{wheel, {}, {}};
  wtc::WheelMotion motion;
  motion.velocity = {0.5, 0.0, 0.0};
  motion.angular_velocity = {0.0, 1.05 * 0.5 / wheel.free_radius, 0.0};
  std::printf("\n  tyre model (%s), 1 ms steps, after 0.3 s\n", model.effects().toString().c_str());
  std::printf("  %-24s %s\n", "wheel centre (m)",
              "per contact: R_z (N), slip ratio, mu, R_xy (N) | wheel: force (N), axial moment (N m)");
  for (const auto& o : centres) {
    wtc::WheelState state;
    for (int k = 1; k < 300; ++k) model.step(ledge, description, {o, Eigen::Vector3d::UnitY()}, motion, 1e-3, state);
    const wtc::WheelForces& f = model.step(ledge, description, {o, Eigen::Vector3d::UnitY()}, motion, 1e-3, state);
    std::printf("  (%6.3f, %5.2f, %6.3f)  ", o.x(), o.y(), o.z());
    for (const auto& c : f.contacts) {
      std::printf(" [%6.1f, %5.3f, %5.3f, (%6.1f, %6.1f, %6.1f)]", c.normal_force, c.slip_ratio, c.mu,
                  c.tangential_force.x(), c.tangential_force.y(), c.tangential_force.z());
    }
    std::printf(" | (%6.1f, %5.1f, %6.1f), %6.2f\n", f.force.x(), f.force.y(), f.force.z(), f.axial_moment.y());
  }
}

}  // namespace

int main(int argc, char** argv) {
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

  try {
    climbLedge(argc > 1 ? argv[1] : WTC_SOURCE_DIR "/terrains/ledge.yaml");
  } catch (const std::exception& error) {
    std::fprintf(stderr, "wtc_demo: %s\n", error.what());
    return 1;
  }
  return 0;
}
