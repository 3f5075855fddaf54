#include "wtc/terrain.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <string>

#include "compact_heightfield.hpp"
#include "wtc/error.hpp"

namespace wtc {
namespace {

// Pieces per leaf: 2 and 4 measure within noise of each other on
// heightfields (bench/wheel_query_bench.cpp); 4 halves the node memory.
constexpr int kLeafPieces = 4;

// Single-precision box rounded outward: never smaller than the double box,
// so the index never misses a piece.
void storeOutward(const Aabb& box, float min[3], float max[3]) {
  for (int k = 0; k < 3; ++k) {
    min[k] = std::nextafter(static_cast<float>(box.min[k]), -std::numeric_limits<float>::infinity());
    max[k] = std::nextafter(static_cast<float>(box.max[k]), std::numeric_limits<float>::infinity());
  }
}

// The query box in single precision, widened by at least one ulp without a
// libm call (this runs once per wheel query): 2^-22 relative plus the
// smallest normal float covers the rounding of the cast.
void widenQuery(const Aabb& box, float lo[3], float hi[3]) {
  constexpr float kUlps = 2.384185791015625e-07f;  // 2^-22
  constexpr float kTiny = std::numeric_limits<float>::min();
  for (int k = 0; k < 3; ++k) {
    const float a = static_cast<float>(box.min[k]);
    const float b = static_cast<float>(box.max[k]);
    lo[k] = a - (std::abs(a) * kUlps + kTiny);
    hi[k] = b + (std::abs(b) * kUlps + kTiny);
  }
}

}  // namespace

MaterialId TerrainBuilder::addMaterial(const Material& material) {
  validate(material, "TerrainBuilder::addMaterial (material '" + material.name + "')");
  materials_.push_back(material);
  return static_cast<MaterialId>(materials_.size() - 1);
}

void TerrainBuilder::requireMaterial(MaterialId material, const char* where) const {
  if (material < 0 || material >= materialCount()) {
    throw InvalidInputError(std::string(where) + ": material id " + std::to_string(material) + " is not registered (" +
                            std::to_string(materials_.size()) + " materials)");
  }
}

PieceId TerrainBuilder::addPiece(ConvexPolyhedron piece, MaterialId material) {
  requireMaterial(material, "wtc::TerrainBuilder::addPiece");
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
  pieces_.reserve(grown);
  piece_material_.reserve(grown);
}

Terrain TerrainBuilder::build() && {
  if (next_id_ == 0) throw InvalidInputError("wtc::TerrainBuilder::build: the terrain has no pieces");
  Terrain terrain;
  terrain.pieces_ = std::move(pieces_);
  terrain.piece_material_ = std::move(piece_material_);
  terrain.materials_ = std::move(materials_);
  terrain.fields_ = std::move(fields_);
  terrain.piece_count_ = next_id_;
  terrain.buildIndex();
  return terrain;
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

bool Terrain::isFormed(PieceId id) const { return !fields_.empty() && place(id).field >= 0; }

const ConvexPolyhedron& Terrain::storedPiece(PieceId id) const {
  const Place at = place(id);
  if (at.field >= 0) {
    throw InvalidInputError("wtc::Terrain::piece: piece " + std::to_string(id) +
                            " belongs to a compact heightfield and is formed on demand; use piece(id, scratch)");
  }
  return pieces_[at.stored];
}

const ConvexPolyhedron& Terrain::piece(PieceId id, std::optional<ConvexPolyhedron>& scratch) const {
  if (fields_.empty()) return pieces_[id];
  const Place at = place(id);
  if (at.field < 0) return pieces_[at.stored];
  const Field& f = fields_[at.field];
  scratch = f.grid->piece(static_cast<std::size_t>(id - f.first));
  return *scratch;
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
  return {f.first, f.count, &f.grid->field(), f.material};
}

Aabb Terrain::pieceBounds(PieceId id) const {
  if (fields_.empty()) return pieces_[id].bounds();
  const Place at = place(id);
  if (at.field < 0) return pieces_[at.stored].bounds();
  const Field& f = fields_[at.field];
  return f.grid->pieceBounds(static_cast<std::size_t>(id - f.first));
}

MaterialId Terrain::fieldAwareMaterialId(PieceId id) const {
  const Place at = place(id);
  if (at.field < 0) return piece_material_[at.stored];
  const Field& f = fields_[at.field];
  const std::vector<MaterialId>& cells = f.grid->field().cell_materials;
  return cells.empty() ? f.material : cells[static_cast<std::size_t>(id - f.first) / 2];  // two pieces a cell
}

// Top-down build over piece centroids. A node's range is split at the
// median along the widest centroid axis, and each half once more, giving up
// to four children; a child of at most kLeafPieces pieces is a leaf. O(n log n).
void Terrain::buildIndex() {
  bool empty = true;
  const auto cover = [&](const Aabb& box) {
    if (empty) bounds_ = box;
    bounds_.include(box);
    empty = false;
  };
  for (const Field& f : fields_) cover(f.grid->bounds());
  const auto n = static_cast<PieceId>(pieces_.size());
  if (n == 0) return;  // compact fields only: their grids are their index
  order_.resize(n);
  std::iota(order_.begin(), order_.end(), 0);
  std::vector<Eigen::Vector3d> centre(n);
  for (PieceId i = 0; i < n; ++i) {
    centre[i] = pieces_[i].bounds().center();
    cover(pieces_[i].bounds());
  }
  auto rangeBox = [&](std::int32_t begin, std::int32_t end) {
    Aabb box = pieces_[order_[begin]].bounds();
    for (std::int32_t k = begin + 1; k < end; ++k) {
      box.include(pieces_[order_[k]].bounds());
    }
    return box;
  };
  auto split = [&](std::int32_t begin, std::int32_t end) {
    Aabb centres{centre[order_[begin]], centre[order_[begin]]};
    for (std::int32_t k = begin + 1; k < end; ++k) centres.include(centre[order_[k]]);
    int axis = 0;
    centres.extent().maxCoeff(&axis);
    const std::int32_t mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](PieceId a, PieceId b) { return centre[a][axis] < centre[b][axis]; });
    return mid;
  };
  nodes_.clear();
  nodes_.reserve(static_cast<std::size_t>(n) / kLeafPieces + 1);
  // Returns the node index; called only for ranges larger than a leaf.
  auto build = [&](auto& self, std::int32_t begin, std::int32_t end) -> std::int32_t {
    std::int32_t bounds[5];
    int parts = 0;
    const std::int32_t mid = split(begin, end);
    for (const auto& [b, e] : {std::pair{begin, mid}, std::pair{mid, end}}) {
      bounds[parts++] = b;
      if (e - b > kLeafPieces) bounds[parts++] = split(b, e);
    }
    bounds[parts] = end;
    const auto index = static_cast<std::int32_t>(nodes_.size());
    nodes_.emplace_back();
    float min[3][4], max[3][4];
    for (int c = 0; c < 4; ++c) {
      constexpr float kInf = std::numeric_limits<float>::infinity();
      float lo[3] = {kInf, kInf, kInf}, hi[3] = {-kInf, -kInf, -kInf};  // empty slot: overlaps nothing
      std::int32_t child = -1, count = 0;
      if (c < parts) {
        const std::int32_t b = bounds[c], e = bounds[c + 1];
        storeOutward(rangeBox(b, e), lo, hi);
        if (e - b <= kLeafPieces) {
          child = ~b;
          count = e - b;
        } else {
          child = self(self, b, e);
        }
      }
      for (int k = 0; k < 3; ++k) {
        min[k][c] = lo[k];
        max[k][c] = hi[k];
      }
      nodes_[index].child[c] = child;
      nodes_[index].count[c] = count;
    }
    Node& node = nodes_[index];
    std::memcpy(&node.min_x, min[0], sizeof(Float4));
    std::memcpy(&node.min_y, min[1], sizeof(Float4));
    std::memcpy(&node.min_z, min[2], sizeof(Float4));
    std::memcpy(&node.max_x, max[0], sizeof(Float4));
    std::memcpy(&node.max_y, max[1], sizeof(Float4));
    std::memcpy(&node.max_z, max[2], sizeof(Float4));
    return index;
  };
  if (n > kLeafPieces) {
    build(build, 0, n);
  } else {
    // A root with a single leaf child keeps one query path for all sizes.
    Node root{};
    float lo[3], hi[3];
    storeOutward(bounds_, lo, hi);
    constexpr float kInf = std::numeric_limits<float>::infinity();
    root.min_x = Float4{lo[0], kInf, kInf, kInf};
    root.min_y = Float4{lo[1], kInf, kInf, kInf};
    root.min_z = Float4{lo[2], kInf, kInf, kInf};
    root.max_x = Float4{hi[0], -kInf, -kInf, -kInf};
    root.max_y = Float4{hi[1], -kInf, -kInf, -kInf};
    root.max_z = Float4{hi[2], -kInf, -kInf, -kInf};
    root.child[0] = ~0;
    root.count[0] = n;
    for (int c = 1; c < 4; ++c) root.child[c] = -1;
    nodes_.push_back(root);
  }
  nodes_.shrink_to_fit();
  // Leaf boxes in tree order, exact (double): a leaf test reads one
  // contiguous run of memory instead of dereferencing each piece.
  leaf_boxes_.resize(n);
  for (PieceId k = 0; k < n; ++k) leaf_boxes_[k] = pieces_[order_[k]].bounds();
  // From here on order_ holds ids: a stored piece's id counts the formed
  // ids of the fields before it.
  if (fields_.empty()) return;
  for (PieceId& k : order_) k = storedId(static_cast<std::size_t>(k));
}

