#include "wtc/terrain/terrain.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>
#include <numeric>
#include <string>

#include "base/cache_line.hpp"
#include "base/huge_pages.hpp"
#include "box_tree.hpp"
#include "builder_support.hpp"
#include "formed_pieces.hpp"
#include "geometry/polyhedron_layout.hpp"
#include "piece_arena.hpp"
#include "wtc/base/error.hpp"
#include "wtc/geometry/point_query.hpp"
#include "wtc/terrain/terrain_primitives.hpp"
#include "wtc/base/tolerances.hpp"

namespace wtc {

namespace {
using detail::kCacheLineBytes;  // the prefetch stride
// Lines of a piece's numbers prefetched: a prism's vertices, face planes and
// first face's side planes, what a query above its top reads first.
constexpr std::size_t kPrefetchLines = 7;
}  // namespace

MaterialId TerrainBuilder::addMaterial(const Material& material) {
  validate(material, "TerrainBuilder::addMaterial (material '" + material.name + "')");
  materials_.push_back(material);
  return static_cast<MaterialId>(materials_.size() - 1);
}

void TerrainBuilder::addSoilRegion(const SoilRegion& region, const std::string& where) {
  validate(region, where);
  soil_regions_.push_back(region);
}

void TerrainBuilder::requireMaterial(MaterialId material, const char* where) const {
  if (material < 0 || material >= materialCount()) {
    throw InvalidInputError(std::string(where) + ": material id " + std::to_string(material) + " is not registered (" +
                            std::to_string(materials_.size()) + " materials)");
  }
}

PieceId TerrainBuilder::addPiece(ConvexPolyhedron piece, MaterialId material) {
  requireMaterial(material, "wtc::TerrainBuilder::addPiece");
  if (pieces_.size() == pieces_.capacity()) reserve(std::max<std::size_t>(pieces_.capacity(), 1));
  pieces_.push_back(std::move(piece));
  piece_material_.push_back(material);
  return static_cast<PieceId>(next_id_++);
}

void TerrainBuilder::requireIdsFor(std::uint64_t count, const std::string& where) const {
  if (count > static_cast<std::uint64_t>(std::numeric_limits<PieceId>::max()) ||
      next_id_ + count > static_cast<std::uint64_t>(std::numeric_limits<PieceId>::max())) {
    throw InvalidInputError(where + ": " + std::to_string(count) + " pieces would pass the largest terrain (" +
                            std::to_string(std::numeric_limits<PieceId>::max()) + " pieces)");
  }
}

void TerrainBuilder::requireRoomFor(std::uint64_t count, const std::string& where) const {
  requireIdsFor(count, where);
  const std::uint64_t total = next_id_ + count;
  const long pages = sysconf(_SC_PHYS_PAGES), page_bytes = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_bytes <= 0) return;  // unknown: let the allocation decide
  const long double needed = static_cast<long double>(total) * sizeof(ConvexPolyhedron);
  const long double memory = static_cast<long double>(pages) * static_cast<long double>(page_bytes);
  if (needed > memory) {
    throw InvalidInputError(where + ": " + std::to_string(count) + " pieces need more than " +
                            formatNumber(static_cast<double>(needed / 1e9)) + " GB, more than this machine's " +
                            formatNumber(static_cast<double>(memory / 1e9)) + " GB of memory");
  }
}

void TerrainBuilder::reserve(std::size_t count) {
  // Grow geometrically: many small reservations must not make building
  // quadratic.
  const std::size_t wanted = pieces_.size() + count;
  if (wanted <= pieces_.capacity()) return;
  const std::size_t grown = std::max(wanted, 2 * pieces_.capacity());
  detail::reserveHuge(pieces_, grown);
  detail::reserveHuge(piece_material_, grown);
}

ConvexPolyhedron detail::FormedPieces::piece(std::size_t k) const {
  std::array<Eigen::Vector3d, 3> top, bottom;
  prismCorners(k, top, bottom);
  return makeCheckedPrism(top, bottom);
}

