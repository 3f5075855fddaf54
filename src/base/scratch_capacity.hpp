#pragma once
// What a wheel's scratch memory is made for when the wheel is made (the
// core, the adapters and the run loop reserve it): a step that meets no
// more contacts or candidate pieces than these allocates nothing, even the first time a wheel meets that many
// (counted in tests/sim/step_allocation_test.cpp). More grow the memory
// once. Contacts: a wheel touches one to three pieces on a ledge or a
// seam; candidates: the pieces whose boxes a wheel's box overlaps, a few
// dozen on a fine heightfield.
#include <cstddef>

namespace wtc {

inline constexpr std::size_t kReservedContacts = 8;     // count
inline constexpr std::size_t kReservedCandidates = 64;  // count

}  // namespace wtc
