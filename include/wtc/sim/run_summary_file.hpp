#pragma once
// summary.json (wtc::io): a run's summary as wtc-sim and wtc-study write it
// (the fields: docs/vehicles-and-scenes.md). Written whole, then renamed,
// so a reader never sees half of one; read back to gather a study.
#include <filesystem>
#include <string>

#include "wtc/sim/run_summary.hpp"
#include "wtc/sim/scene.hpp"

namespace wtc::sim {

/// summary.json's text for `summary`: what writeRunSummary writes, and the
/// one source of the summary the Python package returns (wtc.run,
/// Simulation.summary()), so that the two cannot differ by a key.
std::string runSummaryText(const sim::RunSummary& summary);

void writeRunSummary(const std::filesystem::path& file, const sim::RunSummary& summary);

/// What a run writes before its first step: status "running", success
/// false. A run killed before its end (SIGKILL, a power cut) leaves it;
/// the end replaces it.
void writeRunStarted(const std::filesystem::path& file, const sim::Scene& scene);

/// Over the summary a run left when its process died of `signal`:
/// status "crashed", success false, `reason` as its warning.
void writeRunCrashed(const std::filesystem::path& file, const std::string& reason);

/// Over the summary a run left when an error ended it (an exception out of
/// runScene: a Python controller that raised, a command that is not a
/// number): status "failed", success false, `reason` as its warning and
/// its failed criterion "error". Without it the start's "running" would
/// stay, and a study or a script reading it later would take a dead run for
/// a live one. Not an ended run for runEnded: run again, it is made again.
void writeRunFailed(const std::filesystem::path& file, const std::string& reason);

/// The summary in `file`; a run that did not end reads as interrupted.
/// InvalidInputError naming the file if it is missing or not a summary.
sim::RunSummary readRunSummary(const std::filesystem::path& file);

/// Whether `dir` holds a run that ended: its summary.json says "completed",
/// or "crashed" (made again, it would crash again; delete the directory to
/// retry).
bool runEnded(const std::filesystem::path& dir);

}  // namespace wtc::sim
