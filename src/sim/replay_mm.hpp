#pragma once
// Lengths in the replay file (internal to wtc::sim): whole millimetres, as
// replay.html reads them (include/wtc/sim/replay.hpp), for the bodies and
// the terrain alike.
#include <cmath>

namespace wtc::sim {

inline constexpr double kReplayMmPerM = 1000.0;

/// `metres` (m) rounded to the nearest millimetre.
inline long long replayMm(double metres) { return std::llround(metres * kReplayMmPerM); }

}  // namespace wtc::sim
