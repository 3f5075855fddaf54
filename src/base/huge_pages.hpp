#pragma once
// Transparent huge pages for the large arrays of a terrain (internal to
// wtc::core). A terrain of 10^6 pieces spreads its index and pieces over a
// gigabyte; a wheel's cold query touches a few lines in each of its arrays,
// and on 4 KB pages nearly every one of those lines also misses the TLB (a
// page walk, costlier still under virtualisation). On a kernel whose
// transparent_hugepage setting is "madvise" only memory advised so gets 2 MB
// pages; advice is only a hint, ignored where huge pages are off, and never
// changes what the memory holds.
#include <sys/mman.h>

#include <cstddef>
#include <cstdint>

namespace wtc::detail {

/// The size of an x86-64 / AArch64 (4 KB granule) transparent huge page
/// (bytes).
inline constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;

/// Advises huge pages for the whole 2 MB pages inside [data, data + bytes).
/// Call it before the memory is first written: pages already faulted in stay
/// small until the kernel's background scan collapses them.
inline void adviseHugePages(const void* data, std::size_t bytes) {
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t first = (begin + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
  const std::uintptr_t last = (begin + bytes) / kHugePageBytes * kHugePageBytes;
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
}

/// reserve(count) on `v`, its new block advised for huge pages when large.
template <class Vector>
void reserveHuge(Vector& v, std::size_t count) {
  if (count <= v.capacity()) return;
  Vector grown;
  grown.reserve(count);
  adviseHugePages(grown.data(), count * sizeof(typename Vector::value_type));
  for (auto& x : v) grown.push_back(std::move(x));
  v.swap(grown);
}

}  // namespace wtc::detail
