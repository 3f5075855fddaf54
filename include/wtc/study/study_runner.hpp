#pragma once
// Making a study's runs (wtc::study): in this process on a pool of worker
// threads (TBB), or as a job list of wtc-sim commands for GNU parallel or a
// Slurm array. Either way each run goes into <out>/runs/<key>/ with the same
// files (summary.json, the CSV series), a finished run is never made again
// and an unfinished one is made anew, so a batch resumes where it stopped.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "wtc/sim/scene_run.hpp"
#include "wtc/study/study_plan.hpp"

namespace wtc::study {

/// <out>/runs/<run.key>
std::filesystem::path runDirectory(const std::filesystem::path& out, const PlannedRun& run);

struct RunDone {
  const PlannedRun& run;
  const sim::RunSummary* summary;  ///< Null when the run had finished earlier (skipped).
  std::size_t done, total;
};

/// Makes every run of `plan` not finished in `out`, `workers` at a time
/// (>= 1). Each run is a function of its settings only: its results do
/// not depend on the number of workers or on what runs beside it (the
/// ODE engine keeps its own random stream; see plugins/ode/sim). `done` is
/// called, one call at a time, as each run ends. An error in a run (a
/// scene that does not load) is rethrown naming the run, after the runs
/// under way end.
void runPlan(const StudyPlan& plan, const std::filesystem::path& out, int workers,
             const std::function<void(const RunDone&)>& done = {});

/// One shell command per run: `wtc_sim` with the run's scene, overrides and
/// directory, and --skip-done, so each line is idempotent.
std::vector<std::string> jobLines(const StudyPlan& plan, const std::filesystem::path& out,
                                  const std::filesystem::path& wtc_sim);

}  // namespace wtc::study