void detail::FormedPieces::formInto(std::size_t k, ConvexPolyhedron& into) const {
  std::array<Eigen::Vector3d, 3> top, bottom;
  prismCorners(k, top, bottom);
  makeCheckedPrism(top, bottom, into);
}

namespace {

// ConvexPolyhedron's bounds are the min and max of its vertices.
Aabb cornerBox(const std::array<Eigen::Vector3d, 3>& top, const std::array<Eigen::Vector3d, 3>& bottom) {
  Aabb box{top[0], top[0]};
  for (int i = 0; i < 3; ++i) {
    box.include(top[i]);
    box.include(bottom[i]);
  }
  return box;
}

}  // namespace

Aabb detail::FormedPieces::pieceBounds(std::size_t k) const {
  std::array<Eigen::Vector3d, 3> top, bottom;
  prismCorners(k, top, bottom);
  return cornerBox(top, bottom);
}

void detail::FormedPieces::within(const Eigen::Vector3d& point, double reach, PieceId first,
                                  std::vector<PieceId>& out) const {
  const std::size_t from = out.size();
  overlapping({point.array() - reach, point.array() + reach}, first, out);
  std::size_t kept = from;
  for (std::size_t k = from; k < out.size(); ++k) {
    if (pieceBounds(static_cast<std::size_t>(out[k] - first)).squaredDistance(point) <= reach * reach) {
      out[kept++] = out[k];
    }
  }
  out.resize(kept);
}

bool detail::FormedPieces::beyond(std::size_t k, const Eigen::Vector3d& point, double reach) const {
  std::array<Eigen::Vector3d, 3> top, bottom;
  prismCorners(k, top, bottom);
  // queryPoint's first test, bit for bit: the formed piece's bounds are
  // these corners' box.
  const Aabb box = cornerBox(top, bottom);
  if (box.squaredDistance(point) > reach * reach) return true;
  // Its second: the largest n . p - d over the faces. Each face's plane is
  // computed here from its corners, in the world frame; it is the formed
  // piece's own (local frame, Newell normal, d the largest n . c over the
  // corners) to within roundoff, so clearing the reach by the margin clears
  // it there too. Each face by a corner and its two edges there,
  // n = (a - apex) x (b - apex) outward (makeCheckedPrism's faces): the top,
  // the three sides, the bottom (a mesh's underside can face a wheel).
  static constexpr std::array<std::array<int, 3>, 5> kFaces = {{{0, 1, 2}, {0, 3, 1}, {1, 4, 2}, {2, 5, 0}, {3, 5, 4}}};
  const std::array<Eigen::Vector3d, 6> c = {top[0], top[1], top[2], bottom[0], bottom[1], bottom[2]};
  const double scale =
      std::max({point.cwiseAbs().maxCoeff(), box.min.cwiseAbs().maxCoeff(), box.max.cwiseAbs().maxCoeff()});  // (m)
  const double limit = reach + tolerance::kFormedPlaneMarginRelative * scale;
  constexpr double kMinSine2 = tolerance::kFormedPlaneMinSine * tolerance::kFormedPlaneMinSine;
  for (const auto& [apex, a, b] : kFaces) {
    const Eigen::Vector3d u = c[a] - c[apex], v = c[b] - c[apex];
    const Eigen::Vector3d n = u.cross(v);
    const double n2 = n.squaredNorm();
    const double above = n.dot(point - c[apex]);  // |n| times the plane's value
    // Beyond: above / |n| > limit, unless the face is a sliver (its normal
    // then roundoff's; the other faces still decide).
    if (above > 0.0 && above * above > limit * limit * n2 && n2 > kMinSine2 * u.squaredNorm() * v.squaredNorm()) {
      return true;
    }
  }
  return false;
}

