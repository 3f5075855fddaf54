#include "wtc/sim/step_count.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "wtc/base/error.hpp"
#include "wtc/base/tolerances.hpp"

namespace wtc::sim {
namespace {

// The largest count a double holds exactly (and far beyond any run: 2^53
// steps of 1 us are 285 years).
constexpr double kMaxSteps = 9007199254740992.0;  // 2^53

// A suggested duration: 9 digits, so that 3 x 0.1 reads 0.3.
std::string approximately(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

}  // namespace

std::uint64_t stepCount(double duration_seconds, double dt_seconds) {
  const std::string both = "duration " + formatNumber(duration_seconds) + " s, dt " + formatNumber(dt_seconds) + " s";
  if (!(std::isfinite(duration_seconds) && duration_seconds > 0.0 && std::isfinite(dt_seconds) && dt_seconds > 0.0)) {
    throw InvalidInputError(both + ": both must be finite and > 0");
  }
  if (dt_seconds > duration_seconds) {
    throw InvalidInputError(both + ": the step is longer than the duration (no step would be simulated)");
  }
  const double n = duration_seconds / dt_seconds;
  if (!(n <= kMaxSteps)) throw InvalidInputError(both + ": " + formatNumber(n) + " steps, more than 2^53");
  const double whole = std::round(n);
  if (std::abs(n - whole) > tolerance::kWholeStepsRelative * n) {
    const double below = std::max(1.0, std::floor(n)) * dt_seconds, above = std::ceil(n) * dt_seconds;
    throw InvalidInputError(both + ": the duration is " + approximately(n) +
                            " steps, not a whole number of them; the nearest durations that are: " +
                            approximately(below) + " s and " + approximately(above) + " s");
  }
  return static_cast<std::uint64_t>(whole);
}

}  // namespace wtc::sim