void Terrain::overlapping(const Aabb& box, std::vector<PieceId>& out) const {
  for (const Field& f : fields_) f.grid->overlapping(box, f.first, out);
  if (nodes_.empty()) return;
  float lo[3], hi[3];
  widenQuery(box, lo, hi);
  const Float4 lx{lo[0], lo[0], lo[0], lo[0]}, ly{lo[1], lo[1], lo[1], lo[1]}, lz{lo[2], lo[2], lo[2], lo[2]};
  const Float4 hx{hi[0], hi[0], hi[0], hi[0]}, hy{hi[1], hi[1], hi[1], hi[1]}, hz{hi[2], hi[2], hi[2], hi[2]};
  // Depth-first; a 4-wide tree of depth 32 would hold 2^64 leaves.
  std::int32_t stack[3 * 32 + 1];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    const auto hit = (lx <= node.max_x) & (node.min_x <= hx) & (ly <= node.max_y) & (node.min_y <= hy) &
                     (lz <= node.max_z) & (node.min_z <= hz);
    for (int c = 0; c < 4; ++c) {
      if (hit[c] == 0) continue;
      const std::int32_t child = node.child[c];
      if (child >= 0) {
        stack[top++] = child;
        continue;
      }
      for (std::int32_t k = ~child; k < ~child + node.count[c]; ++k) {
        if (leaf_boxes_[k].overlaps(box)) out.push_back(order_[k]);
      }
    }
  }
}

std::size_t Terrain::pieceMemoryBytes() const {
  std::size_t bytes = piece_material_.capacity() * sizeof(MaterialId) + fields_.capacity() * sizeof(Field);
  for (const Field& f : fields_) bytes += f.grid->memoryBytes();
  for (const auto& p : pieces_) bytes += p.memoryBytes();
  return bytes;
}

std::size_t Terrain::indexMemoryBytes() const {
  return nodes_.capacity() * sizeof(Node) + order_.capacity() * sizeof(PieceId) + leaf_boxes_.capacity() * sizeof(Aabb);
}

}  // namespace wtc
