#pragma once
// Wheel-terrain contact generation (wheel-terrain model, sections 1-2):
// every piece near the wheel gives at most one contact, where the distance
// from the wheel centre O to the piece is below the free radius r_f.
//
// One call reads top to bottom:
//   candidate pieces (terrain index: boxes within r_f of O, Terrain::within;
//     a compact heightfield's interior as one surface, Terrain::withinSurfaces:
//     its triangles in closed form, a candidate only at a local minimum of
//     the distance, src/contact/field_surface.hpp)
//   -> point queries (modified GJK, max_distance = r_f, warm-started)
//   -> seam rule (drop contacts that are internal seams of the ground; a
//     surface's other touching triangles cut and cover as their prisms do)
//   -> tread filter (drop contacts on the cut caps of the truncated sphere)
//   -> optionally keep only the deepest.
//
// Seam rule. The ground is the union of its pieces. A contact from piece B
// whose ground point lies on or inside (within tolerance::kSeamGapRelative
// x r_f) another touching piece A nearer to O is not a local minimum of the
// distance to the union: it is an internal seam (two prisms of one flat
// ground) and is dropped. "Nearer" is the strict order on (distance, piece
// id), so the nearest contact always survives and ties keep one. Contacts at
// distinct places (a ledge's vertical face and the ground in front of it)
// are all kept. Between the two, the rule is continuous: B's load share is
// delta / L, clamped to [0, 1], where delta is how far B's ground point lies
// outside A and L = sqrt(2 r_f Z_B) the half-length of B's contact patch, so
// a concave crease between two nearly coplanar pieces (a heightfield's
// gentle valley) loads the wheel like the flat ground it nearly is, instead
// of doubling the load as soon as the crease is bent. A real edge (B's
// ground point on an edge or vertex of B that no other touching piece
// covers: a kerb's top edge, a crack's lip) is not a crease: it keeps at
// least min(1, clear / Z_B), where clear is how far it stands off the rest
// of the ground. See docs/wheel-contact.md for why this is exact on flat
// seams and ridges.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "wtc/geometry/point_query.hpp"
#include "wtc/terrain/terrain.hpp"

