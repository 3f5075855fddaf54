// wtc-study: what accuracy costs in time. Runs a study file's settings
// (bench/accuracy_study.yaml) on all cores, or writes them as a job list
// for GNU parallel or a Slurm array, and gathers the finished runs into
// tables and a figure. It parses, runs and writes; the study is wtc::study.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>

#include "app_files.hpp"
#include "wtc/base/error.hpp"
#include "wtc/study/study_file.hpp"
#include "wtc/study/study_results.hpp"
#include "wtc/study/study_runner.hpp"

namespace {

namespace fs = std::filesystem;

// Tables and the figure from the finished runs in `out`.
int gather(const wtc::study::StudyPlan& plan, const fs::path& out, bool plots) {
  const std::vector<wtc::study::RunResult> results = wtc::study::gatherResults(plan, out);
  wtc::study::writeResultsCsv(out / "results.csv", results);
  wtc::study::writeResultsMarkdown(out / "results.md", plan, results);
  std::printf("wtc-study: %zu runs gathered: %s, %s\n", results.size(), (out / "results.md").c_str(),
              (out / "results.csv").c_str());
  if (const auto programs = wtc::study::programsOf(results); programs.size() > 1) {
    std::fprintf(stderr,
                 "wtc-study: warning: the runs were made by %zu different builds of wtc-sim; delete %s and make "
                 "them again with one (results.md says which)\n",
                 programs.size(), (out / "runs").c_str());
  }
  if (plots && !wtc::apps::runPlotScript(wtc::apps::ownFile("wtc-study", "plot_study.py"), out)) {
    std::fprintf(stderr, "wtc-study: warning: figure not drawn (python3 with matplotlib is needed)\n");
  }
  return 0;
}

// The wtc-sim the runs use: `given`, else the one installed or built beside
// this program.
fs::path wtcSim(const std::string& given) {
  if (!given.empty()) return fs::absolute(given);
  const fs::path beside = fs::canonical("/proc/self/exe").parent_path() / "wtc-sim";
  if (!fs::exists(beside))
    throw wtc::InvalidInputError("no wtc-sim beside wtc-study (" + beside.string() + "): give --wtc-sim");
  return beside;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"wtc-study: what accuracy costs in time (a study file's runs against a reference)"};
  app.require_subcommand(1);
  std::string study_file, out, wtc_sim;
  int workers = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  bool no_plots = false;
  for (CLI::App* sub : {app.add_subcommand("run", "make the runs not finished yet, on --workers threads, then gather"),
                        app.add_subcommand("jobs", "write <out>/jobs.txt: one wtc-sim command per run"),
                        app.add_subcommand("gather", "tables and figure from the finished runs in <out>")}) {
    sub->add_option("study", study_file, "study file (YAML)")->required();
    sub->add_option("--out", out, "the study's directory (default study/<name>)");
    sub->add_flag("--no-plots", no_plots, "skip the figure");
  }
  app.get_subcommand("run")->add_option("--workers", workers, "simulations at once, at least 1 (default: the cores)");
  for (const char* name : {"run", "jobs"}) {
    app.get_subcommand(name)->add_option("--wtc-sim", wtc_sim,
                                         "the wtc-sim that makes the runs (default: the one beside)");
  }
  wtc::apps::addVersionFlag(app, "wtc-study");
  if (const auto status = wtc::apps::parseCommandLine(app, argc, argv)) return *status;
  if (app.got_subcommand("run") && workers < 1) {
    std::cerr << "wtc-study: --workers " << workers << ": must be at least 1 (simulations at once)\n";
    return 2;
  }

  try {
    const wtc::study::StudyPlan plan = wtc::study::loadStudyPlan(study_file);
    const fs::path dir = out.empty() ? fs::path("study") / plan.name : fs::path(out);
    if (app.got_subcommand("run")) {
      std::printf("wtc-study: %s: %zu runs on %d workers into %s\n", plan.name.c_str(), plan.runs.size(), workers,
                  dir.c_str());
      wtc::study::runPlan(plan, dir, workers, wtcSim(wtc_sim), [](const wtc::study::RunDone& d) {
        if (d.summary == nullptr) {
          std::printf("[%zu/%zu] %s %s: finished earlier\n", d.done, d.total, d.run.scenario.c_str(),
                      d.run.label.c_str());
        } else {
          std::string outcome = d.summary->crashed ? "CRASHED" : d.summary->success ? "success" : "FAILED";
          const auto& failed = d.summary->failed_criteria;  // "FAILED (min_distance, energy)"
          for (std::size_t i = 0; i < failed.size(); ++i)
            outcome.append(i == 0 ? " (" : ", ").append(failed[i].criterion);
          if (!failed.empty()) outcome.append(")");
          std::printf("[%zu/%zu] %s %s: %s, %.1f s wall, %.1fx real time\n", d.done, d.total, d.run.scenario.c_str(),
                      d.run.label.c_str(), outcome.c_str(), d.summary->wall_time, d.summary->real_time_factor);
        }
        std::fflush(stdout);
      });
      return gather(plan, dir, !no_plots);
    }
    if (app.got_subcommand("jobs")) {
      wtc::study::checkStudyRuns(plan);
      const fs::path sim = wtcSim(wtc_sim);
      fs::create_directories(dir);
      std::ofstream lines(dir / "jobs.txt");
      for (const std::string& line : wtc::study::jobLines(plan, fs::absolute(dir), sim)) lines << line << '\n';
      if (!lines) throw wtc::InvalidInputError("cannot write " + (dir / "jobs.txt").string());
      std::printf("wtc-study: %zu jobs in %s\n", plan.runs.size(), (dir / "jobs.txt").c_str());
      return 0;
    }
    return gather(plan, dir, !no_plots);
  } catch (const std::exception& e) {
    std::cerr << "wtc-study: " << e.what() << '\n';
    return 2;
  }
}