PieceRange detail::TerrainBuilderAccess::addFormedPieces(TerrainBuilder& builder,
                                                         std::shared_ptr<const FormedPieces> pieces,
                                                         MaterialId material, const std::string& where) {
  builder.requireMaterial(material, where.c_str());
  // Only the ids are needed: formed pieces take no memory of their own.
  builder.requireIdsFor(pieces->pieceCount(), where);
  TerrainBuilder::Field f;
  f.first = static_cast<PieceId>(builder.next_id_);
  f.count = static_cast<PieceId>(pieces->pieceCount());
  f.formed_before = builder.fields_.empty() ? 0 : builder.fields_.back().formed_before + builder.fields_.back().count;
  f.formed = std::move(pieces);
  f.material = material;
  builder.next_id_ += static_cast<std::size_t>(f.count);
  builder.fields_.push_back(std::move(f));
  return {builder.fields_.back().first, builder.fields_.back().count};
}

PieceRange detail::TerrainBuilderAccess::addPendingPrisms(TerrainBuilder& builder, std::size_t count,
                                                          PendingPrisms::Corners corners,
                                                          const std::function<MaterialId(std::size_t)>& materialOf,
                                                          const std::string& where) {
  builder.requireRoomFor(count, where);
  const PieceRange range{static_cast<PieceId>(builder.next_id_), static_cast<PieceId>(count)};
  if (count == 0) return range;
  builder.reserve(count);
  const std::size_t first = builder.pieces_.size();
  for (std::size_t k = 0; k < count; ++k) builder.piece_material_.push_back(materialOf(k));
  // Empty places, made into the arena by build().
  for (std::size_t k = 0; k < count; ++k) builder.pieces_.push_back(detail::PolyhedronLayout::empty());
  builder.pending_.push_back(std::make_shared<const PendingPrisms>(PendingPrisms{first, count, std::move(corners)}));
  builder.next_id_ += count;
  return range;
}

Terrain TerrainBuilder::build() && {
  if (next_id_ == 0) throw InvalidInputError("wtc::TerrainBuilder::build: the terrain has no pieces");
  Terrain terrain;
  terrain.pieces_ = std::move(pieces_);
  terrain.piece_material_ = std::move(piece_material_);
  terrain.materials_ = std::move(materials_);
  terrain.soil_regions_ = std::move(soil_regions_);
  terrain.fields_ = std::move(fields_);
  terrain.field_prisms_ = std::move(field_prisms_);
  terrain.piece_count_ = next_id_;
  static std::atomic<std::uint64_t> builds{0};
  terrain.serial_ = ++builds;
  std::vector<const detail::PendingPrisms*> pending;
  for (const auto& p : pending_) pending.push_back(p.get());
  terrain.buildIndex(pending);
  return terrain;
}

Terrain::Terrain(const Terrain& other)
    : pieces_(other.pieces_),  // each copy in a block of its own, until gathered
      piece_material_(other.piece_material_),
      materials_(other.materials_),
      soil_regions_(other.soil_regions_),
      fields_(other.fields_),
      field_prisms_(other.field_prisms_),
      piece_count_(other.piece_count_),
      serial_(other.serial_),
      tree_(other.tree_),
      leaves_(other.leaves_),
      bounds_(other.bounds_) {
  gatherPieces();
}

Terrain::Terrain(Terrain&&) noexcept = default;
Terrain& Terrain::operator=(Terrain&&) noexcept = default;
Terrain::~Terrain() = default;

Terrain& Terrain::operator=(const Terrain& other) {
  if (this != &other) *this = Terrain(other);
  return *this;
}

void Terrain::gatherPieces(std::span<const detail::PendingPrisms* const> pending) {
  if (pieces_.empty()) return;
  std::vector<std::int32_t> stored(leaves_.size());
  for (std::size_t k = 0; k < leaves_.size(); ++k) stored[k] = leaves_[k].stored;
  std::vector<std::uint32_t> first_line;
  arena_ = std::make_shared<const detail::PieceArena>(pieces_, pending, stored, first_line);
  for (std::size_t k = 0; k < leaves_.size(); ++k) leaves_[k].line = first_line[k];
}