namespace wtc {

namespace detail {
/// A triangle of a compact heightfield's surface within a wheel's reach
/// and its point nearest the wheel centre (src/contact/field_surface.hpp).
struct SurfacePoint {
  Eigen::Vector3d point{Eigen::Vector3d::Zero()};
  double distance = 0.0;  ///< From the wheel centre (m).
  const Heightfield* field = nullptr;
  double base_z = 0.0;  ///< The field's base (m): its prisms' bottom.
  PieceId id = -1;      ///< The prism whose top it is.
  std::int32_t row = 0, col = 0;
  std::uint8_t triangle = 0, feature = 0;
  bool minimum = false;  ///< A local minimum: a contact.
};
/// A cell's two triangles' distances from the wheel centre (m), valid in
/// the search numbered `stamp`; and which of the six triangles around its
/// first sample comes first in the search's order, valid in the search
/// numbered `vertex_stamp`.
struct SurfaceSlot {
  double distance[2] = {0.0, 0.0};
  std::uint32_t stamp = 0, vertex_stamp = 0;
  bool exposed = false;  ///< Its prisms are queried as prisms.
  std::uint8_t vertex_first = 0;
};
/// Where a rolling wheel's centre may go while the runs it keeps hold
/// (src/contact/field_surface.hpp, runsHold): within `across` (m) of
/// `centre` horizontally and no more than `down` (m) below it, with a reach
/// of at most `reach` (m). `reach` is 0 when no runs are kept.
struct RunsRoom {
  Eigen::Vector3d centre{Eigen::Vector3d::Zero()};
  double across = 0.0, down = 0.0, reach = 0.0;
};
/// The finder's scratch for a field's surface: the triangles within the
/// reach, the runs of cells passed (no minimum on them: answered only when
/// asked), and a window of slots over the cells searched.
struct SurfaceScratch {
  std::vector<SurfacePoint> points;
  std::vector<Terrain::SurfaceRun> passed;
  Eigen::Vector3d centre{Eigen::Vector3d::Zero()};  ///< Of the last search (m).
  std::vector<SurfaceSlot> window;
  std::uint32_t stamp = 0;
  std::size_t triangles = 0;  ///< Answered in closed form by the last search.
};
}  // namespace detail

struct WheelGeometry {
  double free_radius = 0.19;  ///< r_f (m), > 0.
  double tread_width = 0.12;  ///< w (m), > 0; w >= 2 r_f makes a full sphere.
};

/// Throws InvalidInputError naming the field, its value and `where`.
/// Allocates nothing unless it throws (it runs every step).
void validate(const WheelGeometry& wheel, const char* where);

/// True when the unit direction `d` from the wheel centre meets a cut cap
/// rather than the tread: |r_f d . a| > w / 2, with `unit_axle` a. The tread
/// filter's test; the engine adapters apply it to their own contact normals
/// (the sign of d does not matter).
inline bool onCap(const WheelGeometry& wheel, const Eigen::Vector3d& d, const Eigen::Vector3d& unit_axle) {
  return std::abs(wheel.free_radius * d.dot(unit_axle)) > 0.5 * wheel.tread_width;
}

struct WheelPose {
  Eigen::Vector3d center{Eigen::Vector3d::Zero()};  ///< O (world, m).
  Eigen::Vector3d axle{Eigen::Vector3d::UnitY()};   ///< Axle direction a (world; normalised here).
};

struct ContactOptions {
  bool multiple_contacts = true;  ///< Off: only the deepest contact is kept.
  bool tread_truncation = true;   ///< Off: the wheel is a full sphere.
  bool seam_rule = true;          ///< Off: every touching piece gives a contact.
  /// A compact heightfield meets the wheel as one surface: its triangles
  /// answered in closed form, a contact where the distance to the surface
  /// has a local minimum (src/contact/field_surface.hpp), not a point query
  /// and a contact per prism before the seam rule. Off: per prism, for
  /// comparison (docs/terrain.md). Needs the seam rule.
  bool field_surface = true;
};

struct WheelContact {
  Eigen::Vector3d point{Eigen::Vector3d::Zero()};         ///< P = O + r_f e, on the undeformed tread (world, m).
  Eigen::Vector3d ground_point{Eigen::Vector3d::Zero()};  ///< Closest point of the piece (world, m).
  Eigen::Vector3d e{Eigen::Vector3d::UnitZ()};            ///< Unit, from O toward the ground.
  double deflection = 0.0;                                ///< Z = r_f - signed distance (m), > 0.
  double signed_distance = 0.0;                           ///< From O to the piece (m); < 0 inside.
  double load_share = 1.0;  ///< Fraction of this contact's normal force the wheel feels, (0, 1]: below 1 only
                            ///< next to a nearer piece at a shallow concave crease, or on an edge
                            ///< standing less than Z off the rest of the ground, or on the ground
                            ///< below a nearer such edge (seam rule).
  PieceId piece = -1;
  MaterialId material = -1;
};

/// What one call of WheelContactFinder::find did, stage by stage: the
/// pieces the index gave (their boxes come within r_f of O), the point
/// queries run on them (the others were put beyond the reach by their
/// corners without forming them: compact parts only), the pieces found
/// within the reach, and the contacts returned; `surface` counts the
/// triangles of compact heightfields answered in closed form (field_surface),
/// which are among the candidates but not queried, and touching when they
/// are a local minimum. Counted, not timed: a
/// query's cost is in docs/terrain.md.
struct ContactSearchCounts {
  std::size_t candidates = 0;
  std::size_t queried = 0;
  std::size_t touching = 0;
  std::size_t contacts = 0;
  std::size_t surface = 0;
};

/// Per-wheel state: scratch memory and warm-start caches, reused across
/// steps so that a step allocates nothing once warmed up.
class WheelContactFinder {
 public:
  /// Reserves the scratch memory a step needs (see wtc/scratch_capacity.hpp).
  WheelContactFinder();

  /// The contacts of `wheel` at `pose`, valid until the next call. Throws
  /// InvalidInputError for a non-finite pose, a zero axle or invalid
  /// geometry.
  std::span<const WheelContact> find(const Terrain& terrain, const WheelGeometry& wheel, const WheelPose& pose,
                                     const ContactOptions& options = {});

  /// Candidate pieces of the last call (for diagnostics and benchmarks).
  std::span<const PieceId> candidates() const { return candidates_; }
  /// The stages of the last call (for diagnostics and benchmarks).
  const ContactSearchCounts& counts() const { return counts_; }

  /// The contacts of the last call that the tread filter dropped: the ground
  /// touches a cut cap (a wheel cambered beyond asin(w / 2 r_f) against its
  /// ground, or lying on its side). They carry no tyre force; an engine
  /// adapter can let the engine collide the caps (a rigid cylinder of radius
  /// sqrt(r_f^2 - (w/2)^2) and width w) there, so that a fallen wheel does
  /// not sink (docs/wheel-contact.md). After a call with cap contacts, the
  /// next reports them out to r_f (1 + kCapHysteresisRelative).
  std::span<const WheelContact> capContacts() const { return caps_; }

