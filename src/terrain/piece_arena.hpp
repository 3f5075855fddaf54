#pragma once
// One block of memory for all the stored pieces of a terrain (internal to
// wtc::core). A piece built alone owns one block, its numbers then its
// topology (convex_polyhedron.hpp); a terrain of 10^6 pieces would then be
// 10^6 blocks wherever the allocator put them, and a wheel's few pieces
// would each cost a cache miss and a TLB miss of their own. The arena holds
// them instead:
// - the pieces' numbers in the order the caller gives (the index's leaf
//   order, in which pieces near in space are near in memory: a wheel's
//   pieces share pages and often lines), each starting on a cache line;
// - each distinct topology once (a heightfield's 10^6 prisms have one, so
//   the query reads it from a line that stays cached);
// - on 2 MB huge pages where the kernel grants them (madvise), so that a
//   walk over a gigabyte of pieces is not a walk over 4 KB pages' TLB
//   entries.
// The terrain owns its arena and its pieces point into it; a copy of a piece
// owns a block of its own again (ConvexPolyhedron's copy). A builder's
// pending prisms (pending_prisms.hpp) are made straight into it.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "base/cache_line.hpp"
#include "pending_prisms.hpp"
#include "wtc/geometry/aabb.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"

namespace wtc::detail {

/// A stored piece as the terrain's index reports it, one cache line each,
/// in the index's leaf order: the exact box the leaf test reads, the id it
/// reports, and where the piece and its numbers are, so that both can be
/// fetched before the caller asks for them (Terrain::overlapping).
struct alignas(kCacheLineBytes) PieceLeaf {
  Aabb box;                  ///< the piece's bounds (m)
  std::int32_t id = 0;       ///< its PieceId
  std::int32_t stored = 0;   ///< its position in the terrain's pieces
  std::uint32_t line = 0;    ///< its numbers' first cache line in the arena
};

class PieceArena {
 public:
  /// Moves the numbers and topologies of pieces[order[0]], pieces[order[1]],
  /// ... (every piece once) into one block and points each piece at them.
  /// The pieces at the positions of `pending` (sorted by first, disjoint)
  /// are made there instead, from their corners: the pieces given are
  /// placeholders. `first_line[k]` receives where pieces[order[k]]'s
  /// numbers start, in cache lines from base().
  PieceArena(std::span<ConvexPolyhedron> pieces, std::span<const PendingPrisms* const> pending,
             std::span<const std::int32_t> order, std::vector<std::uint32_t>& first_line);
  ~PieceArena();
  PieceArena(const PieceArena&) = delete;
  PieceArena& operator=(const PieceArena&) = delete;

  /// The block's first byte.
  const unsigned char* base() const { return static_cast<const unsigned char*>(memory_); }
  /// Bytes of the block (numbers, topologies, alignment).
  std::size_t memoryBytes() const { return bytes_; }
  /// Distinct topologies stored.
  std::size_t topologyCount() const { return topologies_; }
  /// True when the block was asked to sit on huge pages (large enough).
  bool hugePages() const { return huge_pages_; }

 private:
  void* memory_ = nullptr;
  std::size_t bytes_ = 0;
  std::size_t topologies_ = 0;
  bool huge_pages_ = false;
};

}  // namespace wtc::detail