bool Terrain::isFieldPrism(PieceId id) const {
  // The last range starting at or before id.
  const auto after = std::upper_bound(field_prisms_.begin(), field_prisms_.end(), id,
                                      [](PieceId i, const PieceRange& r) { return i < r.first; });
  return after != field_prisms_.begin() && id < std::prev(after)->end();
}

void detail::TerrainBuilderAccess::noteFieldPrisms(TerrainBuilder& builder, const PieceRange& range) {
  if (range.count > 0) builder.field_prisms_.push_back(range);
}

Terrain::Place Terrain::place(PieceId id) const {
  // The last field starting at or before id (fields are in id order).
  const auto after =
      std::upper_bound(fields_.begin(), fields_.end(), id, [](PieceId i, const Field& f) { return i < f.first; });
  if (after == fields_.begin()) return {-1, static_cast<std::size_t>(id)};
  const Field& f = *(after - 1);
  if (id < f.first + f.count) return {static_cast<int>(after - 1 - fields_.begin()), 0};
  return {-1, static_cast<std::size_t>(id - f.formed_before - f.count)};
}

const Terrain::Field* Terrain::formedField(PieceId id) const {
  if (fields_.empty()) return nullptr;
  const int field = place(id).field;  // -1 for a stored id and for no piece
  return field < 0 ? nullptr : &fields_[field];
}

bool Terrain::isFormed(PieceId id) const { return formedField(id) != nullptr; }

const ConvexPolyhedron& Terrain::storedPiece(PieceId id) const {
  const Place at = place(id);
  if (at.field >= 0) {
    throw InvalidInputError(
        "wtc::Terrain::piece: piece " + std::to_string(id) +
        " belongs to a compact heightfield or mesh and is formed on demand; use piece(id, scratch)");
  }
  return pieces_[at.stored];
}

const ConvexPolyhedron& Terrain::piece(PieceId id, std::optional<ConvexPolyhedron>& scratch) const {
  if (fields_.empty()) return pieces_[id];
  const Place at = place(id);
  if (at.field < 0) return pieces_[at.stored];
  const Field& f = fields_[at.field];
  scratch = f.formed->piece(static_cast<std::size_t>(id - f.first));
  return *scratch;
}

void Terrain::formPiece(PieceId id, ConvexPolyhedron& into) const {
  const Field* f = formedField(id);
  if (f == nullptr) {
    throw InvalidInputError("wtc::Terrain::formPiece: piece " + std::to_string(id) +
                            " is not a formed piece of this terrain (" + std::to_string(piece_count_) + " pieces)");
  }
  f->formed->formInto(static_cast<std::size_t>(id - f->first), into);
}

PieceId Terrain::storedId(std::size_t stored) const {
  // The last field that starts at or before stored position `stored` (field
  // f starts where f.first - f.formed_before stored pieces precede it).
  const auto after = std::upper_bound(fields_.begin(), fields_.end(), stored, [](std::size_t s, const Field& f) {
    return s < static_cast<std::size_t>(f.first - f.formed_before);
  });
  if (after == fields_.begin()) return static_cast<PieceId>(stored);
  const Field& f = *(after - 1);
  return static_cast<PieceId>(stored) + f.formed_before + f.count;
}

Terrain::CompactField Terrain::compactField(std::size_t k) const {
  const Field& f = fields_.at(k);
  return {f.first, f.count, f.formed->heightfield(), f.formed->mesh(), f.formed->thickness(), f.material,
          f.formed->bounds()};
}

PieceId Terrain::nearestPiece(const Eigen::Vector3d& point, PieceId first, PieceId count, double reach) const {
  std::vector<PieceId> near;
  overlapping({point.array() - reach, point.array() + reach}, near);
  PieceId best = -1;
  double best_distance = std::numeric_limits<double>::infinity();
  std::optional<ConvexPolyhedron> scratch;
  for (const PieceId id : near) {
    if (id < first || id >= first + count) continue;
    const double d = queryPoint(piece(id, scratch), point).signed_distance;
    if (d < best_distance || (d == best_distance && id < best)) {
      best = id;
      best_distance = d;
    }
  }
  return best;
}

