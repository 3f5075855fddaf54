#pragma once
// Heap allocations counted by the benchmarks that claim a warm step
// allocates nothing (wtc_bench_forces, wtc_bench_spacing): allocation_count.cpp
// replaces the global operator new, so link it into a benchmark only.
#include <cstddef>

namespace wtc::bench {

/// Calls of operator new since the program started.
std::size_t allocationCount();

}  // namespace wtc::bench
