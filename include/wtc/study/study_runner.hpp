#pragma once
// Making a study's runs (wtc::study): on this machine, a pool of worker
// threads (TBB) each starting one wtc-sim process at a time, or as a job
// list of the same wtc-sim commands for GNU parallel or a Slurm array.
// Either way each run goes into <out>/runs/<key>/ with the same files
// (summary.json, the CSV series), a finished run is never made again and an
// unfinished one is made anew, so a batch resumes where it stopped.
//
// Why processes and not engines in threads: Debian's ODE is built without
// its thread-local storage, and two ODE worlds stepping in two threads of
// one process corrupted the heap (measured: "malloc(): unaligned fastbin
// chunk" after about 40 runs), even with a threading implementation and a
// random stream per world (plugins/ode/sim). A process per run also keeps
// one run's crash from ending the study.
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
/// (>= 1), each by `wtc_sim` (the program) in its own process, its stderr
/// kept in <out>/logs/<key>.stderr. Each run is a function of its settings
/// only: its results do not depend on the number of workers or on what
/// runs beside it. `done` is called, one call at a time, as each run ends.
/// A run killed by a signal (an engine's assertion) is recorded as crashed
/// (a failed run; its summary says how). Every run's scene is loaded first
/// (study::checkStudyRuns): a setting it refuses is an InvalidInputError
/// before any run starts. A run wtc-sim refuses nonetheless (exit 2: its
/// output directory) is an InvalidInputError naming the run and wtc-sim's
/// message, after the runs under way end.
void runPlan(const StudyPlan& plan, const std::filesystem::path& out, int workers, const std::filesystem::path& wtc_sim,
             const std::function<void(const RunDone&)>& done = {});

/// wtc-sim's arguments for one run (after the program): its scene, its
/// directory, --skip-done --quiet --no-plots and its overrides.
std::vector<std::string> wtcSimArguments(const PlannedRun& run, const std::filesystem::path& out);

/// One shell command per run: `wtc_sim` and wtcSimArguments, quoted, so
/// each line is idempotent.
std::vector<std::string> jobLines(const StudyPlan& plan, const std::filesystem::path& out,
                                  const std::filesystem::path& wtc_sim);

}  // namespace wtc::study
