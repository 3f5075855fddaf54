#include "wtc/contact/wheel_contact.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "base/scratch_capacity.hpp"
#include "field_surface.hpp"
#include "wtc/base/checks.hpp"
#include "wtc/base/error.hpp"

namespace wtc {

void validate(const WheelGeometry& wheel, const char* where) {
  requireLength(wheel.free_radius, where, "wheel free_radius");
  requireLength(wheel.tread_width, where, "wheel tread_width");
}

WheelContactFinder::WheelContactFinder() {
  candidates_.reserve(kReservedCandidates);
  caches_.reserve(kReservedCandidates);
  next_caches_.reserve(kReservedCandidates);
  // Every touching piece is a contact until the seam rule: as many as candidates.
  contacts_.reserve(kReservedCandidates);
  caps_.reserve(kReservedCandidates);
  shares_.reserve(kReservedCandidates);
  rank_.reserve(kReservedCandidates);
  through_edge_.reserve(kReservedCandidates);
  uncovered_.reserve(kReservedCandidates);
  surface_runs_.reserve(kReservedCandidates);
  surface_.points.reserve(kReservedCandidates);
  surface_.passed.reserve(kReservedCandidates);
  shadows_.reserve(kReservedCandidates);
  touches_.reserve(kReservedCandidates);
  exits_.reserve(kReservedCandidates);
  next_exits_.reserve(kReservedCandidates);
  contact_pieces_.reserve(kReservedCandidates);
  formed_.reserve(kReservedCandidates);
  next_formed_.reserve(kReservedCandidates);
}

std::span<const WheelContact> WheelContactFinder::find(const Terrain& terrain, const WheelGeometry& wheel,
                                                       const WheelPose& pose, const ContactOptions& options) {
  static constexpr const char* kWhere = "wtc::WheelContactFinder::find";
  validate(wheel, kWhere);
  const double axle_norm = pose.axle.norm();
  if (!isFinite(pose.center) || !std::isfinite(axle_norm) || axle_norm < tolerance::kMinAxleNorm) {
    throw InvalidInputError(std::string(kWhere) + ": wheel pose centre = " + formatVector(pose.center) +
                            ", axle = " + formatVector(pose.axle) + " is not finite or has a zero axle");
  }
  const double r = wheel.free_radius;
  const Eigen::Vector3d& o = pose.center;
  terrain_ = &terrain;
  radius_ = r;
  if (terrain.serial() != terrain_serial_) {  // another terrain: nothing kept holds for it
    terrain_serial_ = terrain.serial();
    caches_.clear();
    exits_.clear();
    for (auto& [id, dropped] : formed_) spare_.push_back(std::move(dropped));
    formed_.clear();
    has_previous_ = false;
    runs_room_.reach = 0.0;
    keep_runs_ = true;
  }

  caps_.clear();

  // Right after a call that saw the ground at a cap, the caps are looked for
  // a little farther (hysteresis): an engine holding the wheel on a cap's
  // rim holds it at about r_f, and the cap contacts must not come and go
  // with every micrometre (they switch the engine's cap collision).
  const double cap_reach = caps_last_ ? r * (1.0 + tolerance::kCapHysteresisRelative) : r;

  // 1. Candidate pieces: those whose boxes come within the reach of O (the
  // others a point query turns away at its first test), and, as ever, meet
  // the cube O +- r_f. Asking the index for the ball, not the cube, visits
  // a fine field's disc of cells under the rim instead of the square
  // around the wheel (issue 53).
  candidates_.clear();
  touches_.clear();
  surface_.points.clear();  // no shadows but this call's
  surface_.passed.clear();
  const double gap = tolerance::kSeamGapRelative * r;
  bool per_prism = !(options.field_surface && options.seam_rule);
  if (!per_prism) {
    // A compact heightfield as one surface: its triangles in closed form,
    // a candidate only where the distance to it has a local minimum (or
    // on an exposed cell, as a prism).
    readSurfaceRuns(terrain, o, cap_reach);
    if (!surface_runs_.empty()) {
      if (detail::surfaceLocalMinima(terrain, surface_runs_, o, cap_reach, gap, surface_, candidates_, touches_)) {
        for (const detail::SurfacePoint& touch : touches_) candidates_.push_back(touch.id);
      } else {  // the centre inside the ground (or a vast window): every prism queried
        per_prism = true;
        candidates_.clear();
        touches_.clear();
        surface_.points.clear();
        surface_.passed.clear();
      }
    }
  }
  if (per_prism) terrain.within(o, cap_reach, candidates_);
  if (cap_reach > r) {
    const Aabb cube{o.array() - r, o.array() + r};
    std::erase_if(candidates_, [&](PieceId id) { return !terrain.pieceBounds(id).overlaps(cube); });
  }
  counts_ = {candidates_.size(), 0, 0, 0, 0};
  if (!per_prism && !surface_runs_.empty()) {
    counts_.surface = surface_.triangles;
    counts_.candidates += surface_.triangles - touches_.size();  // a touch is both
  }

  // 2. Point queries, warm-started from the previous call's simplices.
  QueryOptions query;
  query.max_distance = cap_reach;
  contacts_.clear();
  contact_pieces_.clear();
  next_caches_.clear();
  next_exits_.clear();
  // Candidates in piece order, so that caches_ (last call's, in the same
  // order) is matched in one merge walk: a search per candidate made a fine
  // heightfield's few hundred candidates quadratic.
  std::sort(candidates_.begin(), candidates_.end());
  auto previous = caches_.begin();
  // A compact part's pieces are formed once and kept while they stay
  // candidates (the same merge walk): a rolling wheel meets new cells every
  // few hundred steps.
  auto previous_formed = formed_.begin();
  next_formed_.clear();
  auto touch = touches_.cbegin();  // in id order, as the candidates
  for (const PieceId id : candidates_) {
    while (touch != touches_.cend() && touch->id < id) ++touch;
    const bool on_surface = touch != touches_.cend() && touch->id == id;
    QueryCache cache;
    while (previous != caches_.end() && previous->first < id) ++previous;
    if (previous != caches_.end() && previous->first == id) cache = previous->second;
    const ConvexPolyhedron* piece = nullptr;
    if (terrain.isFormed(id)) {
      while (previous_formed != formed_.end() && previous_formed->first < id) ++previous_formed;
      if (previous_formed != formed_.end() && previous_formed->first == id) {
        next_formed_.emplace_back(id, std::move(previous_formed->second));
      } else {
        // queryPoint's first two tests, the box and the face planes, on
        // the piece's corners without forming it: a piece they put beyond
        // the reach is beyond, its cache untouched, exactly as queryPoint
        // decides for a stored one.
        if (!on_surface && terrain.formedPieceBeyond(id, o, cap_reach)) {
          next_caches_.emplace_back(id, cache);
          continue;
        }
        std::shared_ptr<ConvexPolyhedron> formed;
        if (!spare_.empty()) {
          formed = std::move(spare_.back());
          spare_.pop_back();
        }
        if (formed && formed.use_count() == 1) {
          terrain.formPiece(id, *formed);  // into a dropped prism's buffers
        } else {
          std::optional<ConvexPolyhedron> scratch;
          terrain.piece(id, scratch);
          formed = std::make_shared<ConvexPolyhedron>(std::move(*scratch));
        }
        next_formed_.emplace_back(id, std::move(formed));
      }
      piece = next_formed_.back().second.get();
    } else {
      piece = &terrain.piece(id);
    }
    PointQuery q;
    if (on_surface) {  // answered in closed form; the prism is the seam rule's
      q.status = QueryStatus::kOutside;
      q.closest_point = touch->point;
      q.signed_distance = touch->distance;
      q.normal = (o - touch->point) / touch->distance;
      q.direction = -q.normal;
    } else {
      q = queryPoint(*piece, o, query, cache);
      ++counts_.queried;
      next_caches_.emplace_back(id, cache);
    }
    if (q.status == QueryStatus::kBeyond || !(q.signed_distance < cap_reach)) continue;
    ++counts_.touching;
    WheelContact c;
    c.e = -q.normal;
    c.point = o + r * c.e;
    c.ground_point = q.closest_point;
    c.signed_distance = q.signed_distance;
    c.deflection = r - q.signed_distance;
    c.piece = id;
    c.material = terrain.materialId(id);
    if (q.signed_distance < 0.0) exitWhereEntered(*piece, id, o, r, c);
    if (q.signed_distance >= r) {  // within the caps' hysteresis only
      if (options.tread_truncation && onCap(wheel, c.e, pose.axle / axle_norm)) caps_.push_back(c);
      continue;
    }
    contacts_.push_back(c);
    contact_pieces_.push_back(piece);
  }
  std::swap(caches_, next_caches_);
  std::swap(exits_, next_exits_);
  for (auto& [id, dropped] : formed_) {
    if (dropped) spare_.push_back(std::move(dropped));
  }
  std::swap(formed_, next_formed_);
  previous_centre_ = o;
  has_previous_ = true;

  // 3. Seam rule.
  if (options.seam_rule && contacts_.size() > 1) applySeamRule(gap, r);

  // 4. Tread filter: keep contacts with |OP . a| <= w / 2; the others are
  // the caps'.
  if (options.tread_truncation) {
    const Eigen::Vector3d a = pose.axle / axle_norm;
    std::size_t out = 0;
    for (const WheelContact& c : contacts_) {
      if (onCap(wheel, c.e, a)) {
        caps_.push_back(c);
      } else {
        contacts_[out++] = c;
      }
    }
    contacts_.resize(out);
  }

  // 5. Deepest only.
  if (!options.multiple_contacts && contacts_.size() > 1) {
    auto deepest = std::max_element(contacts_.begin(), contacts_.end(),
                                    [](const auto& x, const auto& y) { return x.deflection < y.deflection; });
    std::swap(contacts_.front(), *deepest);
    contacts_.resize(1);
  }
  caps_last_ = !caps_.empty();
  counts_.contacts = contacts_.size();
  return contacts_;
}

// A rolling wheel on the terrain's one compact heightfield keeps the cells
// within its reach from anywhere in a room about a point ahead of it (along
// its last move, half the room's width; RunsRoom) and reads them again
// while its centre stays in the room: a step then tests those cells, not
// the walk's. The search decides each cell by its own test, so the answer
// is the same whichever runs hold the cell. Runs with a passed cell hold
// for their centre alone (a cell passes or not by where the centre is);
// with several compact parts each call walks them as they are.
void WheelContactFinder::readSurfaceRuns(const Terrain& terrain, const Eigen::Vector3d& o, double reach) {
  if (runs_room_.reach > 0.0 && detail::runsHold(runs_room_, o, reach)) {
    terrain.withinBesideSurfaces(o, reach, candidates_);
    return;
  }
  surface_runs_.clear();
  runs_room_.reach = 0.0;
  if (keep_runs_ && terrain.compactFieldCount() == 1) {
    detail::RunsRoom room{o, kRunsAcrossRelative * radius_, kRunsDownRelative * radius_, reach};
    const Eigen::Vector3d moved(o.x() - previous_centre_.x(), o.y() - previous_centre_.y(), 0.0);
    const double step = moved.norm();
    if (has_previous_ && step > 0.0 && step < room.across) room.centre += (0.5 * room.across / step) * moved;
    const double walk = reach + std::hypot(room.across, room.down);  // from the room's centre to its floor's rim
    // (The room holds the centre by more than the cell test's own margin
    // unless the reach is under a micrometre.)
    if (detail::runsKeep(terrain, walk) && detail::runsHold(room, o, reach)) {
      terrain.withinBesideSurfaces(o, reach, candidates_);
      terrain.surfaceRuns(room.centre, walk, surface_runs_);
      if (detail::narrowRuns(terrain, surface_runs_, room)) {
        runs_room_ = room;
        return;
      }
      // A passed cell: passed for the room's centre, walked again for the centre.
      surface_runs_.clear();
      terrain.surfaceRuns(o, reach, surface_runs_);
      keep_runs_ = false;
      return;
    }
  }
  terrain.withinSurfaces(o, reach, candidates_, surface_runs_);
  // Where cells pass, each call walks anew; once none does, the wheel
  // keeps its runs again.
  keep_runs_ = std::none_of(surface_runs_.begin(), surface_runs_.end(),
                            [](const Terrain::SurfaceRun& run) { return run.passed; });
}

// The centre is inside the piece: it leaves by the face it came in through.
// The nearest face is not always that one: a large step can carry the centre
// past the middle of a thin piece, and pushing out by the far face pushes it
// on through (issue 11). The faces whose planes the last call's centre was
// in front of are the ones it crossed; of those, the shallowest. A centre
// that was already inside keeps the face it was pushed out by then; with
// neither (a first call, a teleport), the nearest face stays.
void WheelContactFinder::exitWhereEntered(const ConvexPolyhedron& piece, PieceId id, const Eigen::Vector3d& o, double r,
                                          WheelContact& c) {
  const auto previous_exit = std::find_if(exits_.begin(), exits_.end(), [id](const auto& e) { return e.first == id; });
  const bool came_in = has_previous_ && piece.planeBound(previous_centre_) > 0.0;
  int best = -1;
  double best_depth = 0.0, best_alignment = -2.0;
  for (int f = 0; f < piece.faceCount(); ++f) {
    const Eigen::Vector3d n = piece.faceNormal(f);
    const double depth = piece.faceOffset(f) - n.dot(o);
    if (came_in) {
      if (n.dot(previous_centre_) - piece.faceOffset(f) <= 0.0) continue;  // not crossed
      if (best < 0 || depth < best_depth) best = f, best_depth = depth;
    } else if (previous_exit != exits_.end()) {
      const double alignment = n.dot(previous_exit->second);
      if (alignment > best_alignment) best = f, best_depth = depth, best_alignment = alignment;
    }
  }
  if (best >= 0) {
    const Eigen::Vector3d n = piece.faceNormal(best);
    if (n.dot(-c.e) < tolerance::kSameFaceNormalCos) {  // another face than the nearest
      c.e = -n;
      c.point = o + r * c.e;
      c.ground_point = o + best_depth * n;
      c.signed_distance = -best_depth;
      c.deflection = r + best_depth;
    }
  }
  next_exits_.emplace_back(id, -c.e);
}

void WheelContactFinder::applySeamRule(double gap, double radius) {
  // Contacts are ranked strictly by (distance, piece id): the nearest one
  // keeps its whole load, and no two contacts can shadow each other. Each
  // piece gives at most one contact, so the rank is a strict order and the
  // contacts nearer than B are those ranked before it.
  rank_.resize(contacts_.size());
  for (std::size_t k = 0; k < rank_.size(); ++k) rank_[k] = k;
  std::sort(rank_.begin(), rank_.end(), [&](std::size_t x, std::size_t y) {
    const WheelContact &a = contacts_[x], &b = contacts_[y];
    return a.signed_distance < b.signed_distance || (a.signed_distance == b.signed_distance && a.piece < b.piece);
  });
  // The field surfaces' touching triangles that are no contact (in no
  // order: each contact reads them once, a sort cost more), by their place
  // in surface_.points.
  shadows_.clear();
  for (std::size_t k = 0; k < surface_.points.size(); ++k) {
    const detail::SurfacePoint& s = surface_.points[k];
    if (!s.minimum && s.distance < radius) shadows_.push_back(k);
  }
  // The cells the search passed: only those that could change a share.
  // A contact another contact covers reads no shadow's coverage, nor
  // (covered, it is no real edge) a shadow's clearance.
  if (!surface_.passed.empty()) {
    uncovered_.assign(contacts_.size(), 1);
    for (std::size_t b = 0; b < contacts_.size(); ++b) {
      for (std::size_t a = 0; a < contacts_.size() && uncovered_[b]; ++a) {
        if (a != b && contact_pieces_[a]->planeBound(contacts_[b].ground_point) - gap <= 0.0) uncovered_[b] = 0;
      }
    }
    // (Appended to the searched points: passedShadows reads none of them.)
    const std::size_t searched = surface_.points.size();
    detail::passedShadows(*terrain_, surface_, contacts_, uncovered_, radius, gap, surface_.points);
    for (std::size_t k = searched; k < surface_.points.size(); ++k) shadows_.push_back(k);
  }
  const double tie = gap;  // shadowNearer's
  auto share = [&](std::size_t at) {
    const std::size_t kb = rank_[at];
    const WheelContact& b = contacts_[kb];
    // L = sqrt(2 r Z): half the chord the ground cuts from the undeformed tread.
    const double patch = std::sqrt(2.0 * radius * b.deflection);
    double least = 1.0;
    bool covered = false;  // B's ground point lies on another touching piece: a seam, not a real edge
    // The nearer contacts, the ones nearest B's distance first: on a fine
    // field the piece that covers B is its neighbour, a little nearer. Once
    // B is covered with no share left, no other contact can change that:
    // the loop stops (the same answer as reading all of them, bit for bit;
    // without it the rule read every pair, half a fine field's search).
    for (std::size_t q = at; q-- > 0 && !(covered && least == 0.0);) {
      const std::size_t ka = rank_[q];
      const double outside = contact_pieces_[ka]->planeBound(b.ground_point) - gap;  // (m)
      covered = covered || outside <= 0.0;
      double cut = outside <= 0.0 ? 0.0 : std::min(1.0, outside / patch);
      // A nearer real edge standing less than its deflection off the ground
      // presses Z_A - clear of B's own ground through it: B adds the rest,
      // Z_B - (Z_A - clear), not the crease's share (issue 40, item 6).
      if (cut > 0.0) cut = std::min(cut, std::max(0.0, 1.0 - groundThroughEdge(ka, gap) / b.deflection));
      least = std::min(least, cut);
    }
    // A field surface's nearer triangles that are no contact cut B as
    // their prisms did (they stand on no real edge: nothing passes through).
    for (const std::size_t k : shadows_) {
      const detail::SurfacePoint& s = surface_.points[k];
      if (covered && least == 0.0) break;
      if (s.distance > b.signed_distance + tie || !shadowNearer(s, b)) continue;
      // Beyond the patch a shadow cuts nothing (and covers nothing).
      const double outside = detail::prismPlaneBound(s, b.ground_point, patch + gap) - gap;  // (m)
      covered = covered || outside <= 0.0;
      least = std::min(least, outside <= 0.0 ? 0.0 : std::min(1.0, outside / patch));
    }
    if (least == 1.0) return least;  // whole: coverage is asked only of a cut contact
    // The farther contacts cut nothing but may cover B; so may the farther
    // triangles of a field's surface.
    for (std::size_t q = at + 1; q < rank_.size() && !covered; ++q) {
      covered = contact_pieces_[rank_[q]]->planeBound(b.ground_point) - gap <= 0.0;
    }
    covered = covered || detail::shadowsCover(surface_.points, shadows_, b.ground_point, gap,
                                              [&](const detail::SurfacePoint& s) { return !shadowNearer(s, b); });
    return !covered && onAnEdge(kb, gap) ? std::max(least, realEdgeClearance(kb, gap) / b.deflection) : least;
  };
  // Decide on the unfiltered set, then erase: the rule is symmetric in order.
  through_edge_.assign(contacts_.size(), kNotMeasured);
  shares_.resize(contacts_.size());
  for (std::size_t at = 0; at < rank_.size(); ++at) shares_[rank_[at]] = share(at);
  std::size_t out = 0;
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    if (shares_[k] == 0.0) continue;
    contacts_[out] = contacts_[k];
    contacts_[out++].load_share = shares_[k];
  }
  contacts_.resize(out);
}