Aabb Terrain::pieceBounds(PieceId id) const {
  if (fields_.empty()) return pieces_[id].bounds();
  const Place at = place(id);
  if (at.field < 0) return pieces_[at.stored].bounds();
  const Field& f = fields_[at.field];
  return f.formed->pieceBounds(static_cast<std::size_t>(id - f.first));
}

bool Terrain::formedPieceBeyond(PieceId id, const Eigen::Vector3d& point, double reach) const {
  const Field* f = formedField(id);
  return f != nullptr && f->formed->beyond(static_cast<std::size_t>(id - f->first), point, reach);
}

MaterialId Terrain::fieldAwareMaterialId(PieceId id) const {
  const Place at = place(id);
  if (at.field < 0) return piece_material_[at.stored];
  const Field& f = fields_[at.field];
  return f.formed->materialId(static_cast<std::size_t>(id - f.first), f.material);
}

void Terrain::buildIndex(std::span<const detail::PendingPrisms* const> pending) {
  bool empty = true;
  const auto cover = [&](const Aabb& box) {
    if (empty) bounds_ = box;
    bounds_.include(box);
    empty = false;
  };
  for (const Field& f : fields_) cover(f.formed->bounds());
  if (pieces_.empty()) return;  // compact parts only: each is its own index
  // Leaf boxes in tree order, exact (double): a leaf test reads one
  // contiguous run of memory instead of dereferencing each piece.
  // A pending prism's box is its corners' (a made prism's bounds are the
  // min and max of its vertices, bit for bit).
  std::vector<Aabb> boxes(pieces_.size());
  for (std::size_t i = 0; i < pieces_.size(); ++i) boxes[i] = pieces_[i].bounds();
  std::array<Eigen::Vector3d, 3> top, bottom;
  for (const detail::PendingPrisms* p : pending) {
    for (std::size_t k = 0; k < p->count; ++k) {
      p->corners(k, top, bottom);
      boxes[p->first + k] = cornerBox(top, bottom);
    }
  }
  for (const Aabb& box : boxes) cover(box);
  std::vector<std::int32_t> order;  // stored positions in tree order
  tree_ = std::make_shared<const detail::BoxTree>(boxes, order);
  detail::reserveHuge(leaves_, order.size());
  for (const std::int32_t stored : order) {
    // A stored piece's id counts the formed ids of the parts before it.
    const PieceId id = fields_.empty() ? stored : storedId(static_cast<std::size_t>(stored));
    leaves_.push_back({boxes[stored], id, stored, 0});
  }
  gatherPieces(pending);
}

void Terrain::overlapping(const Aabb& box, std::vector<PieceId>& out) const { collect(box, nullptr, out); }

void Terrain::within(const Eigen::Vector3d& point, double reach, std::vector<PieceId>& out) const {
  const detail::BoxTreeBall ball{point, reach};
  collect({point.array() - reach, point.array() + reach}, &ball, out);
}

void Terrain::withinSurfaces(const Eigen::Vector3d& point, double reach, std::vector<PieceId>& out,
                             std::vector<SurfaceRun>& runs) const {
  withinBesideSurfaces(point, reach, out);
  surfaceRuns(point, reach, runs);
}

void Terrain::surfaceRuns(const Eigen::Vector3d& point, double reach, std::vector<SurfaceRun>& runs) const {
  const Aabb cube{point.array() - reach, point.array() + reach};
  for (std::size_t part = 0; part < fields_.size(); ++part) {
    const Field& f = fields_[part];
    if (f.formed->isSurface() && f.formed->bounds().overlaps(cube)) {
      f.formed->surfaceWithin(point, reach, f.first, static_cast<int>(part), runs);
    }
  }
}

