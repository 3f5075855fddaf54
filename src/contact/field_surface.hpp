#pragma once
// A compact heightfield met as one surface (internal to wtc::core; issue 53).
//
// The ground a heightfield makes is the union of its prisms. Away from its
// edges and holes every prism's walls are its neighbours' walls too, inside
// the ground, so seen from a point above the surface the ground is the
// surface itself, a mesh of triangles. Where the ground touches a wheel is
// where the distance from the wheel centre O to that surface has a local
// minimum: one on a smooth patch (its deepest point), one more for every
// kerb's edge, crack's lip or second face of a crease.
//
// Each triangle's closest point is found in closed form
// (triangle_closest_point.hpp). Triangle T's closest point q is a local
// minimum unless a triangle that also holds q (its neighbour across the edge
// q lies on, or one of the six around the vertex q is) is nearer to O:
// the distance on that triangle then falls away from q. "Nearer" is one
// strict order, (distance, id), the seam rule's too: of triangles holding
// one q (the same edge point or vertex) at distances a roundoff apart, the
// first in it is kept, and the first of all is always a contact.
//
// These local minima are exactly the per-prism contacts that the seam rule
// keeps: a prism whose closest point is not one lies on a nearer prism and
// is dropped (share 0) by it. Only the seam rule's partial shares can
// differ, as the dropped contacts no longer cut the kept ones (a concave
// crease's second face): docs/terrain.md measures it.
//
// Exposed cells (a hole or the field's edge within one cell: walls that are
// ground) and a centre inside the ground are left to the per-prism path.
//
// The cells come as runs along rows (Terrain::withinSurfaces); each cell's
// box is tested first (most of a disc's cells lie below the reach), and the
// two distances of each cell tested are kept in a window over the runs'
// cells, where a triangle finds its neighbours'. A passed run
// (SurfaceRun::passed: cells where the distance falls away everywhere,
// src/terrain/field_cells.hpp) holds no minimum: its cells are tested and
// answered only when a neighbour's test asks for them, and the seam rule
// asks for those that could change a share (passedShadows).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "wtc/contact/wheel_contact.hpp"
#include "wtc/terrain/heightfield.hpp"
#include "wtc/terrain/terrain.hpp"

namespace wtc::detail {

/// The local minima within `reach` (m) of `centre` on the compact
/// heightfields' surfaces, from Terrain::withinSurfaces's `runs` for the
/// same centre and reach: appended to `touches` in id order; an exposed
/// prism takes a point it shares to within `tie` (m). The pieces of exposed
/// cells whose boxes come within the reach go to `prisms`, to be queried as
/// prisms. False
/// when the centre is inside or below a part's ground, or the runs span
/// more than kMaxSurfaceWindowCells cells: the per-prism path answers then
/// (what was appended is to be dropped).
bool surfaceLocalMinima(const Terrain& terrain, std::span<const Terrain::SurfaceRun> runs,
                        const Eigen::Vector3d& centre, double reach, double tie, SurfaceScratch& scratch,
                        std::vector<PieceId>& prisms, std::vector<SurfacePoint>& touches);

/// The seam rule's shadows on the cells the last search passed
/// (scratch.passed, for scratch.centre): the triangles nearer than `radius`
/// (m) of each passed cell that could change a share the rule gives
/// `contacts` (WheelContactFinder::applySeamRule, with its `gap`, m),
/// appended to `out`. uncovered[k]: no other contact covers contact k's
/// ground point (only then does a shadow's coverage or clearance count).
void passedShadows(const Terrain& terrain, const SurfaceScratch& scratch, std::span<const WheelContact> contacts,
                   std::span<const std::uint8_t> uncovered, double radius, double gap, std::vector<SurfacePoint>& out);

/// The plane bound (ConvexPolyhedron::planeBound, m) at `p` of the prism
/// whose top is `s`'s triangle, from the field's samples; any value above
/// `enough` (m) once the base and the walls pass it.
double prismPlaneBound(const SurfacePoint& s, const Eigen::Vector3d& p,
                       double enough = std::numeric_limits<double>::infinity());

/// Whether the prism of one of `shadows` (places in `points`) that
/// `consider` accepts covers `p`: its plane bound (prismPlaneBound) at p is
/// within `gap` (m). An "or", the same in any order, so the shadows on the
/// cells around p's come first: a prism that covers p stands there, and
/// most points asked about (a minimum at a sample) have one; the rest only
/// when none of those does.
template <typename Consider>
bool shadowsCover(std::span<const SurfacePoint> points, std::span<const std::size_t> shadows, const Eigen::Vector3d& p,
                  double gap, Consider&& consider) {
  const Heightfield* field = nullptr;
  double row = 0.0, col = 0.0;  // p's place on `field`, in cells
  const auto around = [&](const SurfacePoint& s) {
    if (s.field != field) {
      field = s.field;
      col = (p.x() - field->origin.x()) / field->spacing_x, row = (p.y() - field->origin.y()) / field->spacing_y;
    }
    return std::abs(col - (s.col + 0.5)) < 1.5 && std::abs(row - (s.row + 0.5)) < 1.5;
  };
  for (const bool first : {true, false}) {
    for (const std::size_t k : shadows) {
      const SurfacePoint& s = points[k];
      if (around(s) != first || !consider(s)) continue;
      if (prismPlaneBound(s, p, gap) - gap <= 0.0) return true;
    }
  }
  return false;
}

/// The least plane bound (m) of a prism of field `f` at a point `beside`
/// (m) beside its cell (the largest of the point's distances out past the
/// cell's four sides): one wall stands at least
/// beside min(sx, sy) / (diagonal + max(sx, sy)) off the point.
inline double besideBound(const Heightfield& f, double beside) {
  const double length = std::sqrt(f.spacing_x * f.spacing_x + f.spacing_y * f.spacing_y);  // the diagonal's (m)
  return beside * std::min(f.spacing_x, f.spacing_y) / (length + std::max(f.spacing_x, f.spacing_y));
}

/// Whether a wheel may keep its runs for `runs_reach` (m) on `terrain`
/// (WheelContactFinder): it has one compact part, and the part's cells are
/// not too fine for the search's window (kMaxSurfaceWindowCells) to hold
/// every cell that reach may span, so that no search ever hands the centre
/// to the prisms for the window's size, whichever runs it reads.
bool runsKeep(const Terrain& terrain, double runs_reach);

/// A rolling wheel's runs (WheelContactFinder): `runs`, from
/// Terrain::surfaceRuns about room.centre for room.reach plus the room's
/// diagonal, narrowed to the cells whose boxes come within room.reach of
/// some point of the room (horizontally within room.across, vertically
/// from room.down below to any height); false, the runs left as they were,
/// when one of them is passed (whether a cell passes depends on the centre).
bool narrowRuns(const Terrain& terrain, std::vector<Terrain::SurfaceRun>& runs, const RunsRoom& room);

/// Whether narrowRuns's runs for `room` hold every cell whose box comes
/// within `reach` (m) of `centre`, as the search's cell test decides: the
/// centre is in the room, by more than roundoff, and the reach no wider.
bool runsHold(const RunsRoom& room, const Eigen::Vector3d& centre, double reach);

/// Cells of the largest window of distances a search keeps (32 bytes a
/// cell): a 0.19 m wheel on a 1 mm field spans 145,000.
inline constexpr std::size_t kMaxSurfaceWindowCells = std::size_t{1} << 18;

}  // namespace wtc::detail