// A real edge (issue 11, defect 3): B's ground point lies on an edge or a
// vertex of B (two or more of B's face planes pass through it) that no other
// touching piece covers: a kerb's top edge, a crack's lip, a box's corner.
// A seam's or a crease's edge is always covered, by the piece on its other
// side. Such an edge stands `clear` off the rest of the ground (the kerb's
// height, the crack's width) and presses into the tread by min(Z_B, clear),
// as a brush tyre's bristles over a step: share min(1, clear / Z_B). It is 0
// on every seam (so flat tessellated ground is untouched, bit for bit) and
// continuous as contacts come and go: a piece that starts touching the wheel
// is at least Z_B from B's ground point (triangle inequality), so distances
// below Z_B are measured exactly, not by the plane bound.
bool WheelContactFinder::onAnEdge(std::size_t b, double gap) const {
  const ConvexPolyhedron& piece = *contact_pieces_[b];
  const Eigen::Vector3d p = contacts_[b].ground_point - piece.origin();  // in the piece's frame (m)
  int planes_through = 0;
  for (int f = 0; f < piece.faceCount() && planes_through < 2; ++f) {
    if (std::abs(piece.faceNormal(f).dot(p) - piece.faceOffsetLocal(f)) <= gap) ++planes_through;
  }
  return planes_through >= 2;  // else a face: the crease rule alone
}

