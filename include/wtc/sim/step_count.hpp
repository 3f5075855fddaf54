#pragma once
// How many steps a run makes (wtc::sim): a run simulates exactly its
// duration, so the duration must be a whole number of steps (to roundoff,
// tolerance::kWholeStepsRelative). A step longer than the duration, or a
// duration between two whole numbers of steps, is refused rather than
// rounded: rounding ran 0 steps for dt > duration (and reported a success
// without simulating) and 30 s for a 25 s scene at dt = 10 s.
#include <cstdint>

namespace wtc::sim {

/// duration / dt when it is a whole number (to roundoff), >= 1 and at most
/// 2^53 (every count a double holds exactly). Otherwise InvalidInputError
/// naming both numbers and, for a duration between two whole numbers of
/// steps, the nearest durations that are whole.
std::uint64_t stepCount(double duration_seconds, double dt_seconds);

}  // namespace wtc::sim
