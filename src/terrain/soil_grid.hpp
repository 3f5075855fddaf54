#pragma once
// The memory of a soft ground (internal to wtc::core; issue 55, the ground
// that remembers; docs/soft-soil.md): a grid of nodes over a soil region,
// each with the plastic sinkage it keeps (a rut; negative where bulldozed
// soil was raised) and the largest pressure it has carried (what a second
// pass reloads elastically up to).
//
// Only touched nodes cost memory. Nodes live in tiles of kTileNodes x
// kTileNodes, allocated the first time one of their nodes is written, kept
// in chunks (no copy of them all as they grow); an open-addressing index
// maps a tile's coordinates to it (8 bytes a slot, at most half full).
// Untouched ground costs nothing, and a long run over the same ground
// touches no new tiles. A node holds 6 bytes: the sinkage as a float (a
// rut's millimetres need no more than single precision's 7 digits) and the
// largest pressure as a bfloat16 (a float's upper half, rounded up: within
// 0.8 % above the pressure, so a reload is never taken for a first load).
// Small tiles keep a rut's stored nodes close to its touched ones: a rut
// five nodes wide (a 0.11 m wheel at 2 cm) fills 5/8 of the tiles it
// crosses at worst.
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wtc/terrain/soil_region.hpp"

namespace wtc::detail {

/// A bfloat16's float: its bits as a float's upper half.
inline float fromBfloat16(std::uint16_t half) { return std::bit_cast<float>(static_cast<std::uint32_t>(half) << 16); }

/// One node's memory.
struct SoilNode {
  float plastic_sinkage = 0.0f;  ///< Below the base surface (m); < 0 where raised.
  float max_pressure = 0.0f;     ///< The largest normal stress it has carried (Pa).
};

class SoilGrid {
 public:
  static constexpr int kTileNodes = 4;
  /// The most nodes a region may have along x or y: a tile's coordinate
  /// fits in 16 bits.
  static constexpr int kMaxNodesAcross = 65535 * kTileNodes;

  /// Validates `spec` (where: "soil grid").
  explicit SoilGrid(const SoilRegion& region);

  const SoilRegion& spec() const { return spec_; }
  /// Nodes along x and y: size / spacing + 1, each.
  int columns() const { return columns_; }
  int rows() const { return rows_; }
  /// Whether (x, y) lies in the region (its nodes' hull).
  bool contains(double x, double y) const;

  /// Node (i, j): the stored one, or a fresh one (zeros) where none is.
  /// Precondition: 0 <= i < columns(), 0 <= j < rows().
  SoilNode node(int i, int j) const;
  /// Writes node (i, j) (its max_pressure rounded up to a bfloat16),
  /// allocating its tile the first time.
  void set(int i, int j, const SoilNode& node);

  /// The nodes' memory at (x, y), bilinear between the four nodes around
  /// it (a fresh node outside the region).
  SoilNode sample(double x, double y) const;

  /// Calls visit(i, j, node) for every touched node, tile by tile (in the
  /// index's order: no set one).
  template <class Visit>
  void forEachTouched(Visit&& visit) const;

  std::size_t touchedNodes() const { return touched_; }
  std::size_t tiles() const { return tile_count_; }
  /// What the memory holds now (bytes): the tiles, the index's nodes and
  /// buckets as libstdc++ lays them out.
  std::size_t bytes() const;
  /// The most a region of these nodes may hold, every node touched (bytes).
  static double fullBytes(double nodes);

 private:
  static constexpr int kNodes = kTileNodes * kTileNodes;
  static constexpr std::size_t kChunkTiles = 256;
  struct Tile {
    std::uint16_t touched = 0;                     ///< Bit k: node k has been written.
    std::array<std::uint16_t, kNodes> pressure{};  ///< bfloat16.
    std::array<float, kNodes> sinkage{};
  };
  using Chunk = std::array<Tile, kChunkTiles>;
  /// An index slot: a tile's key (tile_j << 16 | tile_i; kEmpty: none) and
  /// its number.
  struct Slot {
    std::uint32_t key;
    std::uint32_t tile;
  };
  static constexpr std::uint32_t kEmpty = 0xffffffffu;
  static std::uint32_t key(int i, int j);
  /// The slot of `key`: its own, or the empty one where it would go.
  std::size_t slot(std::uint32_t key) const;
  const Tile* find(int i, int j) const;
  void grow();

  SoilRegion spec_;
  int columns_ = 0, rows_ = 0;
  std::vector<std::unique_ptr<Chunk>> chunks_;
  std::size_t tile_count_ = 0;
  std::vector<Slot> index_;
  std::size_t touched_ = 0;
};

template <class Visit>
void SoilGrid::forEachTouched(Visit&& visit) const {
  // A tile's coordinates live in its index slot's key (tile_j << 16 | tile_i).
  for (const Slot& s : index_) {
    if (s.key == kEmpty) continue;
    const Tile& tile = (*chunks_[s.tile / kChunkTiles])[s.tile % kChunkTiles];
    const int ti = static_cast<int>(s.key & 0xffffu) * kTileNodes, tj = static_cast<int>(s.key >> 16) * kTileNodes;
    for (int n = 0; n < kNodes; ++n) {
      if ((tile.touched & (1u << n)) == 0) continue;
      const auto k = static_cast<std::size_t>(n);
      visit(ti + n % kTileNodes, tj + n / kTileNodes, SoilNode{tile.sinkage[k], fromBfloat16(tile.pressure[k])});
    }
  }
}

}  // namespace wtc::detail
