#include "field_surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>

#include "geometry/triangle_closest_point.hpp"
#include "terrain/field_cells.hpp"
#include "wtc/terrain/heightfield.hpp"

namespace wtc::detail {

namespace {

using Run = Terrain::SurfaceRun;

// A triangle named by its cell and its half: 0 (p00, p01, p11), 1 (p00,
// p11, p10), closestOnTriangle's corners a, b, c in that order.
struct Cell {
  int row, col, t;
};

// The sample (row, col) at corner `corner` (0 a, 1 b, 2 c) of a triangle.
std::array<int, 2> cornerSample(const Cell& x, int corner) {
  if (corner == 0) return {x.row, x.col};
  if (corner == 1) return x.t == 0 ? std::array<int, 2>{x.row, x.col + 1} : std::array<int, 2>{x.row + 1, x.col + 1};
  return x.t == 0 ? std::array<int, 2>{x.row + 1, x.col + 1} : std::array<int, 2>{x.row + 1, x.col};
}

// The triangle across edge `edge` (0: ab, 1: bc, 2: ca).
Cell acrossEdge(const Cell& x, int edge) {
  if (x.t == 0) {
    if (edge == 0) return {x.row - 1, x.col, 1};  // p00 p01: the cell below's (p11, p10)
    if (edge == 1) return {x.row, x.col + 1, 1};  // p01 p11: the next cell's (p10, p00)
    return {x.row, x.col, 1};                     // the diagonal
  }
  if (edge == 0) return {x.row, x.col, 0};      // the diagonal
  if (edge == 1) return {x.row + 1, x.col, 0};  // p11 p10: the cell above's (p01, p00)
  return {x.row, x.col - 1, 0};                 // p10 p00: the previous cell's (p11, p01)
}

// The six triangles around sample (i, j).
std::array<Cell, 6> aroundSample(int i, int j) {
  return {{{i, j, 0}, {i, j, 1}, {i, j - 1, 0}, {i - 1, j - 1, 0}, {i - 1, j - 1, 1}, {i - 1, j, 1}}};
}

// Cell (r, c) or one of its eight neighbours is a hole or beyond the field:
// its prisms' walls may be ground. Every other wall is a neighbour's too,
// bit for bit, inside the ground.
bool exposed(const Heightfield& f, int r, int c) {
  if (r == 0 || c == 0 || r + 2 >= f.rows || c + 2 >= f.cols) return true;
  if (f.cell_holes.empty()) return false;
  for (int dr = -1; dr <= 1; ++dr) {
    for (int dc = -1; dc <= 1; ++dc) {
      if (f.isHole(r + dr, c + dc)) return true;
    }
  }
  return false;
}

// True when the centre is above the part's base and, over a ground cell,
// above its surface by more than `tie` (m).
bool above(const Terrain::CompactField& compact, const Eigen::Vector3d& o, double tie) {
  if (!(o.z() > compact.bounds.min.z())) return false;
  const std::optional<double> surface = surfaceHeight(*compact.field, o.x(), o.y());  // none beyond it or over a hole
  return !surface || o.z() > *surface + tie;
}

// The two triangles of cell (r, c) answered for the centre `o` (inlined:
// a search answers dozens a step).
[[gnu::always_inline]] inline std::array<TriangleClosestPoint, 2> answerCell(const Heightfield& f, int r, int c,
                                                                             const Eigen::Vector3d& o) {
  const Eigen::Vector3d p00 = f.sample(r, c), p01 = f.sample(r, c + 1);
  const Eigen::Vector3d p10 = f.sample(r + 1, c), p11 = f.sample(r + 1, c + 1);
  return {closestOnTriangle(o, p00, p01, p11), closestOnTriangle(o, p00, p11, p10)};
}

// The first prism of cell (r, c) if a run of `passed` (row-major) holds it.
std::optional<PieceId> passedCell(std::span<const Run> passed, int r, int c) {
  auto run = std::lower_bound(passed.begin(), passed.end(), r, [](const Run& x, int row) { return x.row < row; });
  for (; run != passed.end() && run->row == r; ++run) {
    if (run->first_col <= c && c <= run->last_col) return run->first_piece + 2 * (c - run->first_col);
  }
  return std::nullopt;
}

// A cell of `passed` tested as a searched cell is (its box within the
// reach, the same sums) and answered into `slot`; false when no run holds
// it or it lies beyond the reach. Out of line: most searches ask none.
[[gnu::noinline]] bool testPassed(const Heightfield& f, std::span<const Run> passed, int r, int c,
                                  const Eigen::Vector3d& o, double reach, SurfaceSlot& slot) {
  const std::optional<PieceId> id = passedCell(passed, r, c);
  if (!id) return false;
  bool near = false;
  forEachCellNear(f, r, c, c, *id, o, reach, [&](int, PieceId) { near = true; });
  if (!near) return false;
  const std::array<TriangleClosestPoint, 2> q = answerCell(f, r, c, o);
  slot.exposed = false;
  for (int t = 0; t < 2; ++t) slot.distance[t] = (q[t].point - o).norm();
  return true;
}

}  // namespace

bool surfaceLocalMinima(const Terrain& terrain, std::span<const Run> runs, const Eigen::Vector3d& o, double reach,
                        double tie, SurfaceScratch& scratch, std::vector<PieceId>& prisms,
                        std::vector<SurfacePoint>& touches) {
  scratch.points.clear();
  scratch.passed.clear();
  scratch.centre = o;
  scratch.triangles = 0;
  for (std::size_t begin = 0; begin < runs.size();) {
    const int part = runs[begin].part;
    std::size_t end = begin;
    int c_min = runs[begin].first_col, c_max = runs[begin].last_col;
    for (; end < runs.size() && runs[end].part == part; ++end) {
      c_min = std::min(c_min, runs[end].first_col), c_max = std::max(c_max, runs[end].last_col);
    }
    const std::span<const Run> own = runs.subspan(begin, end - begin);
    begin = end;
    const Terrain::CompactField compact = terrain.compactField(static_cast<std::size_t>(part));
    const Heightfield& f = *compact.field;
    // On or below the surface: the per-prism path, which knows the face
    // the centre came in by.
    if (!above(compact, o, tie)) return false;

    // The window: the runs' rows by their columns' span, and a border of
    // one cell all round that no search stamps, where a neighbour's look
    // finds no slot without a bounds test (neighbours are at most a cell off).
    const int r_min = own.front().row, r_max = own.back().row;
    const std::size_t cells = static_cast<std::size_t>(r_max - r_min + 1) * static_cast<std::size_t>(c_max - c_min + 1);
    if (cells > kMaxSurfaceWindowCells) return false;
    const auto width = static_cast<std::size_t>(c_max - c_min + 3);
    const std::size_t slots = static_cast<std::size_t>(r_max - r_min + 3) * width;
    if (scratch.window.size() < slots) scratch.window.resize(slots);
    if (++scratch.stamp == 0) {  // wrapped: no slot may look current
      for (SurfaceSlot& slot : scratch.window) slot.stamp = 0, slot.vertex_stamp = 0;
      scratch.stamp = 1;
    }
    const std::uint32_t stamp = scratch.stamp;
    const auto slot = [&](int r, int c) -> SurfaceSlot& {
      return scratch.window[static_cast<std::size_t>(r - r_min + 1) * width + static_cast<std::size_t>(c - c_min + 1)];
    };

    // Each run's cells: the cell's box, then its two triangles.
    const double base_z = compact.bounds.min.z();
    const std::size_t first_point = scratch.points.size(), first_passed = scratch.passed.size();
    for (const Run& run : own) {
      if (run.passed) {  // no minimum there: answered when asked
        scratch.passed.push_back(run);
        continue;
      }
      const int r = run.row;
      forEachCellNear(f, r, run.first_col, run.last_col, run.first_piece, o, reach, [&](int c, PieceId cell_id) {
        const std::array<TriangleClosestPoint, 2> q = answerCell(f, r, c, o);
        scratch.triangles += 2;
        SurfaceSlot& s = slot(r, c);
        s.stamp = stamp;
        const bool walls = exposed(f, r, c);
        s.exposed = walls;
        for (int t = 0; t < 2; ++t) {
          const double d = (q[t].point - o).norm();
          s.distance[t] = d;
          if (walls) {
            // A prism with ground walls: queried as a prism when its box
            // comes within the reach (Terrain::within's test).
            if (prismBoxWithin(f, r, c, t, base_z, o, reach)) prisms.push_back(cell_id + t);
          } else if (d < reach) {
            scratch.points.push_back({q[t].point, d, &f, base_z, cell_id + t, r, c, static_cast<std::uint8_t>(t),
                                      static_cast<std::uint8_t>(q[t].feature)});
          }
        }
      });
    }

    // A triangle's slot, none beyond the reach (a cell not tested). A
    // passed cell is tested, and answered, when first asked: with the same
    // test, on the same sums, as a searched one.
    const std::span<const Run> passed = std::span<const Run>(scratch.passed).subspan(first_passed);
    const auto tested = [&](const Cell& n) -> const SurfaceSlot* {
      SurfaceSlot& s = slot(n.row, n.col);
      if (s.stamp == stamp) return &s;
      if (passed.empty() || !testPassed(f, passed, n.row, n.col, o, reach, s)) return nullptr;
      s.stamp = stamp;
      scratch.triangles += 2;
      return &s;
    };
    // Of the six triangles around sample (i, j), in id order (i - 1, j - 1,
    // 0), (i - 1, j - 1, 1), (i - 1, j, 1), (i, j - 1, 0), (i, j, 0), (i,
    // j, 1), the one first in the order (distance, id) among those tested,
    // or kExposedAround when one is exposed; once a sample, however many
    // triangles have their closest point there (most of a rough patch's
    // do). Without passed runs only: a passed cell is answered when a
    // triangle's own test asks for it, and only then.
    constexpr std::uint8_t kExposedAround = 0xff;
    const auto firstAround = [&](int i, int j) {
      SurfaceSlot& v = slot(i, j);
      if (v.vertex_stamp == stamp) return v.vertex_first;
      const SurfaceSlot* below = &v - width;
      const std::array<const SurfaceSlot*, 6> cell{below - 1, below - 1, below, &v - 1, &v, &v};
      constexpr std::array<int, 6> half{0, 1, 1, 0, 0, 1};
      std::uint8_t first = kExposedAround;
      double nearest = std::numeric_limits<double>::infinity();
      for (std::uint8_t k = 0; k < 6; ++k) {
        if (cell[k]->stamp != stamp) continue;
        if (cell[k]->exposed) {
          first = kExposedAround;
          break;
        }
        const double d = cell[k]->distance[half[k]];
        if (d < nearest) nearest = d, first = k;
      }
      v.vertex_stamp = stamp, v.vertex_first = first;
      return first;
    };
    for (std::size_t k = first_point; k < scratch.points.size(); ++k) {
      SurfacePoint& a = scratch.points[k];
      const Cell self{a.row, a.col, a.triangle};
      // First in the one strict order the seam rule ranks by too: nearer,
      // or as near and first in id order (row, column, half). An exposed
      // prism, queried as a prism (GJK's roundoff), takes a point it shares
      // to within `tie`. No tie between two triangles of the surface: with
      // one, two minima a roundoff apart at one point could each be cut by
      // something the other order put first, and a wheel on a grid point
      // lost its contact (issue 53); in a strict order the first point is
      // always a minimum and nothing comes before it.
      const auto beats = [&](const Cell& n) {
        const SurfaceSlot* s = tested(n);
        if (s == nullptr) return false;
        const double d = s->distance[n.t];
        if (s->exposed && std::abs(d - a.distance) <= tie) return true;
        return d < a.distance ||
               (d == a.distance && std::tie(n.row, n.col, n.t) < std::tie(self.row, self.col, self.t));
      };
      bool dominated = false;
      switch (static_cast<TriangleFeature>(a.feature)) {
        case TriangleFeature::kFace:
          break;
        case TriangleFeature::kEdgeAB:
          dominated = beats(acrossEdge(self, 0));
          break;
        case TriangleFeature::kEdgeBC:
          dominated = beats(acrossEdge(self, 1));
          break;
        case TriangleFeature::kEdgeCA:
          dominated = beats(acrossEdge(self, 2));
          break;
        default: {
          const int corner = a.feature - static_cast<int>(TriangleFeature::kVertexA);
          const std::array<int, 2> s = cornerSample(self, corner);
          if (passed.empty()) {
            // The strict order's first of the six, unless one is exposed.
            const std::uint8_t first = firstAround(s[0], s[1]);
            if (first != kExposedAround) {
              const int own = self.row < s[0] ? (self.col < s[1] ? self.t : 2) : (self.col < s[1] ? 3 : 4 + self.t);
              dominated = first != own;
              break;
            }
          }
          for (const Cell& n : aroundSample(s[0], s[1])) {
            if ((n.row != self.row || n.col != self.col || n.t != self.t) && beats(n)) {
              dominated = true;
              break;
            }
          }
        }
      }
      if (dominated) continue;
      a.minimum = true;
      touches.push_back(a);  // row-major: in id order
    }
  }
  return true;
}

void passedShadows(const Terrain& terrain, const SurfaceScratch& scratch, std::span<const WheelContact> contacts,
                   std::span<const std::uint8_t> uncovered, double radius, double gap, std::vector<SurfacePoint>& out) {
  const Eigen::Vector3d& o = scratch.centre;
  // A contact b reads a shadow's prism through its plane bound at b's
  // ground point, less the gap (`outside`, m): a cut below b's patch
  // sqrt(2 r Z_b) from a shadow no farther from O than b (plus the gap),
  // coverage at or below 0, a real edge's clearance below Z_b (the last
  // two only when no other contact covers b). Beside a cell by `beside`
  // (m) that bound is at least besideBound(beside), and
  // no triangle of a box lies nearer to O than the box (`nearest`, asked
  // only when needed).
  const Heightfield* field = nullptr;
  const auto matters = [&](double x0, double x1, double y0, double y1, const auto& nearest) {
    double near = -1.0;
    for (std::size_t k = 0; k < contacts.size(); ++k) {
      const WheelContact& b = contacts[k];
      const Eigen::Vector3d& p = b.ground_point;
      const double outside = besideBound(*field, std::max({x0 - p.x(), p.x() - x1, y0 - p.y(), p.y() - y1})) - gap;
      if (uncovered[k] != 0 && outside < b.deflection) return true;
      if (outside < std::sqrt(2.0 * radius * b.deflection)) {
        if (near < 0.0) near = nearest();
        if (near <= b.signed_distance + gap) return true;
      }
    }
    return false;
  };
  int part = -1;
  double base_z = 0.0;
  for (const Run& run : scratch.passed) {
    if (run.part != part) {
      part = run.part;
      const Terrain::CompactField compact = terrain.compactField(static_cast<std::size_t>(part));
      field = compact.field, base_z = compact.bounds.min.z();
    }
    const Heightfield& f = *field;
    const auto x = [&](int i) { return f.origin.x() + i * f.spacing_x; };  // as sample() computes them
    const auto y = [&](int i) { return f.origin.y() + i * f.spacing_y; };
    const int r = run.row;
    // The distance from O of the box of cells lo ... hi.
    const auto box = [&](int lo, int hi) {
      return [&f, &o, &x, &y, r, lo, hi] {
        double top = f.height(r, lo);
        for (int c = lo; c <= hi + 1; ++c) top = std::max({top, f.height(r, c), f.height(r + 1, c)});
        const double dx = std::max({0.0, x(lo) - o.x(), o.x() - x(hi + 1)});
        const double dy = std::max({0.0, y(r) - o.y(), o.y() - y(r + 1)});
        const double dz = std::max(0.0, o.z() - (f.origin.z() + top));
        return std::sqrt(dx * dx + dy * dy + dz * dz);
      };
    };
    if (!matters(x(run.first_col), x(run.last_col + 1), y(r), y(r + 1), box(run.first_col, run.last_col))) continue;
    for (int c = run.first_col; c <= run.last_col; ++c) {
      if (!matters(x(c), x(c + 1), y(r), y(r + 1), box(c, c))) continue;
      const std::array<TriangleClosestPoint, 2> q = answerCell(f, r, c, o);
      const PieceId id = run.first_piece + 2 * (c - run.first_col);
      for (int t = 0; t < 2; ++t) {
        const double d = (q[t].point - o).norm();
        if (d < radius) {  // a cell beyond the reach has none
          out.push_back({q[t].point, d, &f, base_z, id + t, r, c, static_cast<std::uint8_t>(t),
                         static_cast<std::uint8_t>(q[t].feature)});
        }
      }
    }
  }
}

bool runsKeep(const Terrain& terrain, double runs_reach) {
  if (terrain.compactFieldCount() != 1) return false;
  const Heightfield* f = terrain.compactField(0).field;
  if (f == nullptr) return true;  // a mesh: no runs
  // A reach's cube spans at most 2 reach / spacing + 1 cells a side, and
  // a cell more each side at most: the largest window a search may open.
  const double side = 2.0 * runs_reach / std::min(f->spacing_x, f->spacing_y) + 3.0;
  return side * side <= static_cast<double>(kMaxSurfaceWindowCells);
}

bool narrowRuns(const Terrain& terrain, std::vector<Run>& runs, const RunsRoom& room) {
  if (std::any_of(runs.begin(), runs.end(), [](const Run& run) { return run.passed; })) return false;
  // A centre p in the room is within `across` of its centre horizontally
  // and above its floor: a box's distance from p is at least
  // max(0, horizontal - across) and max(0, floor - top) along the two
  // axes, so a cell the search keeps for p (forEachCellNear) passes this
  // test, which keeps a margin far above the roundoff of either.
  const Eigen::Vector3d& a = room.centre;
  const double floor = a.z() - room.down;
  const double slack2 = (room.reach * room.reach * (1.0 + kCellSlack) + kCellSlack) * (1.0 + kCellSlack);
  std::size_t out = 0;
  for (const Run& run : runs) {
    const Heightfield& f = *terrain.compactField(static_cast<std::size_t>(run.part)).field;
    const double dy = rowDistance(f, run.row, a.y());
    Run narrowed = run;
    narrowed.first_col = run.last_col + 1;
    forEachCellBox(f, run.row, run.first_col, run.last_col, run.first_piece,
                   [&](int c, PieceId id, double x0, double x1, double top) {
                     const double dx = std::max({0.0, x0 - a.x(), a.x() - x1});
                     const double h = std::max(0.0, std::sqrt(dx * dx + dy * dy) - room.across);
                     const double v = std::max(0.0, floor - top);
                     if (h * h + v * v > slack2) return;
                     if (c < narrowed.first_col) narrowed.first_col = c, narrowed.first_piece = id;
                     narrowed.last_col = c;
                   });
    if (narrowed.first_col <= narrowed.last_col) runs[out++] = narrowed;
  }
  runs.resize(out);
  return true;
}

bool runsHold(const RunsRoom& room, const Eigen::Vector3d& centre, double reach) {
  const Eigen::Vector3d& a = room.centre;
  const double roundoff = 1e-12 * (1.0 + a.cwiseAbs().maxCoeff() + room.reach);
  return reach <= room.reach && (centre - a).head<2>().norm() <= room.across - roundoff &&
         centre.z() >= a.z() - room.down + roundoff;
}

double prismPlaneBound(const SurfacePoint& s, const Eigen::Vector3d& p, double enough) {
  const Heightfield& f = *s.field;
  const int r = s.row, c = s.col;
  const double x0 = f.origin.x() + c * f.spacing_x, y0 = f.origin.y() + r * f.spacing_y;  // as sample() has them
  const double dx = p.x() - x0, dy = p.y() - y0;
  // The base and the three walls (the cell's two sides the triangle
  // spans, and the diagonal; the triangle counter-clockwise seen from
  // above, each wall's normal the edge's direction turned clockwise).
  const double length = std::sqrt(f.spacing_x * f.spacing_x + f.spacing_y * f.spacing_y);  // the diagonal's (m)
  const double beside = std::max({x0 - p.x(), dx - f.spacing_x, y0 - p.y(), dy - f.spacing_y});
  if (beside * std::min(f.spacing_x, f.spacing_y) > enough * (length + std::max(f.spacing_x, f.spacing_y))) {
    return besideBound(f, beside);
  }
  const double diagonal = (f.spacing_y * dx - f.spacing_x * dy) / length;
  double bound = s.base_z - p.z();
  if (s.triangle == 0) {  // (p00, p01, p11): the walls y = y0, x = x1 and the diagonal, outward up-left
    bound = std::max({bound, y0 - p.y(), p.x() - (f.origin.x() + (c + 1) * f.spacing_x), -diagonal});
  } else {  // (p00, p11, p10): x = x0, y = y1 and the diagonal, outward down-right
    bound = std::max({bound, x0 - p.x(), p.y() - (f.origin.y() + (r + 1) * f.spacing_y), diagonal});
  }
  if (bound > enough) return bound;
  // The top.
  const Cell cell{r, c, s.triangle};
  const std::array<int, 2> ia = cornerSample(cell, 0), ib = cornerSample(cell, 1), ic = cornerSample(cell, 2);
  const Eigen::Vector3d a = f.sample(ia[0], ia[1]);
  const Eigen::Vector3d n = (f.sample(ib[0], ib[1]) - a).cross(f.sample(ic[0], ic[1]) - a).normalized();
  return std::max(bound, n.dot(p - a));
}

}  // namespace wtc::detail
