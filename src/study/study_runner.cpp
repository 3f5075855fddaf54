#include "wtc/study/study_runner.hpp"

#include <mutex>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "wtc/error.hpp"
#include "wtc/io/run_summary_file.hpp"
#include "wtc/sim/make_engine.hpp"

namespace wtc::study {
namespace {

namespace fs = std::filesystem;

// A shell word: single-quoted, with ' written as '\''.
std::string shellQuote(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) {
    if (c == '\'') {
      quoted.append("'\\''");
    } else {
      quoted.push_back(c);
    }
  }
  quoted.push_back('\'');
  return quoted;
}

// What `wtc-sim --out dir --skip-done --no-plots` does for one run that has
// not finished: the same files, in the same directory.
sim::RunSummary makeRun(const PlannedRun& run, const fs::path& dir) {
  const sim::Scene scene = io::loadScene(run.scene_file, run.overrides);
  const auto engine = sim::makeEngine(scene.engine, *scene.terrain, scene.vehicle, scene.placement);
  if (fs::exists(dir)) fs::remove_all(dir);  // an unfinished run's files
  fs::create_directories(dir);
  io::writeRunStarted(dir / "summary.json", scene);
  sim::RunOptions options;
  options.out_dir = dir;
  const sim::RunSummary summary = sim::runScene(scene, *engine, options);
  io::writeRunSummary(dir / "summary.json", summary);
  return summary;
}

}  // namespace

fs::path runDirectory(const fs::path& out, const PlannedRun& run) { return out / "runs" / run.key; }

void runPlan(const StudyPlan& plan, const fs::path& out, int workers, const std::function<void(const RunDone&)>& done) {
  if (workers < 1) throw InvalidInputError("wtc::study::runPlan: workers must be >= 1, not " + std::to_string(workers));
  std::mutex lock;
  std::size_t finished = 0;
  tbb::task_arena arena(workers);
  arena.execute([&] {
    // Grain 1: runs differ in cost by 1000x, so each worker takes the next one.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, plan.runs.size(), 1), [&](const auto& range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        const PlannedRun& run = plan.runs[i];
        const fs::path dir = runDirectory(out, run);
        std::optional<sim::RunSummary> summary;
        if (!io::runCompleted(dir)) {
          try {
            summary = makeRun(run, dir);
          } catch (const std::exception& e) {
            throw InvalidInputError("study " + plan.name + ", run " + run.key + " (" + run.scenario + ", " +
                                    run.label + "): " + e.what());
          }
        }
        const std::lock_guard<std::mutex> guard(lock);
        ++finished;
        if (done) done({run, summary ? &*summary : nullptr, finished, plan.runs.size()});
      }
    });
  });
}

std::vector<std::string> jobLines(const StudyPlan& plan, const fs::path& out, const fs::path& wtc_sim) {
  std::vector<std::string> lines;
  for (const PlannedRun& run : plan.runs) {
    // Built with append: GCC 12 warns falsely (-Wrestrict) on long chains of std::string +.
    std::string line = shellQuote(wtc_sim.string());
    line.append(" ").append(shellQuote(run.scene_file.string()));
    line.append(" --out ").append(shellQuote(runDirectory(out, run).string()));
    line.append(" --skip-done --quiet --no-plots");
    for (const io::Override& o : run.overrides) line.append(" --set ").append(shellQuote(o.path + "=" + o.value));
    lines.push_back(std::move(line));
  }
  return lines;
}

}  // namespace wtc::study
