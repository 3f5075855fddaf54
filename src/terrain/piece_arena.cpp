// The stored pieces' arena (design note in piece_arena.hpp).
#include "piece_arena.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>
#include <unordered_map>
#include <vector>

#include "base/cache_line.hpp"
#include "base/huge_pages.hpp"
#include "builder_support.hpp"
#include "geometry/polyhedron_layout.hpp"

namespace wtc::detail {

namespace {

// A piece's numbers start on a cache line (kCacheLineBytes): a prism's 880
// bytes then span 14 lines, never 15.

constexpr std::size_t roundUp(std::size_t n, std::size_t to) { return (n + to - 1) / to * to; }

// FNV-1a over a topology's integers: equal topologies are found by hash,
// then compared whole.
std::uint64_t hashOf(std::span<const std::int32_t> topology) {
  std::uint64_t h = 1469598103934665603ull;
  for (const std::int32_t v : topology) {
    h ^= static_cast<std::uint32_t>(v);
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace

PieceArena::PieceArena(std::span<ConvexPolyhedron> pieces, std::span<const PendingPrisms* const> pending,
                       std::span<const std::int32_t> order, std::vector<std::uint32_t>& first_line) {
  using Layout = PolyhedronLayout;
  // The pending part holding stored position i, or null.
  const auto pendingAt = [&](std::size_t i) -> const PendingPrisms* {
    const auto after = std::upper_bound(pending.begin(), pending.end(), i,
                                        [](std::size_t at, const PendingPrisms* p) { return at < p->first; });
    if (after == pending.begin()) return nullptr;
    const PendingPrisms* p = *(after - 1);
    return i < p->first + p->count ? p : nullptr;
  };
  // A pending prism is made here, then copied to its place: its numbers'
  // size and its topology are every such prism's (makeCheckedPrism copies
  // one reference topology).
  ConvexPolyhedron scratch = Layout::empty();
  std::array<Eigen::Vector3d, 3> top, bottom;
  const auto make = [&](const PendingPrisms& p, std::size_t i) {
    p.corners(i - p.first, top, bottom);
    makeCheckedPrism(top, bottom, scratch);
  };
  std::size_t prism_number_bytes = 0;
  if (!pending.empty()) {
    make(*pending.front(), pending.front()->first);
    prism_number_bytes = Layout::numbers(scratch).size_bytes();
  }
  const auto numberBytes = [&](std::size_t i) {
    return pendingAt(i) != nullptr ? prism_number_bytes : Layout::numbers(pieces[i]).size_bytes();
  };
  // 1. Distinct topologies, and each piece's (an offset in integers).
  std::vector<std::int32_t> topologies;
  std::vector<std::size_t> topology_at(pieces.size());
  struct Stored {
    std::size_t at, size;  // in integers
  };
  std::unordered_map<std::uint64_t, std::vector<Stored>> seen;
  const auto store = [&](std::span<const std::int32_t> topology) {
    auto& same_hash = seen[hashOf(topology)];
    const auto same = std::find_if(same_hash.begin(), same_hash.end(), [&](const Stored& s) {
      return s.size == topology.size() && std::equal(topology.begin(), topology.end(),
                                                     topologies.begin() + static_cast<std::ptrdiff_t>(s.at));
    });
    if (same != same_hash.end()) return same->at;
    const std::size_t at = topologies.size();
    same_hash.push_back({at, topology.size()});
    topologies.insert(topologies.end(), topology.begin(), topology.end());
    ++topologies_;
    return at;
  };
  const std::size_t prism_topology_at = pending.empty() ? 0 : store(Layout::topology(scratch));
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    topology_at[i] = pendingAt(i) != nullptr ? prism_topology_at : store(Layout::topology(pieces[i]));
  }
  // 2. The block: numbers in `order`, each on a line, then the topologies.
  std::size_t number_bytes = 0;
  for (const std::int32_t i : order) number_bytes += roundUp(numberBytes(i), kCacheLineBytes);
  const std::size_t wanted = number_bytes + topologies.size() * sizeof(std::int32_t);
  if (number_bytes / kCacheLineBytes > std::numeric_limits<std::uint32_t>::max()) throw std::bad_alloc();
  huge_pages_ = wanted >= kHugePageBytes;
  const std::size_t alignment = huge_pages_ ? kHugePageBytes : kCacheLineBytes;
  bytes_ = roundUp(std::max<std::size_t>(wanted, 1), alignment);
  memory_ = std::aligned_alloc(alignment, bytes_);
  if (memory_ == nullptr) throw std::bad_alloc();
  // Before the first touch: the pages are then faulted in as huge ones.
  // Advice only; a kernel without transparent huge pages ignores it.
  if (huge_pages_) adviseHugePages(memory_, bytes_);
  auto* bytes = static_cast<unsigned char*>(memory_);
  auto* topology_base = reinterpret_cast<std::int32_t*>(bytes + number_bytes);
  if (!topologies.empty()) std::memcpy(topology_base, topologies.data(), topologies.size() * sizeof(std::int32_t));
  std::size_t at = 0;
  first_line.clear();
  first_line.reserve(order.size());
  for (const std::int32_t i : order) {
    first_line.push_back(static_cast<std::uint32_t>(at / kCacheLineBytes));
    auto* to = reinterpret_cast<double*>(bytes + at);
    const PendingPrisms* part = pendingAt(static_cast<std::size_t>(i));
    if (part != nullptr) make(*part, static_cast<std::size_t>(i));
    const ConvexPolyhedron& made = part != nullptr ? scratch : pieces[i];
    const std::span<const double> numbers = Layout::numbers(made);
    if (!numbers.empty()) std::memcpy(to, numbers.data(), numbers.size_bytes());
    if (part != nullptr) {
      Layout::adoptShape(pieces[i], scratch, to, topology_base + topology_at[i]);
    } else {
      Layout::useStorage(pieces[i], to, topology_base + topology_at[i]);
    }
    at += roundUp(numbers.size_bytes(), kCacheLineBytes);
  }
}

PieceArena::~PieceArena() { std::free(memory_); }

}  // namespace wtc::detail
