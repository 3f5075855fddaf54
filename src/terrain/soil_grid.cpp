// The memory of a soft ground (design in soil_grid.hpp).
#include "soil_grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace wtc::detail {

namespace {

// A float's upper half, rounded up in magnitude (pressures are >= 0).
std::uint16_t toBfloat16(float value) {
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
  const std::uint32_t upper = bits >> 16;
  return static_cast<std::uint16_t>((bits & 0xffffu) != 0 ? upper + 1 : upper);
}

// Fibonacci hashing of a tile's key into mask + 1 slots (a power of two).
std::size_t hashSlot(std::uint32_t key, std::size_t mask) {
  return static_cast<std::size_t>((key * 0x9e3779b97f4a7c15ull) >> 32) & mask;
}

constexpr std::size_t kFirstSlots = 64;

}  // namespace

double SoilGrid::fullBytes(double nodes) {
  // A tile, and its index slot at the least full the index gets (a quarter).
  constexpr double kPerTile = static_cast<double>(sizeof(Tile) + 4 * sizeof(Slot));
  return std::ceil(nodes / kNodes) * kPerTile;
}

SoilGrid::SoilGrid(const SoilRegion& region) : spec_(region) {
  validate(spec_, "soil grid");
  columns_ = static_cast<int>(std::floor(spec_.size.x() / spec_.spacing)) + 1;
  rows_ = static_cast<int>(std::floor(spec_.size.y() / spec_.spacing)) + 1;
}

std::uint32_t SoilGrid::key(int i, int j) {
  return (static_cast<std::uint32_t>(j / kTileNodes) << 16) | static_cast<std::uint32_t>(i / kTileNodes);
}

std::size_t SoilGrid::slot(std::uint32_t key) const {
  const std::size_t mask = index_.size() - 1;
  std::size_t at = hashSlot(key, mask);
  while (index_[at].key != key && index_[at].key != kEmpty) at = (at + 1) & mask;  // linear probing
  return at;
}

const SoilGrid::Tile* SoilGrid::find(int i, int j) const {
  if (index_.empty()) return nullptr;
  const Slot& s = index_[slot(key(i, j))];
  if (s.key == kEmpty) return nullptr;
  return &(*chunks_[s.tile / kChunkTiles])[s.tile % kChunkTiles];
}

void SoilGrid::grow() {
  std::vector<Slot> old(std::max(kFirstSlots, 2 * index_.size()), Slot{kEmpty, 0});
  old.swap(index_);
  for (const Slot& s : old) {
    if (s.key != kEmpty) index_[slot(s.key)] = s;
  }
}

bool SoilGrid::contains(double x, double y) const {
  const double u = (x - spec_.origin.x()) / spec_.spacing, v = (y - spec_.origin.y()) / spec_.spacing;
  return u >= 0.0 && v >= 0.0 && u <= columns_ - 1 && v <= rows_ - 1;
}

SoilNode SoilGrid::node(int i, int j) const {
  const Tile* tile = find(i, j);
  if (tile == nullptr) return {};
  const auto k = static_cast<std::size_t>((j % kTileNodes) * kTileNodes + i % kTileNodes);
  return {tile->sinkage[k], fromBfloat16(tile->pressure[k])};
}

void SoilGrid::set(int i, int j, const SoilNode& node) {
  // At most half full: a probe ends within a few slots.
  if (2 * (tile_count_ + 1) > index_.size()) grow();
  const std::uint32_t k = key(i, j);
  Slot& s = index_[slot(k)];
  if (s.key == kEmpty) {
    s = {k, static_cast<std::uint32_t>(tile_count_)};
    if (tile_count_ % kChunkTiles == 0) chunks_.push_back(std::make_unique<Chunk>());
    ++tile_count_;
  }
  Tile& tile = (*chunks_[s.tile / kChunkTiles])[s.tile % kChunkTiles];
  const int n = (j % kTileNodes) * kTileNodes + i % kTileNodes;
  const auto bit = static_cast<std::uint16_t>(1u << n);
  if ((tile.touched & bit) == 0) {
    tile.touched = static_cast<std::uint16_t>(tile.touched | bit);
    ++touched_;
  }
  tile.sinkage[static_cast<std::size_t>(n)] = node.plastic_sinkage;
  tile.pressure[static_cast<std::size_t>(n)] = toBfloat16(node.max_pressure);
}

SoilNode SoilGrid::sample(double x, double y) const {
  const double u = (x - spec_.origin.x()) / spec_.spacing, v = (y - spec_.origin.y()) / spec_.spacing;
  if (!(u >= 0.0 && v >= 0.0 && u <= columns_ - 1 && v <= rows_ - 1)) return {};
  // The cell's lower corner, kept inside so that the far edge interpolates
  // within the last cell.
  const int i = std::max(0, std::min(static_cast<int>(u), columns_ - 2));
  const int j = std::max(0, std::min(static_cast<int>(v), rows_ - 2));
  const double fu = u - i, fv = v - j;
  const auto at = [&](int di, int dj) {
    return i + di < columns_ && j + dj < rows_ ? node(i + di, j + dj) : SoilNode{};
  };
  const SoilNode a = at(0, 0), b = at(1, 0), c = at(0, 1), d = at(1, 1);
  const auto mix = [&](float SoilNode::*field) {
    return static_cast<float>((1 - fv) * ((1 - fu) * a.*field + fu * b.*field) +
                              fv * ((1 - fu) * c.*field + fu * d.*field));
  };
  return {mix(&SoilNode::plastic_sinkage), mix(&SoilNode::max_pressure)};
}

std::size_t SoilGrid::bytes() const {
  return chunks_.size() * sizeof(Chunk) + chunks_.capacity() * sizeof(void*) + index_.capacity() * sizeof(Slot);
}

}  // namespace wtc::detail