// min(Z_B, clear) (m) of contact b, on an edge that no other touching piece
// covers (above).
double WheelContactFinder::realEdgeClearance(std::size_t b, double gap) {
  const WheelContact& edge = contacts_[b];
  double clear = edge.deflection;  // only clearances below Z_B matter
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    if (contacts_[k].piece == edge.piece) continue;
    const ConvexPolyhedron& other = *contact_pieces_[k];
    double outside = other.planeBound(edge.ground_point) - gap;  // (m), > 0 (not covered), a lower bound
    if (outside < clear) outside = queryPoint(other, edge.ground_point).signed_distance - gap;
    clear = std::min(clear, outside);
  }
  for (const std::size_t k : shadows_) {
    const detail::SurfacePoint& s = surface_.points[k];
    double outside = detail::prismPlaneBound(s, edge.ground_point) - gap;
    if (outside < clear) outside = shadowDistance(s, edge.ground_point) - gap;
    clear = std::min(clear, outside);
  }
  return clear;
}

bool WheelContactFinder::shadowNearer(const detail::SurfacePoint& s, const WheelContact& b) const {
  // The seam rule's order, (distance, id), strict, as the local minima were
  // found (field_surface.hpp); but an exposed prism's contact (GJK's) keeps
  // a point it shares with a shadow to within roundoff.
  const double tie = tolerance::kSeamGapRelative * radius_;
  if (std::abs(s.distance - b.signed_distance) <= tie && !onSurface(b.piece) &&
      (s.point - b.ground_point).norm() <= tie) {
    return false;
  }
  return s.distance < b.signed_distance || (s.distance == b.signed_distance && s.id < b.piece);
}

