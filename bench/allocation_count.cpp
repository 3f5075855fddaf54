// The global operator new, counting (allocation_count.hpp).
#include "allocation_count.hpp"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {

// The benchmarks are single-threaded: a relaxed load and store count exactly
// without the locked add that would slow every allocation down.
std::atomic<std::size_t> g_allocations{0};

}  // namespace

std::size_t wtc::bench::allocationCount() { return g_allocations.load(std::memory_order_relaxed); }

void* operator new(std::size_t size) {
  g_allocations.store(g_allocations.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
