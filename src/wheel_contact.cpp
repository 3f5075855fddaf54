#include "wtc/wheel_contact.hpp"

#include <algorithm>
#include <cmath>

#include "builder_support.hpp"
#include "wtc/error.hpp"
#include "wtc/scratch_capacity.hpp"

namespace wtc {

void validate(const WheelGeometry& wheel, const char* where) {
  detail::requirePositive(wheel.free_radius, where, "wheel free_radius", "m");
  detail::requirePositive(wheel.tread_width, where, "wheel tread_width", "m");
}

WheelContactFinder::WheelContactFinder() {
  candidates_.reserve(kReservedCandidates);
  caches_.reserve(kReservedCandidates);
  next_caches_.reserve(kReservedCandidates);
  // Every touching piece is a contact until the seam rule: as many as candidates.
  contacts_.reserve(kReservedCandidates);
  caps_.reserve(kReservedCandidates);
  shares_.reserve(kReservedCandidates);
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

  caps_.clear();

  // 1. Candidate pieces.
  candidates_.clear();
  terrain.overlapping({o.array() - r, o.array() + r}, candidates_);

  // 2. Point queries, warm-started from the previous call's simplices.
  QueryOptions query;
  query.max_distance = r;
  contacts_.clear();
  next_caches_.clear();
  // Candidates in piece order, so that caches_ (last call's, in the same
  // order) is matched in one merge walk: a search per candidate made a fine
  // heightfield's few hundred candidates quadratic.
  std::sort(candidates_.begin(), candidates_.end());
  auto previous = caches_.begin();
  for (const PieceId id : candidates_) {
    QueryCache cache;
    while (previous != caches_.end() && previous->first < id) ++previous;
    if (previous != caches_.end() && previous->first == id) cache = previous->second;
    const PointQuery q = queryPoint(terrain.piece(id), o, query, cache);
    next_caches_.emplace_back(id, cache);
    if (q.status == QueryStatus::kBeyond || !(q.signed_distance < r)) continue;
    WheelContact c;
    c.e = -q.normal;
    c.point = o + r * c.e;
    c.ground_point = q.closest_point;
    c.signed_distance = q.signed_distance;
    c.deflection = r - q.signed_distance;
    c.piece = id;
    c.material = terrain.materialId(id);
    contacts_.push_back(c);
  }
  std::swap(caches_, next_caches_);

  // 3. Seam rule.
  if (options.seam_rule && contacts_.size() > 1) applySeamRule(terrain, tolerance::kSeamGapRelative * r, r);

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
  return contacts_;
}

void WheelContactFinder::applySeamRule(const Terrain& terrain, double gap, double radius) {
  // Contacts are ranked strictly by (distance, piece id): the nearest one
  // keeps its whole load, and no two contacts can shadow each other.
  auto share = [&](const WheelContact& b) {
    // L = sqrt(2 r Z): half the chord the ground cuts from the undeformed tread.
    const double patch = std::sqrt(2.0 * radius * b.deflection);
    double least = 1.0;
    for (const WheelContact& a : contacts_) {
      const bool nearer =
          a.signed_distance < b.signed_distance || (a.signed_distance == b.signed_distance && a.piece < b.piece);
      if (!nearer) continue;
      const double outside = terrain.piece(a.piece).planeBound(b.ground_point) - gap;  // (m)
      least = std::min(least, outside <= 0.0 ? 0.0 : std::min(1.0, outside / patch));
    }
    return least;
  };
  // Decide on the unfiltered set, then erase: the rule is symmetric in order.
  shares_.resize(contacts_.size());
  for (std::size_t k = 0; k < contacts_.size(); ++k) shares_[k] = share(contacts_[k]);
  std::size_t out = 0;
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    if (shares_[k] == 0.0) continue;
    contacts_[out] = contacts_[k];
    contacts_[out++].load_share = shares_[k];
  }
  contacts_.resize(out);
}

}  // namespace wtc
