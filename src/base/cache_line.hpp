#pragma once
// The cache line the stored pieces are laid out by (internal to wtc::core):
// a piece's block and its numbers in a terrain's arena start on one, a leaf
// record fills one, and the index prefetches by it. 64 bytes on x86-64 and
// on the AArch64 cores WTC is built for.
#include <cstddef>

namespace wtc::detail {

/// Bytes of a cache line.
inline constexpr std::size_t kCacheLineBytes = 64;

}  // namespace wtc::detail
