#include "wtc/study/study_runner.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <mutex>
#include <optional>
#include <sstream>

#include "wtc/base/error.hpp"
#include "wtc/sim/run_summary_file.hpp"
#include "wtc/study/study_file.hpp"

extern char** environ;

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

std::string fileText(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs `program args...` with stdout to /dev/null and stderr to `log`;
// returns its wait status.
int spawnAndWait(const fs::path& program, const std::vector<std::string>& args, const fs::path& log) {
  std::vector<std::string> words{program.string()};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&files, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, program.c_str(), &files, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  if (error != 0) throw InvalidInputError("cannot start " + program.string() + ": " + std::strerror(error));
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw InvalidInputError("waiting for " + program.string() + ": " + std::strerror(errno));
  }
  return status;
}

// One run by wtc-sim in its own process. Returns its summary.
sim::RunSummary makeRun(const PlannedRun& run, const fs::path& out, const fs::path& wtc_sim) {
  const fs::path dir = runDirectory(out, run);
  const fs::path log = out / "logs" / (run.key + ".stderr");
  const int status = spawnAndWait(wtc_sim, wtcSimArguments(run, out), log);
  if (WIFSIGNALED(status)) {
    // The run's own last words (an engine's assertion) say more than the signal.
    std::string last = fileText(log);
    while (!last.empty() && (last.back() == '\n' || last.back() == '\r')) last.pop_back();
    last = last.substr(last.rfind('\n') == std::string::npos ? 0 : last.rfind('\n') + 1);
    const std::string reason = std::string("the run's process died of signal ") + std::to_string(WTERMSIG(status)) +
                               " (" + strsignal(WTERMSIG(status)) + ")" + (last.empty() ? "" : ": " + last);
    fs::create_directories(dir);
    sim::writeRunCrashed(dir / "summary.json", reason);
  } else if (WEXITSTATUS(status) != 0 && WEXITSTATUS(status) != 1) {  // 1: the scene's criterion failed
    throw InvalidInputError(fileText(log));
  }
  return sim::readRunSummary(dir / "summary.json");
}

}  // namespace

fs::path runDirectory(const fs::path& out, const PlannedRun& run) { return out / "runs" / run.key; }

std::vector<std::string> wtcSimArguments(const PlannedRun& run, const fs::path& out) {
  std::vector<std::string> args = {run.scene_file.string(), "--out",   runDirectory(out, run).string(),
                                   "--skip-done",           "--quiet", "--no-plots"};
  for (const sim::Override& o : run.overrides) {
    args.push_back("--set");
    args.push_back(o.path + "=" + o.value);
  }
  return args;
}

void runPlan(const StudyPlan& plan, const fs::path& out, int workers, const fs::path& wtc_sim,
             const std::function<void(const RunDone&)>& done) {
  if (workers < 1) throw InvalidInputError("wtc::study::runPlan: workers must be >= 1, not " + std::to_string(workers));
  study::checkStudyRuns(plan);  // every run loads before any is made
  fs::create_directories(out / "logs");
  std::mutex lock;
  std::size_t finished = 0;
  tbb::task_arena arena(workers);
  arena.execute([&] {
    // Grain 1: runs differ in cost by 1000x, so each worker takes the next one.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, plan.runs.size(), 1), [&](const auto& range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        const PlannedRun& run = plan.runs[i];
        std::optional<sim::RunSummary> summary;
        if (!sim::runEnded(runDirectory(out, run))) {
          try {
            summary = makeRun(run, out, wtc_sim);
          } catch (const std::exception& e) {
            throw InvalidInputError("study " + plan.name + ", run " + run.key + " (" + run.scenario + ", " + run.label +
                                    "): " + e.what());
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
    std::string line = shellQuote(wtc_sim.string());
    for (const std::string& arg : wtcSimArguments(run, out)) line.append(" ").append(shellQuote(arg));
    lines.push_back(std::move(line));
  }
  return lines;
}

}  // namespace wtc::study
