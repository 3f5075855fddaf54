#pragma once
// A contact on soft soil: the soil's stresses (wtc/tyre/wheel_soil.hpp) as
// the contact's force, for the soft_soil effect (internal to wtc).
#include <span>

#include "tyre_kernels.hpp"
#include "wtc/tyre/ground_memory.hpp"

namespace wtc::detail {

/// Replaces the force of every contact in `out` whose material has a soil
/// by the soil's, for a rigid wheel of radius r_f and width `width`. With
/// a ground memory (or null), a contact in one of its regions meets the
/// remembered surface and presses its nodes.
void applySoil(const KernelInputs& in, double width, std::span<const WheelContact> contacts, GroundMemory* memory,
               ContactForce* out);

}  // namespace wtc::detail