bool WheelContactFinder::onSurface(PieceId id) const {
  const auto at = std::lower_bound(touches_.begin(), touches_.end(), id,
                                   [](const detail::SurfacePoint& t, PieceId wanted) { return t.id < wanted; });
  return at != touches_.end() && at->id == id;
}

double WheelContactFinder::shadowDistance(const detail::SurfacePoint& s, const Eigen::Vector3d& p) {
  if (shadow_piece_) {
    terrain_->formPiece(s.id, *shadow_piece_);
  } else {
    terrain_->piece(s.id, shadow_piece_);
  }
  return queryPoint(*shadow_piece_, p).signed_distance;
}

// A step lower than the tread's deflection (issue 40, item 6): contact a on
// a real edge pressed Z_A into the tread, standing clear < Z_A off the
// ground below it, presses Z_A - clear of that ground's own deflection
// through the step (the bristles over the step are pressed by the ground's
// patch and the step's height on top of it). Returns that part, Z_A - clear
// (m), 0 for a face, a covered edge (a seam's or a crease's) or an edge at
// least Z_A high. Measured once per call, when a farther contact asks.
double WheelContactFinder::groundThroughEdge(std::size_t a, double gap) {
  double& through = through_edge_[a];
  if (through != kNotMeasured) return through;
  through = 0.0;
  if (!onAnEdge(a, gap)) return through;  // first: most contacts a farther one asks about are on a face
  const WheelContact& edge = contacts_[a];
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    if (contacts_[k].piece != edge.piece && contact_pieces_[k]->planeBound(edge.ground_point) - gap <= 0.0) {
      return through;  // covered: a seam's or a crease's edge
    }
  }
  if (detail::shadowsCover(surface_.points, shadows_, edge.ground_point, gap,
                           [](const detail::SurfacePoint&) { return true; })) {
    return through;
  }
  through = edge.deflection - std::max(0.0, realEdgeClearance(a, gap));
  return through;
}

}  // namespace wtc
