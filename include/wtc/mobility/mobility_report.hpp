#pragma once
// The mobility report (wtc::mobility): report.json (every event, engine and
// mode: measured, bound, governing limit, the search's trials) and
// report.md (one table), in the output directory; plot_mobility.py draws
// the figures from report.json (DP/W against slip, the searches).
#include <filesystem>
#include <string>

#include "wtc/mobility/mobility_run.hpp"

namespace wtc::mobility {

/// Writes <out>/report.json and <out>/report.md; `command` is the command
/// line that made it (for the report's header).
void writeReport(const EventVehicle& vehicle, const MobilitySettings& settings, const MobilityOutcome& outcome,
                 const std::filesystem::path& out, const std::string& command);

/// report.md's table, as text (a row per event, engine and mode).
std::string reportTable(const MobilityOutcome& outcome);

}  // namespace wtc::mobility
