#pragma once
// Counting allocations (tests that check "a warm step allocates nothing"):
// an executable that links wtc_allocation_counter replaces the global
// operator new with one that counts, so give such tests an executable of
// their own: the counter sees only them.

namespace wtc::testing {

/// operator new calls since the program started.
long allocationCount();

}  // namespace wtc::testing
