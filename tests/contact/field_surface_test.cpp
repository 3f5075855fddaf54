// A compact heightfield met as one surface (ContactOptions::field_surface,
// issue 53: its triangles in closed form, a contact where the distance to
// the surface has a local minimum) against the same field met prism by
// prism, the answer before it (field_surface off): the same contacts at the
// same points, the load they carry within a millimetre of deflection, on a
// fine rough field with a kerb and a crack (holes) sampled in it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <random>
#include <span>
#include <vector>

#include "contact/field_surface.hpp"
#include "geometry/triangle_closest_point.hpp"
#include "terrain/field_cells.hpp"
#include "wtc/contact/wheel_contact.hpp"
#include "wtc/terrain/heightfield.hpp"
#include "wtc/terrain/terrain.hpp"

namespace wtc {
namespace {

constexpr double kSpacing = 0.01;              // m
constexpr double kKerbX = 1.6, kKerbM = 0.05;  // a 5 cm kerb from x = 1.6 m on
constexpr double kCrackX = 0.9;                // a 2 cm crack across the middle third

double relief(double x, double y) {
  return 0.03 * std::sin(2.1 * x) * std::sin(3.3 * y) + 0.004 * std::sin(90.0 * x) * std::sin(81.0 * y) +
         (x >= kKerbX ? kKerbM : 0.0);
}

// `ground` sampled at 1 cm over 2.4 m x 0.8 m, with a 2 cm crack (holes)
// across the middle third from column `crack`.
template <typename Ground>
Heightfield sampledField(Ground&& ground, int crack) {
  Heightfield f;
  f.cols = 241, f.rows = 81;  // 2.4 m x 0.8 m
  f.spacing_x = f.spacing_y = kSpacing;
  f.origin = {0.0, -0.4, 0.0};
  f.base_depth = 0.3;
  f.heights.resize(static_cast<std::size_t>(f.rows) * f.cols);
  for (int r = 0; r < f.rows; ++r)
    for (int c = 0; c < f.cols; ++c)
      f.heights[static_cast<std::size_t>(r) * f.cols + c] = ground(c * kSpacing, -0.4 + r * kSpacing);
  f.cell_holes.assign(static_cast<std::size_t>(f.rows - 1) * (f.cols - 1), 0);
  for (int r = 27; r < 53; ++r)
    for (int c = crack; c < crack + 2; ++c) f.cell_holes[static_cast<std::size_t>(r) * (f.cols - 1) + c] = 1;
  return f;
}

// sampledField as one compact field.
template <typename Ground>
Terrain sampledTerrain(Ground&& ground, int crack) {
  TerrainBuilder builder;
  const MaterialId material = builder.addMaterial({});
  addCompactHeightfield(builder, sampledField(ground, crack), material);
  return std::move(builder).build();
}

Terrain fineTerrain() { return sampledTerrain(relief, static_cast<int>(std::lround(kCrackX / kSpacing))); }

// The load the contacts carry, as deflection: sum of share x Z (m).
double carried(std::span<const WheelContact> contacts) {
  double sum = 0.0;
  for (const WheelContact& c : contacts) sum += c.load_share * c.deflection;
  return sum;
}

// The per-prism answer's own roundoff: GJK's closest point can lie a
// fraction of a micrometre outside the prisms that share it, beyond the seam
// rule's gap (0.19 um for this wheel), where the closed form puts it on
// them. The seam rule then takes a seam for a real edge and raises its share
// (up to clear / Z). True when `p` lies that close to one of `touching`
// other than `piece`, neither clearly on it nor clearly off it.
bool onARoundedSeam(const Terrain& terrain, std::span<const WheelContact> touching, PieceId piece,
                    const Eigen::Vector3d& p) {
  std::optional<ConvexPolyhedron> scratch;
  for (const WheelContact& other : touching) {
    if (other.piece == piece) continue;
    const double bound = terrain.piece(other.piece, scratch).planeBound(p);
    if (bound > 0.0 && bound < 1e-5) return true;
  }
  return false;
}

// How a surface's answers along a path compared with the prisms'.
struct PathAgreement {
  int steps = 0, same_load = 0, two_faces = 0, on_surface = 0, rounded = 0;
  double worst_load = 0.0;
  std::size_t triangles = 0;  // answered by the surface, all steps
  std::size_t prisms = 0;     // within the reach (the prisms' candidates), all steps
};

// Along the field from x0 to x1, 7 mm a step, the centre bobbing so that it
// sinks 0-24 mm into `ground`: every contact of the surface is one of the
// prisms', at the same point, with the same deflection, and the same share
// but where the prisms' answer rounded a seam into a real edge.
template <typename Ground>
PathAgreement meetAlongPath(const Terrain& terrain, Ground&& ground, double x0, double x1) {
  const WheelGeometry wheel{.free_radius = 0.19, .tread_width = 0.12};
  ContactOptions per_prism, every_piece;
  per_prism.field_surface = false;
  every_piece.field_surface = false, every_piece.seam_rule = false;
  WheelContactFinder surface, prisms, pieces;
  PathAgreement agreement;
  PathAgreement& a = agreement;
  for (double x = x0; x < x1; x += 0.007, ++a.steps) {
    const double y = 0.1 * std::sin(3.0 * x);
    const WheelPose pose{.center = {x, y, ground(x, y) + 0.19 - 0.012 * (1.0 + std::sin(11.0 * x))},
                         .axle = {0.03, 1.0, 0.05}};
    const auto found = prisms.find(terrain, wheel, pose, per_prism);
    const std::vector<WheelContact> expected(found.begin(), found.end());
    a.prisms += prisms.counts().candidates;
    const auto b = surface.find(terrain, wheel, pose);
    a.on_surface += surface.counts().surface > 0;
    a.triangles += surface.counts().surface;
    a.two_faces += b.size() >= 2;
    // Every contact of the surface is one of the prisms', at the same point
    // (of two triangles tied on one edge's point the lower id, where GJK
    // may have put a rounding nearer the other), and the prisms' are all
    // there: within the seam gap of the same points.
    EXPECT_EQ(b.size(), expected.size()) << "x " << x;
    if (b.size() != expected.size()) return agreement;
    bool shares_agree = true;
    for (const WheelContact& got : b) {
      const auto match = std::find_if(expected.begin(), expected.end(), [&](const WheelContact& c) {
        return (c.ground_point - got.ground_point).norm() < 1e-6;
      });
      EXPECT_NE(match, expected.end()) << "x " << x << ": piece " << got.piece << " is no prism's contact";
      if (match == expected.end()) return agreement;
      EXPECT_NEAR(got.deflection, match->deflection, 1e-9) << "x " << x;
      EXPECT_LT((got.e - match->e).norm(), 1e-6) << "x " << x;
      shares_agree = shares_agree && std::abs(got.load_share - match->load_share) < 1e-9;
    }
    const double difference = std::abs(carried(b) - carried(expected));
    if (shares_agree) {
      ++a.same_load;
      EXPECT_LT(difference, 1e-9) << "x " << x;
    } else {
      // Only where the prisms' answer rounded a seam into a real edge.
      const auto all = pieces.find(terrain, wheel, pose, every_piece);
      const std::vector<WheelContact> touching(all.begin(), all.end());
      bool explained = false;
      for (const WheelContact& c : expected)
        explained = explained || onARoundedSeam(terrain, touching, c.piece, c.ground_point);
      EXPECT_TRUE(explained) << "x " << x << ": the shares differ by " << difference << " m of deflection";
      ++a.rounded;
    }
    a.worst_load = std::max(a.worst_load, difference);
    if (::testing::Test::HasFailure()) return agreement;
  }
  return agreement;
}

TEST(FieldSurfaceTest, MeetsAFineFieldAtThePrismsContactsWithinAMillimetre) {
  const Terrain terrain = fineTerrain();
  // Over the crack and onto the kerb.
  const PathAgreement a = meetAlongPath(terrain, relief, 0.2, 2.2);
  ASSERT_FALSE(::testing::Test::HasFailure());
  EXPECT_GT(a.same_load, 0.97 * a.steps);  // the same load, to roundoff, almost everywhere
  EXPECT_GT(a.two_faces, 20);              // the kerb's edge and the crack's lips kept their own
  EXPECT_GT(a.on_surface, 0.8 * a.steps);  // answered as a surface most of the way
  EXPECT_LT(a.worst_load, 1e-3) << a.rounded << " steps' prisms rounded a seam";  // a millimetre at worst
}

// Built ground sampled at 1 cm: flat, a 4 % ramp, a flat top with a 2 cm
// crack (holes) across part of it, a 5 cm kerb, and a patch of 3 mm
// roughness: where the distance from a wheel centre has no local minimum
// the search passes the cells (SurfaceRun::passed).
constexpr double kRampX = 0.5, kRampEndX = 1.0, kRampRise = 0.02, kBuiltKerbX = 1.5, kRoughX = 1.9;

double builtGround(double x, double y) {
  double z = std::clamp((x - kRampX) / (kRampEndX - kRampX), 0.0, 1.0) * kRampRise;
  if (x >= kBuiltKerbX) z += kKerbM;
  if (x >= kRoughX) z += 0.003 * std::sin(90.0 * x) * std::sin(81.0 * y);
  return z;
}

Terrain builtTerrain() { return sampledTerrain(builtGround, 120); }

TEST(FieldSurfaceTest, PassesTheCellsWithoutAMinimumAndMeetsThePrismsContacts) {
  const Terrain terrain = builtTerrain();
  // The flat and the ramp: of the triangles within the reach the surface
  // answers those near the centre's vertical (a few on the flat, more on
  // the ramp).
  const PathAgreement flat = meetAlongPath(terrain, builtGround, 0.2, 1.1);
  ASSERT_FALSE(::testing::Test::HasFailure());
  EXPECT_EQ(flat.same_load, flat.steps);
  EXPECT_LT(flat.triangles * 8, flat.prisms) << flat.triangles << " of " << flat.prisms;
  // Over the crack, the kerb and the rough patch.
  const PathAgreement rest = meetAlongPath(terrain, builtGround, 1.1, 2.2);
  ASSERT_FALSE(::testing::Test::HasFailure());
  EXPECT_GT(rest.same_load, 0.97 * rest.steps);
  EXPECT_GT(rest.two_faces, 10);
  EXPECT_LT(rest.worst_load, 1e-3);
}

// SurfaceRun::passed's claim, checked by brute force: each triangle of a
// passed cell has its closest point to the centre on a neighbouring
// triangle (one that holds that point) whose own closest point is strictly
// nearer, so no minimum is lost by passing it. Random centres over the
// built ground and the rough one; passed cells must be found on both.
TEST(FieldSurfaceTest, NoPassedCellHoldsALocalMinimum) {
  int passed_cells = 0;
  for (const bool built : {true, false}) {
    const Terrain terrain = built ? builtTerrain() : fineTerrain();
    const Heightfield& f = *terrain.compactField(0).field;
    const auto ground = [&](double x, double y) { return built ? builtGround(x, y) : relief(x, y); };
    // Triangle t of cell (r, c): its corners, closestOnTriangle's a, b, c.
    const auto corners = [&](int r, int c, int t) -> std::array<Eigen::Vector3d, 3> {
      if (t == 0) return {f.sample(r, c), f.sample(r, c + 1), f.sample(r + 1, c + 1)};
      return {f.sample(r, c), f.sample(r + 1, c + 1), f.sample(r + 1, c)};
    };
    // Whether triangle `x` holds `q` (seen from above, to a nanometre).
    const auto holds = [](const std::array<Eigen::Vector3d, 3>& x, const Eigen::Vector3d& q) {
      for (int i = 0; i < 3; ++i) {
        const Eigen::Vector3d& a = x[i];
        const Eigen::Vector3d& b = x[(i + 1) % 3];
        const double cross = (b.x() - a.x()) * (q.y() - a.y()) - (b.y() - a.y()) * (q.x() - a.x());
        if (cross < -1e-9 * (b - a).head<2>().norm()) return false;  // counter-clockwise seen from above
      }
      return true;
    };
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> along(0.1, 2.3), across(-0.3, 0.3), above(0.1, 0.19);
    std::vector<PieceId> others;
    std::vector<Terrain::SurfaceRun> runs;
    for (int trial = 0; trial < 400; ++trial) {
      const double x = along(gen), y = across(gen);
      const Eigen::Vector3d o(x, y, ground(x, y) + above(gen));
      others.clear(), runs.clear();
      terrain.withinSurfaces(o, 0.19, others, runs);
      for (const Terrain::SurfaceRun& run : runs) {
        if (!run.passed) continue;
        for (int c = run.first_col; c <= run.last_col; ++c, ++passed_cells) {
          for (int t = 0; t < 2; ++t) {
            const std::array<Eigen::Vector3d, 3> own = corners(run.row, c, t);
            const Eigen::Vector3d q = detail::closestOnTriangle(o, own[0], own[1], own[2]).point;
            const double d = (q - o).norm();
            bool nearer = false;
            for (int rr = run.row - 1; rr <= run.row + 1 && !nearer; ++rr) {
              for (int cc = c - 1; cc <= c + 1 && !nearer; ++cc) {
                for (int tt = 0; tt < 2 && !nearer; ++tt) {
                  if (rr == run.row && cc == c && tt == t) continue;
                  const std::array<Eigen::Vector3d, 3> other = corners(rr, cc, tt);
                  if (!holds(other, q)) continue;
                  const Eigen::Vector3d p = detail::closestOnTriangle(o, other[0], other[1], other[2]).point;
                  nearer = (p - o).norm() < d;
                }
              }
            }
            ASSERT_TRUE(nearer) << "trial " << trial << ": cell (" << run.row << ", " << c << ") triangle " << t
                                << " holds a minimum " << d << " m from " << o.transpose();
          }
        }
      }
    }
  }
  EXPECT_GT(passed_cells, 10000);
}

// A wheel over a grid point of a flat field, its centre up to a micrometre
// off it: the closed forms of the six triangles there give points within
// the seam rule's gap of each other, their distances 1e-13 m apart. With a
// tie in the order (within the gap, the lower id first) two minima a
// roundoff apart could each be cut by one the other order put first: the
// wheel had no contact at all (the robot's first steps on a sampled ledge,
// and a loaded front wheel on its top, issue 53). One contact now, the
// prisms' deflection, at every offset and load.
TEST(FieldSurfaceTest, AWheelOverAGridPointKeepsItsContact) {
  Heightfield f;
  f.cols = 201, f.rows = 201;  // 4 m x 4 m of 2 cm cells, its grid points at -2 + 0.02 k
  f.spacing_x = f.spacing_y = 0.02;
  f.origin = {-2.0, -2.0, 0.0};
  f.base_depth = 0.5;
  f.heights.assign(static_cast<std::size_t>(f.rows) * f.cols, 0.0);
  TerrainBuilder builder;
  const MaterialId material = builder.addMaterial({});
  addCompactHeightfield(builder, std::move(f), material);
  const Terrain terrain = std::move(builder).build();
  const WheelGeometry wheel{.free_radius = 0.19, .tread_width = 0.12};
  ContactOptions per_prism;
  per_prism.field_surface = false;
  WheelContactFinder surface, prisms;
  for (const double depth : {1e-5, 3.7e-3}) {
    for (const double dx : {0.0, 1e-9, -1e-9, 2e-8, -2e-8, 1e-7, -1e-7, 2.6e-7, -2.6e-7, 1e-6, -1e-6}) {
      for (const double dy : {0.0, 2e-8, -2e-8, 4.2e-8, -4.2e-8}) {
        const WheelPose pose{.center = {-1.5 + dx, -2.0 + 114 * 0.02 + dy, 0.19 - depth}, .axle = {0.0, 1.0, 0.0}};
        const auto a = prisms.find(terrain, wheel, pose, per_prism);
        ASSERT_EQ(a.size(), 1u);
        const WheelContact expected = a[0];
        const auto b = surface.find(terrain, wheel, pose);
        ASSERT_EQ(b.size(), 1u) << "depth " << depth << ", dx " << dx << ", dy " << dy;
        EXPECT_NEAR(b[0].deflection, expected.deflection, 1e-12);
        EXPECT_LT((b[0].ground_point - expected.ground_point).norm(), 1e-6);  // one point, to the gap
        EXPECT_EQ(b[0].load_share, 1.0);
      }
    }
  }
}

// A centre inside the ground (a wheel pushed through it) is the per-prism
// path's, bit for bit: it knows the face the centre came in by.
TEST(FieldSurfaceTest, LeavesACentreInsideTheGroundToThePrisms) {
  const Terrain terrain = fineTerrain();
  const WheelGeometry wheel{.free_radius = 0.06, .tread_width = 0.05};
  ContactOptions per_prism;
  per_prism.field_surface = false;
  WheelContactFinder surface, prisms;
  for (double x = 0.3; x < 0.32; x += 0.004) {  // a few poses: a centre inside touches a disc of prisms
    const WheelPose pose{.center = {x, 0.0, relief(x, 0.0) - 0.01}, .axle = {0.0, 1.0, 0.0}};
    const auto a = prisms.find(terrain, wheel, pose, per_prism);
    const std::vector<WheelContact> expected(a.begin(), a.end());
    const auto b = surface.find(terrain, wheel, pose);
    EXPECT_EQ(surface.counts().surface, 0u);
    ASSERT_EQ(b.size(), expected.size());
    for (std::size_t i = 0; i < b.size(); ++i) {
      EXPECT_EQ(b[i].piece, expected[i].piece);
      EXPECT_EQ(b[i].ground_point, expected[i].ground_point);
      EXPECT_EQ(b[i].load_share, expected[i].load_share);
    }
  }
}

// Terrain::withinSurfaces's runs hold every piece Terrain::within finds
// (random balls over the field, its holes and beyond its edges).
TEST(FieldSurfaceTest, RunsHoldEveryPieceWithinTheReach) {
  const Terrain terrain = fineTerrain();
  const Heightfield& f = *terrain.compactField(0).field;
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> along(-0.2, 2.6), across(-0.6, 0.6), up(-0.4, 0.4), reach(0.005, 0.3);
  std::vector<PieceId> within, others, in_runs;
  std::vector<Terrain::SurfaceRun> runs;
  for (int trial = 0; trial < 2000; ++trial) {
    const Eigen::Vector3d p(along(gen), across(gen), up(gen));
    const double r = reach(gen);
    within.clear(), others.clear(), runs.clear(), in_runs.clear();
    terrain.within(p, r, within);
    terrain.withinSurfaces(p, r, others, runs);
    EXPECT_TRUE(others.empty());
    for (const Terrain::SurfaceRun& run : runs) {
      PieceId id = run.first_piece;
      for (int c = run.first_col; c <= run.last_col; ++c) {
        if (f.isHole(run.row, c)) continue;
        in_runs.push_back(id), in_runs.push_back(id + 1);
        id += 2;
      }
    }
    std::sort(in_runs.begin(), in_runs.end());
    for (const PieceId id : within) {
      ASSERT_TRUE(std::binary_search(in_runs.begin(), in_runs.end(), id)) << "trial " << trial << ", piece " << id;
    }
  }
}

// The cells of `runs` (row, column) whose boxes come within `reach` of `p`
// by the search's own test, sorted.
std::vector<std::array<int, 2>> cellsNear(const Heightfield& f, std::span<const Terrain::SurfaceRun> runs,
                                          const Eigen::Vector3d& p, double reach) {
  std::vector<std::array<int, 2>> cells;
  for (const Terrain::SurfaceRun& run : runs) {
    detail::forEachCellNear(f, run.row, run.first_col, run.last_col, run.first_piece, p, reach, [&](int c, PieceId) {
      cells.push_back({run.row, c});
    });
  }
  std::sort(cells.begin(), cells.end());
  return cells;
}

TEST(FieldSurfaceTest, KeptRunsHoldEveryCellTheSearchTestsFromAnywhereInTheirRoom) {
  const Terrain terrain = fineTerrain();
  const Heightfield& f = *terrain.compactField(0).field;
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> along(0.1, 2.3), across(-0.3, 0.3), unit(-1.0, 1.0), share(0.0, 1.0);
  std::vector<PieceId> others;
  std::vector<Terrain::SurfaceRun> kept, walked;
  int held = 0, kept_cells = 0, tested_cells = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const double x = along(gen), y = across(gen);
    const double reach = 0.05 + 0.25 * share(gen);
    // A room about a point 0-6 mm below a wheel resting on the ground.
    detail::RunsRoom room{
        {x, y, relief(x, y) + reach - 0.006 * share(gen)}, 0.05 * share(gen), 0.02 * share(gen), reach};
    kept.clear();
    terrain.surfaceRuns(room.centre, reach + std::hypot(room.across, room.down), kept);
    if (!detail::narrowRuns(terrain, kept, room)) continue;  // a passed cell: kept for no room
    // A centre near the room's floor and rim, where a cell the room misses
    // would show, in the room or just outside it (which runsHold turns away).
    const double angle = 3.14159 * unit(gen), out = 1.0 + 0.3 * unit(gen), below = 1.0 + 0.3 * unit(gen);
    const Eigen::Vector3d p = room.centre + Eigen::Vector3d(out * room.across * std::cos(angle),
                                                            out * room.across * std::sin(angle), -below * room.down);
    const double r = reach * (1.0 - 0.01 * share(gen));
    if (!detail::runsHold(room, p, r)) continue;
    ++held;
    others.clear(), walked.clear();
    terrain.withinSurfaces(p, r, others, walked);
    const std::vector<std::array<int, 2>> expected = cellsNear(f, walked, p, r);
    const std::vector<std::array<int, 2>> got = cellsNear(f, kept, p, r);
    ASSERT_EQ(got, expected) << "trial " << trial;
    for (const Terrain::SurfaceRun& run : kept) kept_cells += run.last_col - run.first_col + 1;
    tested_cells += static_cast<int>(expected.size());
  }
  // Many rooms hold, and the kept cells are not the whole disc.
  EXPECT_GT(held, 500);
  EXPECT_GT(tested_cells, 10000);
  EXPECT_LT(kept_cells, 8 * tested_cells);
}

// The field of fineTerrain and a second, far away (added after it: the
// first's pieces keep their ids): a wheel on it walks anew every call.
Terrain fineTerrainAndAnother() {
  TerrainBuilder builder;
  const MaterialId material = builder.addMaterial({});
  addCompactHeightfield(builder, sampledField(relief, static_cast<int>(std::lround(kCrackX / kSpacing))), material);
  Heightfield far;
  far.cols = far.rows = 3;
  far.spacing_x = far.spacing_y = 0.5;
  far.origin = {20.0, 20.0, 0.0};
  far.heights.assign(9, 0.0);
  addCompactHeightfield(builder, std::move(far), material);
  return std::move(builder).build();
}

TEST(FieldSurfaceTest, AWheelKeepingItsRunsMeetsTheGroundAsOneWalkingAnewEachCall) {
  const Terrain one = fineTerrain(), two = fineTerrainAndAnother();
  const WheelGeometry wheel{.free_radius = 0.19, .tread_width = 0.12};
  WheelContactFinder keeping, walking;
  // Rolling 1-8 mm a step, bobbing 0-24 mm into the ground (down as well
  // as up), over the crack's exposed cells and the kerb, with a jump back.
  int steps = 0, touched = 0;
  double x = 0.3;
  for (int k = 0; k < 700; ++k, ++steps) {
    x += k == 400 ? -0.5 : 0.001 * (4.5 + 3.5 * std::sin(0.07 * k));
    const double y = 0.1 * std::sin(3.0 * x);
    const WheelPose pose{.center = {x, y, relief(x, y) + 0.19 - 0.012 * (1.0 + std::sin(23.0 * x))},
                         .axle = {0.03, 1.0, 0.05}};
    const auto a = keeping.find(one, wheel, pose);
    const std::vector<WheelContact> got(a.begin(), a.end());
    const auto b = walking.find(two, wheel, pose);
    touched += !got.empty();
    ASSERT_EQ(got.size(), b.size()) << "x " << x;
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(got[i].piece, b[i].piece) << "x " << x;
      EXPECT_EQ(got[i].ground_point, b[i].ground_point) << "x " << x;
      EXPECT_EQ(got[i].deflection, b[i].deflection) << "x " << x;
      EXPECT_EQ(got[i].load_share, b[i].load_share) << "x " << x;
    }
    ASSERT_EQ(keeping.counts().surface, walking.counts().surface) << "x " << x;
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_GT(touched, steps / 2);
}

}  // namespace
}  // namespace wtc