 private:
  // The compact heightfields' runs about centre `o` for `reach` (m) into
  // surface_runs_, and the other pieces within the reach into candidates_:
  // a rolling wheel's kept runs when they hold, else walked anew.
  void readSurfaceRuns(const Terrain& terrain, const Eigen::Vector3d& o, double reach);
  // The room (relative to r_f) a wheel's kept runs give its centre,
  // across and down (RunsRoom): a rolling wheel moves 1-5 mm a step, a
  // little of it down; each millimetre of room down widens the cells kept
  // as much as several across (docs/terrain.md measures both).
  static constexpr double kRunsAcrossRelative = 0.03;
  static constexpr double kRunsDownRelative = 0.003;
  // The seam rule's parts; a contact is named by its index in contacts_
  // (and contact_pieces_), before the rule erases any.
  void applySeamRule(double gap, double radius);
  bool onAnEdge(std::size_t b, double gap) const;
  double realEdgeClearance(std::size_t b, double gap);
  double groundThroughEdge(std::size_t a, double gap);
  static constexpr double kNotMeasured = -1.0;  // through_edge_ before groundThroughEdge measures it (m)
  // The field surfaces' triangles touching the wheel that are not contacts
  // (not local minima) still shape the seam rule as the prisms under them
  // did: they cut farther contacts and cover seams (shadows). Whether one is
  // such a shadow nearer than contact b, or farther; its prism's exact
  // distance from `p` (m), for a real edge's clearance.
  bool shadowNearer(const detail::SurfacePoint& s, const WheelContact& b) const;
  bool onSurface(PieceId id) const;  // a contact of this call's local minima
  double shadowDistance(const detail::SurfacePoint& s, const Eigen::Vector3d& p);
  double radius_ = 0.0;  // r_f of this call (m): the shadows are the touching triangles
  void exitWhereEntered(const ConvexPolyhedron& piece, PieceId id, const Eigen::Vector3d& centre, double radius,
                        WheelContact& c);
  std::vector<PieceId> candidates_;
  // A compact heightfield's surface (field_surface): its triangles within the
  // reach, and the local minima among them.
  std::vector<Terrain::SurfaceRun> surface_runs_;
  detail::SurfaceScratch surface_;
  std::vector<detail::SurfacePoint> touches_;
  std::vector<std::size_t> shadows_;                  // the seam rule's shadows: their places in surface_.points
  const Terrain* terrain_ = nullptr;                  // of this call, for a shadow's exact distance
  std::optional<ConvexPolyhedron> shadow_piece_;      // a shadow prism formed for it
  ContactSearchCounts counts_;
  std::vector<WheelContact> contacts_, caps_;
  std::vector<std::pair<PieceId, QueryCache>> caches_, next_caches_;
  std::vector<double> shares_;
  std::vector<std::size_t> rank_;  // the seam rule's order: contacts_ indices, nearest first
  std::vector<double> through_edge_;  // per contact of this call: groundThroughEdge's answer, or kNotMeasured
  std::vector<std::uint8_t> uncovered_;  // per contact of this call: no other contact covers its ground point
  // The piece of each of this call's contacts (contacts_ order: stored, or
  // formed and kept in formed_), and the pieces formed for this call's
  // candidates (compact parts'), kept for the next call. Held by
  // pointer: a kept prism moves from call to call as one pointer, not as
  // its dozen buffers; the prisms dropped wait in spare_ to be formed into
  // again. Shared, so that a copied finder shares its formed prisms (never
  // changed while shared: only a spare held by no one else is reused).
  std::vector<const ConvexPolyhedron*> contact_pieces_;
  std::vector<std::pair<PieceId, std::shared_ptr<ConvexPolyhedron>>> formed_, next_formed_;
  std::vector<std::shared_ptr<ConvexPolyhedron>> spare_;
  // The centre of the last call, and for each piece the centre was inside
  // then, the outward normal of the face it was pushed out by.
  Eigen::Vector3d previous_centre_{Eigen::Vector3d::Zero()};
  bool has_previous_ = false;
  bool caps_last_ = false;  // the last call saw the ground at a cap
  std::vector<std::pair<PieceId, Eigen::Vector3d>> exits_, next_exits_;
  // What the calls keep (the pieces formed, the caches, the exits, the
  // runs) holds for the terrain of this serial (Terrain::serial).
  std::uint64_t terrain_serial_ = 0;
  // A rolling wheel's walk (issue 53): surface_runs_ hold the cells of the
  // terrain's one compact heightfield whose boxes come within the reach of
  // some point of runs_room_ (none passed), read again while the centre
  // stays in the room (detail::runsHold); its reach is 0 when they hold for
  // this call only. keep_runs_: the last walk passed no cell, so the next
  // is walked to be kept.
  detail::RunsRoom runs_room_;
  bool keep_runs_ = true;
};

}  // namespace wtc