void Terrain::withinBesideSurfaces(const Eigen::Vector3d& point, double reach, std::vector<PieceId>& out) const {
  const detail::BoxTreeBall ball{point, reach};
  collect({point.array() - reach, point.array() + reach}, &ball, out, /*skip_surfaces=*/true);
}

// overlapping() and within(): `box` holds `ball` when there is one.
void Terrain::collect(const Aabb& box, const detail::BoxTreeBall* ball, std::vector<PieceId>& out,
                      bool skip_surfaces) const {
  // Each compact part is its own index; its bounds spare a part far away
  // the walk (a box with a NaN overlaps no bounds).
  for (std::size_t part = 0; part < fields_.size(); ++part) {
    const Field& f = fields_[part];
    if (!f.formed->bounds().overlaps(box)) continue;
    if (skip_surfaces && f.formed->isSurface()) continue;  // surfaceRuns' part
    if (ball != nullptr) {
      f.formed->within(ball->centre, ball->radius, f.first, out);
    } else {
      f.formed->overlapping(box, f.first, out);
    }
  }
  if (!tree_) return;
  // A reported piece and its numbers are fetched while the walk goes on
  // (a hint, no effect on any answer): its caller reads them next, and on a
  // terrain larger than the cache the misses of all the pieces reported
  // then overlap instead of coming one after another.
  const unsigned char* arena = arena_->base();
  auto report = [&](std::int32_t k) {
    const detail::PieceLeaf& leaf = leaves_[k];
    // queryPoint's first test, on the same box: within the reach or not.
    if (!leaf.box.overlaps(box) ||
        (ball != nullptr && leaf.box.squaredDistance(ball->centre) > ball->radius * ball->radius)) {
      return;
    }
    out.push_back(leaf.id);
    // Fixed counts, unrolled: a rolling wheel's pieces are cached, and there
    // the prefetches are pure overhead. A line past a small piece's numbers
    // is another piece's (a prefetch never faults).
    const char* piece = reinterpret_cast<const char*>(&pieces_[leaf.stored]);
#pragma GCC unroll 4
    for (std::size_t at = 0; at < sizeof(ConvexPolyhedron); at += kCacheLineBytes) __builtin_prefetch(piece + at);
    __builtin_prefetch(piece + sizeof(ConvexPolyhedron) - 1);
    const unsigned char* numbers = arena + static_cast<std::size_t>(leaf.line) * kCacheLineBytes;
#pragma GCC unroll 8
    for (std::size_t line = 0; line < kPrefetchLines; ++line) __builtin_prefetch(numbers + line * kCacheLineBytes);
    __builtin_prefetch(&piece_material_[leaf.stored]);  // a contact's material is read next
  };
  // The leaf records report() reads, asked for while the walk goes on.
  auto touch = [&](std::int32_t first, std::int32_t count) {
    for (std::int32_t k = first; k < first + count; ++k) __builtin_prefetch(&leaves_[k]);
  };
  if (ball != nullptr) {
    tree_->visitNear(box, *ball, report, touch);
  } else {
    tree_->visit(box, report, touch);
  }
}

std::size_t Terrain::pieceMemoryBytes() const {
  std::size_t bytes = piece_material_.capacity() * sizeof(MaterialId) + fields_.capacity() * sizeof(Field);
  for (const Field& f : fields_) bytes += f.formed->memoryBytes();
  // Every stored piece's numbers and topology are in the arena.
  bytes += pieces_.capacity() * sizeof(ConvexPolyhedron);
  return bytes + (arena_ ? arena_->memoryBytes() : 0);
}

std::size_t Terrain::indexMemoryBytes() const {
  std::size_t bytes =
      (tree_ ? tree_->memoryBytes() : 0) + leaves_.capacity() * sizeof(detail::PieceLeaf);
  for (const Field& f : fields_) bytes += f.formed->indexMemoryBytes();
  return bytes;
}

}  // namespace wtc
