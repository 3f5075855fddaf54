#include "wtc/study/study_results.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>

#include <Eigen/Core>

#include "io/atomic_file.hpp"
#include "series.hpp"
#include "wtc/base/constants.hpp"
#include "wtc/base/error.hpp"
#include "wtc/sim/run_summary_file.hpp"
#include "wtc/study/study_runner.hpp"

namespace wtc::study {
namespace {

namespace fs = std::filesystem;
using detail::Series;

// bodies.csv: t, then the first body's x y z (Recorder).
constexpr std::size_t kFirstBodyX = 1;

// A run's series, with the columns and figures the measures need.
struct RunSeries {
  Series bodies, wheels;
  std::vector<std::size_t> wheel_fx;  // fx of each wheel; fy fz follow
  double peak_pitch_deg = 0.0;        // the largest |pitch| of a body that is not a wheel
};

Eigen::Vector3d vec(const std::vector<double>& row, std::size_t c) { return {row[c], row[c + 1], row[c + 2]}; }
Eigen::Vector3d vecAt(const Series& s, std::size_t c, double t) {
  return {detail::valueAt(s, c, t), detail::valueAt(s, c + 1, t), detail::valueAt(s, c + 2, t)};
}

// The angle of the body's x axis above the horizontal: asin(R_20), R_20 = 2 (qx qz - qw qy).
double pitchDeg(const std::vector<double>& row, std::size_t qw) {
  const double w = row[qw], x = row[qw + 1], y = row[qw + 2], z = row[qw + 3];
  return std::asin(std::clamp(2.0 * (x * z - w * y), -1.0, 1.0)) * kDegPerRad;
}

RunSeries readRun(const fs::path& dir) {
  RunSeries r;
  r.bodies = detail::readSeries(dir / "bodies.csv");
  r.wheels = detail::readSeries(dir / "wheels.csv");
  std::set<std::string> wheels;
  for (const std::string& n : r.wheels.names) {
    if (n.ends_with(".contacts")) {
      const std::string name = n.substr(0, n.size() - 9);
      wheels.insert(name);
      r.wheel_fx.push_back(r.wheels.column(name + ".fx_N"));
    }
  }
  if (r.bodies.names.size() < 2) throw InvalidInputError((dir / "bodies.csv").string() + ": no body");
  std::vector<std::size_t> pitched_qw;  // qw of each body that is not a wheel; qx qy qz follow
  for (std::size_t c = kFirstBodyX; c < r.bodies.names.size(); ++c) {
    const std::string& n = r.bodies.names[c];
    if (n.ends_with(".qw") && !wheels.contains(n.substr(0, n.size() - 3))) pitched_qw.push_back(c);
  }
  for (const auto& row : r.bodies.rows) {
    for (const std::size_t qw : pitched_qw) r.peak_pitch_deg = std::max(r.peak_pitch_deg, std::abs(pitchDeg(row, qw)));
  }
  return r;
}

void measure(RunResult& out, const RunSeries& run, const RunSeries& ref) {
  const double t_end = std::min(run.bodies.rows.back()[0], ref.bodies.rows.back()[0]);
  double sum_sq = 0.0;
  std::size_t n = 0;
  for (const auto& row : run.bodies.rows) {
    if (row[0] > t_end) break;
    sum_sq += (vec(row, kFirstBodyX) - vecAt(ref.bodies, kFirstBodyX, row[0])).squaredNorm();
    ++n;
  }
  out.rms_position_error = n > 0 ? std::sqrt(sum_sq / static_cast<double>(n)) : 0.0;
  out.final_position_error = (vecAt(run.bodies, kFirstBodyX, t_end) - vecAt(ref.bodies, kFirstBodyX, t_end)).norm();
  out.peak_pitch_deg = run.peak_pitch_deg;
  out.peak_pitch_error_deg = std::abs(run.peak_pitch_deg - ref.peak_pitch_deg);

  double force_sq = 0.0;
  std::size_t m = 0;
  for (const auto& row : run.wheels.rows) {
    for (std::size_t w = 0; w < run.wheel_fx.size(); ++w) {
      const double f = vec(row, run.wheel_fx[w]).norm();
      out.peak_wheel_force = std::max(out.peak_wheel_force, f);
      if (row[0] > t_end || w >= ref.wheel_fx.size()) continue;
      const double f_ref = vecAt(ref.wheels, ref.wheel_fx[w], row[0]).norm();
      force_sq += (f - f_ref) * (f - f_ref);
      ++m;
    }
  }
  out.rms_wheel_force_error = m > 0 ? std::sqrt(force_sq / static_cast<double>(m)) : 0.0;
}

void markFront(std::vector<RunResult>& results) {
  std::map<std::string, std::vector<RunResult*>> by_scenario;
  for (RunResult& r : results) {
    if (r.summary.success) by_scenario[r.run->scenario].push_back(&r);
  }
  for (auto& [scenario, runs] : by_scenario) {
    std::sort(runs.begin(), runs.end(), [](const RunResult* a, const RunResult* b) {
      return a->summary.wall_time != b->summary.wall_time ? a->summary.wall_time < b->summary.wall_time
                                                          : a->rms_position_error < b->rms_position_error;
    });
    double best = std::numeric_limits<double>::infinity();
    for (RunResult* r : runs) {
      if (r->rms_position_error < best) {
        r->on_front = true;
        best = r->rms_position_error;
      }
    }
  }
}

std::string number(double v, const char* format = "%.6g") {
  char text[40];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

std::string csvText(std::string text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string join(const std::vector<std::string>& cells, const char* separator) {
  std::string text;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i > 0) text.append(separator);
    text.append(cells[i]);
  }
  return text;
}

// The rate at which wheels lost the ground (scene_run.cpp: a measure of
// contact jitter), 0 for runs made before it was counted.
double contactBreaksPerSecond(const sim::RunSummary& s) {
  const auto found = s.fields.find("contact_breaks_per_s");
  return found == s.fields.end() ? 0.0 : found->second;
}

// Why a run failed, one text: each failed criterion (sim::describe), "; "
// between them; "" for a success.
std::string failedText(const sim::RunSummary& s) {
  std::string text;
  for (const sim::FailedCriterion& f : s.failed_criteria)
    text.append(text.empty() ? "" : "; ").append(sim::describe(f));
  return text;
}

// `text` for a Markdown table's cell: '|' escaped, no line breaks.
std::string cellText(const std::string& text) {
  std::string cell;
  for (const char c : text) {
    if (c == '|') {
      cell.append("\\|");
    } else {
      cell.push_back(c == '\n' || c == '\r' ? ' ' : c);
    }
  }
  return cell;
}

}  // namespace

std::vector<RunResult> gatherResults(const StudyPlan& plan, const fs::path& out) {
  std::string unfinished;
  for (const PlannedRun& run : plan.runs) {
    if (!sim::runEnded(runDirectory(out, run))) unfinished += "\n  " + run.key + " (" + run.label + ")";
  }
  if (!unfinished.empty()) {
    throw InvalidInputError("study " + plan.name + ": runs not finished in " + (out / "runs").string() + ":" +
                            unfinished);
  }
  std::map<std::string, RunSeries> references;
  for (const PlannedRun& run : plan.runs) {
    if (!run.reference) continue;
    const fs::path dir = runDirectory(out, run);
    const sim::RunSummary s = sim::readRunSummary(dir / "summary.json");
    if (s.crashed) {
      throw InvalidInputError("study " + plan.name + ": the reference of " + run.scenario + " (" + run.label +
                              ") crashed: " + s.warnings.front() + "; nothing can be measured against it");
    }
    references.emplace(run.scenario, readRun(dir));
  }
  std::vector<RunResult> results;
  for (const PlannedRun& run : plan.runs) {
    RunResult r;
    r.run = &run;
    const fs::path dir = runDirectory(out, run);
    r.summary = sim::readRunSummary(dir / "summary.json");
    if (r.summary.crashed) {
      // Nothing it recorded can be trusted to its end: no figures.
      const double nan = std::numeric_limits<double>::quiet_NaN();
      r.rms_position_error = r.final_position_error = r.peak_pitch_deg = r.peak_pitch_error_deg = nan;
      r.peak_wheel_force = r.rms_wheel_force_error = nan;
    } else if (run.reference) {
      measure(r, references.at(run.scenario), references.at(run.scenario));  // read once, above
    } else {
      measure(r, readRun(dir), references.at(run.scenario));
    }
    if (const auto it = r.summary.fields.find("rms_tracking_error_m"); it != r.summary.fields.end()) {
      r.path_error = it->second;
    }
    results.push_back(std::move(r));
  }
  markFront(results);
  return results;
}

std::map<std::string, int> programsOf(const std::vector<RunResult>& results) {
  std::map<std::string, int> programs;
  for (const RunResult& r : results) {
    if (!r.summary.program.empty()) ++programs[r.summary.program];
  }
  return programs;
}

void writeResultsCsv(const fs::path& file, const std::vector<RunResult>& results) {
  std::string text =
      "scenario,key,sweep,label,engine,mode,dt_s,reference,success,crashed,nan,diverged,wall_time_s,real_time_factor,"
      "steps,"
      "rms_position_error_m,final_position_error_m,peak_pitch_deg,peak_pitch_error_deg,peak_wheel_force_N,"
      "rms_wheel_force_error_N,contact_breaks_per_s,path_error_m,warnings,on_front,failed_criteria\n";
  for (const RunResult& r : results) {
    const sim::RunSummary& s = r.summary;
    text += join({csvText(r.run->scenario),
                  r.run->key,
                  csvText(r.run->sweep),
                  csvText(r.run->label),
                  s.engine,
                  s.mode,
                  number(s.dt),
                  r.run->reference ? "1" : "0",
                  s.success ? "1" : "0",
                  s.crashed ? "1" : "0",
                  s.nan ? "1" : "0",
                  s.diverged ? "1" : "0",
                  number(s.wall_time),
                  number(s.real_time_factor),
                  std::to_string(s.steps),
                  number(r.rms_position_error),
                  number(r.final_position_error),
                  number(r.peak_pitch_deg),
                  number(r.peak_pitch_error_deg),
                  number(r.peak_wheel_force),
                  number(r.rms_wheel_force_error),
                  number(contactBreaksPerSecond(s)),
                  r.path_error ? number(*r.path_error) : std::string(),
                  std::to_string(s.warnings.size()),
                  r.on_front ? "1" : "0",
                  csvText(failedText(s))},
                 ",");
    text += "\n";
  }
  io::writeFileAtomically(file, text);
}

void writeResultsMarkdown(const fs::path& file, const StudyPlan& plan, const std::vector<RunResult>& results) {
  std::string text = "<!-- written by wtc-study from " + plan.source.filename().string() + "; do not edit -->\n";
  if (const auto programs = programsOf(results); programs.size() > 1) {
    // Built with append: GCC 12 warns falsely (-Wrestrict) on chains of std::string +.
    text.append("\n**These runs were made by ").append(std::to_string(programs.size()));
    text.append(" different builds of wtc-sim (");
    for (const auto& [program, runs] : programs) {
      text.append(program).append(": ").append(std::to_string(runs)).append(" runs; ");
    }
    text.resize(text.size() - 2);
    text.append(").** A run's key covers its settings, not the program: delete `runs/` and make them again with ");
    text.append("one build.\n");
  }
  for (const std::string& scenario : plan.scenarios) {
    std::vector<const RunResult*> rows;
    const RunResult* reference = nullptr;
    for (const RunResult& r : results) {
      if (r.run->scenario != scenario) continue;
      rows.push_back(&r);
      if (r.run->reference) reference = &r;
    }
    std::sort(rows.begin(), rows.end(),
              [](const RunResult* a, const RunResult* b) { return a->summary.wall_time < b->summary.wall_time; });
    const bool paths = std::any_of(rows.begin(), rows.end(), [](const RunResult* r) { return r->path_error; });
    std::vector<std::string> header = {"setting",
                                       "success",
                                       "wall (s)",
                                       "× real time",
                                       "RMS position error (mm)",
                                       "final error (mm)",
                                       "peak pitch (°)",
                                       "its error (°)",
                                       "peak wheel force (N)",
                                       "RMS force error (N)",
                                       "contact breaks (1/s)"};
    if (paths) header.push_back("path error RMS (mm)");
    header.insert(header.end(), {"warnings", "front"});
    // Why a run failed, where one did (the criteria its summary names).
    const bool failures =
        std::any_of(rows.begin(), rows.end(), [](const RunResult* r) { return !r->summary.failed_criteria.empty(); });
    if (failures) header.push_back("failed criteria");
    text.append("\n### ").append(scenario).append(" (reference: ");
    text.append(reference ? reference->run->label : std::string("?")).append(")\n\n");
    text.append("| ").append(join(header, " | ")).append(" |\n|");
    for (std::size_t i = 0; i < header.size(); ++i) text += "---|";
    text += "\n";
    for (const RunResult* r : rows) {
      const sim::RunSummary& s = r->summary;
      std::vector<std::string> cells = {r->run->label + (r->run->reference ? " (reference)" : ""),
                                        s.crashed    ? "crashed"
                                        : s.nan      ? "non-finite"
                                        : s.diverged ? "diverged"
                                        : s.success  ? "yes"
                                                     : "no",
                                        number(s.wall_time, "%.2f"),
                                        number(s.real_time_factor, "%.1f"),
                                        number(r->rms_position_error * 1e3, "%.2f"),
                                        number(r->final_position_error * 1e3, "%.2f"),
                                        number(r->peak_pitch_deg, "%.1f"),
                                        number(r->peak_pitch_error_deg, "%.1f"),
                                        number(r->peak_wheel_force, "%.0f"),
                                        number(r->rms_wheel_force_error, "%.1f"),
                                        number(contactBreaksPerSecond(s), "%.0f")};
      if (paths) cells.push_back(r->path_error ? number(*r->path_error * 1e3, "%.2f") : std::string("–"));
      cells.push_back(std::to_string(s.warnings.size()));
      cells.push_back(r->on_front ? "●" : "");
      if (failures) cells.push_back(cellText(failedText(s)));
      text.append("| ").append(join(cells, " | ")).append(" |\n");
    }
  }
  io::writeFileAtomically(file, text);
}

}  // namespace wtc::study
