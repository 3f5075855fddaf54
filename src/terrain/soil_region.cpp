// A soil region's checks (wtc/terrain/soil_region.hpp).
#include "wtc/terrain/soil_region.hpp"

#include <algorithm>
#include <cmath>

#include "soil_grid.hpp"
#include "wtc/base/error.hpp"

namespace wtc {

void validate(const SoilRegion& s, const std::string& where) {
  const auto fail = [&](const std::string& what) { throw InvalidInputError(where + ": " + what); };
  if (!s.origin.allFinite()) fail("origin is not finite");
  if (!(std::isfinite(s.spacing) && s.spacing >= kMinSoilSpacingM)) {
    fail("spacing " + formatNumber(s.spacing) + " m: must be at least " + formatNumber(kMinSoilSpacingM) + " m");
  }
  for (int axis = 0; axis < 2; ++axis) {
    const char* name = axis == 0 ? "x" : "y";
    if (!(std::isfinite(s.size[axis]) && s.size[axis] > 0.0)) {
      fail(std::string("size along ") + name + " " + formatNumber(s.size[axis]) + " m: must be finite and > 0");
    }
  }
  if (!(s.flow_factor >= 0.0 && s.flow_factor <= 1.0)) {
    fail("flow_factor " + formatNumber(s.flow_factor) + ": must be in [0, 1] (the fraction of pressed soil raised)");
  }
  if (!(s.repose_angle_deg > 0.0 && s.repose_angle_deg < 90.0)) {
    fail("repose_angle_deg " + formatNumber(s.repose_angle_deg) + ": must be in (0, 90) (deg)");
  }
  if (!(std::isfinite(s.memory_cap_bytes) && s.memory_cap_bytes > 0.0)) {
    fail("memory cap " + formatNumber(s.memory_cap_bytes) + " bytes: must be finite and > 0");
  }
  const double across_x = std::floor(s.size.x() / s.spacing) + 1.0, across_y = std::floor(s.size.y() / s.spacing) + 1.0;
  const double nodes = across_x * across_y;
  using detail::SoilGrid;
  if (SoilGrid::fullBytes(nodes) > s.memory_cap_bytes) {
    fail(formatNumber(nodes) + " nodes (" + formatNumber(s.size.x()) + " x " + formatNumber(s.size.y()) + " m at " +
         formatNumber(s.spacing) + " m) would hold " + formatNumber(SoilGrid::fullBytes(nodes)) +
         " bytes once all are touched, beyond the cap of " + formatNumber(s.memory_cap_bytes) +
         " bytes: a coarser spacing, a smaller region or a larger memory cap");
  }
  if (std::max(across_x, across_y) > SoilGrid::kMaxNodesAcross) {
    fail(formatNumber(std::max(across_x, across_y)) + " nodes across: at most " +
         std::to_string(SoilGrid::kMaxNodesAcross) + " (a coarser spacing, or several regions)");
  }
}

}  // namespace wtc
