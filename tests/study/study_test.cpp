// wtc::study: the plan a study file expands to, runs on one and on two
// workers (the same results), the job list through GNU parallel (the same
// table as in process), resuming after an interruption, and bad files.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>

#include "scratch_path.hpp"
#include "wtc/base/error.hpp"
#include "wtc/sim/run_summary_file.hpp"
#include "wtc/study/study_file.hpp"
#include "wtc/study/study_results.hpp"
#include "wtc/study/study_runner.hpp"

namespace {

namespace fs = std::filesystem;
using testing::HasSubstr;
using wtc::study::PlannedRun;
using wtc::study::RunResult;
using wtc::study::StudyPlan;

const fs::path kTinyStudy = fs::path(WTC_SOURCE_DIR) / "tests/study/tiny_study.yaml";

fs::path freshDirectory(const std::string& name) {
  const fs::path dir = wtc::test::scratchPath("wtc_study_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

fs::path writeFile(const fs::path& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name) << text;
  return dir / name;
}

// A study of the towed incline alone, with its reference and sweeps (YAML flow maps).
std::string towedStudy(const std::string& name, const std::string& reference, const std::string& sweeps) {
  return "name: " + name + "\nbase: {engine: bullet, mode: force, dt: 0.0004}\n" +
         "scenarios: {towed: {scene: " WTC_SOURCE_DIR "/scenes/towed_incline.yaml}}\n" + "reference: " + reference +
         "\nsweeps: " + sweeps + "\n";
}

// Every figure of a result that is a function of the run's settings (not
// the wall time, the real-time factor, nor the front, which depends on them).
void expectSameResults(const std::vector<RunResult>& a, const std::vector<RunResult>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    SCOPED_TRACE(a[i].run->key + " " + a[i].run->label);
    EXPECT_EQ(a[i].run->key, b[i].run->key);
    EXPECT_EQ(a[i].summary.steps, b[i].summary.steps);
    EXPECT_EQ(a[i].summary.success, b[i].summary.success);
    EXPECT_EQ(a[i].summary.fields, b[i].summary.fields);
    EXPECT_EQ(a[i].rms_position_error, b[i].rms_position_error);
    EXPECT_EQ(a[i].final_position_error, b[i].final_position_error);
    EXPECT_EQ(a[i].peak_pitch_deg, b[i].peak_pitch_deg);
    EXPECT_EQ(a[i].peak_wheel_force, b[i].peak_wheel_force);
    EXPECT_EQ(a[i].rms_wheel_force_error, b[i].rms_wheel_force_error);
    EXPECT_EQ(a[i].path_error, b[i].path_error);
  }
}

TEST(StudyPlanTest, ExpandsSweepsIntoDistinctRunsWithTheReferenceFirst) {
  const StudyPlan plan = wtc::study::loadStudyPlan(kTinyStudy);
  EXPECT_EQ(plan.name, "tiny");
  EXPECT_EQ(plan.scenarios, (std::vector<std::string>{"towed", "robot"}));
  // Per scenario: the reference, 2 engines x 2 steps, and one effect set.
  ASSERT_EQ(plan.runs.size(), 12u);
  std::set<std::string> keys;
  for (const PlannedRun& r : plan.runs) keys.insert(r.key);
  EXPECT_EQ(keys.size(), plan.runs.size());
  EXPECT_TRUE(plan.runs[0].reference);
  EXPECT_EQ(plan.runs[0].label, "ode force 0.2 ms");
  EXPECT_EQ(plan.runs[1].label, "bullet force 0.4 ms");
  EXPECT_EQ(plan.runs[5].label, "bullet force 0.4 ms effects=coulomb");
  EXPECT_THAT(plan.runs[0].key, testing::StartsWith("towed-"));
  // The key is the settings', not the file order's nor the load's.
  EXPECT_EQ(wtc::study::loadStudyPlan(kTinyStudy).runs[3].key, plan.runs[3].key);
}

TEST(StudyPlanTest, ASweptSettingEqualToTheReferenceIsTheReferenceRunOnce) {
  const fs::path dir = freshDirectory("dedupe");
  const fs::path file = writeFile(
      dir, "s.yaml", towedStudy("d", "{engine: ode, dt: 0.0002}", "{step: {engine: [ode, bullet], dt: [0.0002]}}"));
  const StudyPlan plan = wtc::study::loadStudyPlan(file);
  ASSERT_EQ(plan.runs.size(), 2u);
  EXPECT_TRUE(plan.runs[0].reference);
  EXPECT_EQ(plan.runs[0].label, "ode force 0.2 ms");
  EXPECT_FALSE(plan.runs[1].reference);
  fs::remove_all(dir);
}

TEST(StudyPlanTest, OnlyLimitsASweepToTheScenariosItNames) {
  const fs::path dir = freshDirectory("only");
  const std::string head =
      "name: o\nbase: {engine: bullet, mode: force, dt: 0.0004}\nreference: {dt: 0.0002}\n"
      "scenarios: {towed: {scene: " WTC_SOURCE_DIR "/scenes/towed_incline.yaml}, robot: {scene: " WTC_SOURCE_DIR
      "/scenes/robot_straight.yaml}}\n";
  const StudyPlan plan = wtc::study::loadStudyPlan(writeFile(
      dir, "s.yaml", head + "sweeps: {step: {dt: [0.001]}, solver: {only: [robot], solver_iterations: [5]}}\n"));
  std::vector<std::string> labels;
  for (const PlannedRun& r : plan.runs) labels.push_back(r.scenario + ": " + r.label);
  EXPECT_EQ(labels, (std::vector<std::string>{"towed: bullet force 0.2 ms", "towed: bullet force 1 ms",
                                              "robot: bullet force 0.2 ms", "robot: bullet force 1 ms",
                                              "robot: bullet force 0.4 ms solver_iterations=5"}));
  EXPECT_THAT(
      [&] { wtc::study::loadStudyPlan(writeFile(dir, "t.yaml", head + "sweeps: {s: {only: [robt], dt: [1]}}\n")); },
      testing::ThrowsMessage<wtc::InvalidInputError>(
          testing::AllOf(HasSubstr("t.yaml:5:"), HasSubstr("only: no scenario 'robt'"))));
  fs::remove_all(dir);
}

TEST(StudyPlanTest, BadStudyFilesAreNamedWithTheirPlace) {
  const fs::path dir = freshDirectory("bad");
  const std::string head = "name: b\nbase: {engine: bullet, mode: force, dt: 0.0004}\nreference: {dt: 0.0002}\n";
  const std::string scene = "scenarios: {t: {scene: " WTC_SOURCE_DIR "/scenes/towed_incline.yaml}}\n";
  const auto error = [&](const std::string& text) {
    try {
      wtc::study::loadStudyPlan(writeFile(dir, "bad.yaml", text));
    } catch (const wtc::InvalidInputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // Case: a missing scene, named once at its place (its context was once
  // joined twice: "scenarios.tscenarios.t.scene").
  EXPECT_THAT(error(head + "scenarios: {t: {scene: nowhere.yaml}}\nsweeps: {}\n"),
              HasSubstr("bad.yaml:4:24: scenarios.t: scene: " + (dir / "nowhere.yaml").string() + ": file not found"));
  EXPECT_THAT(error(head + scene + "sweeps: {step: {dt: []}}\n"),
              testing::AllOf(HasSubstr("bad.yaml:5:"), HasSubstr("sweeps.step.dt: no values")));
  EXPECT_THAT(error(head + scene + "sweeps: {step: {dt: 0.001}}\n"), HasSubstr("expected a list of values"));
  EXPECT_THAT(error(head + scene + "sweeps: {}\nsweep: {}\n"), HasSubstr("sweep"));
  EXPECT_THAT(error("name: b\nbase: {engine: bullet}\nreference: {}\n" + scene + "sweeps: {}\n"),
              HasSubstr("base: must give mode"));
  EXPECT_THAT(error(head + scene + "sweeps: {s: {dt: [0.0004"), HasSubstr("bad.yaml:"));
  // Case: no scenario, no run (issue 35: it ran "0 runs" and exited 0).
  EXPECT_THAT(error(head + "scenarios: {}\nsweeps: {}\n"),
              testing::AllOf(HasSubstr("bad.yaml:4:12:"), HasSubstr("scenarios: none")));
  fs::remove_all(dir);
}

// Issue 35: a sweep's value is checked with every run before any starts,
// named by its place in the study file, not by the scene's.
TEST(StudyPlanTest, ABadSweepValueIsRefusedBeforeAnyRunNamingItsPlace) {
  const fs::path dir = freshDirectory("badsweep");
  const fs::path file =
      writeFile(dir, "s.yaml", towedStudy("b", "{dt: 0.0002}", "{step: {engine: [bullet, ode], dt: [0.0004, -1]}}"));
  const StudyPlan plan = wtc::study::loadStudyPlan(file);
  const auto message = [&](const std::function<void()>& f) {
    try {
      f();
    } catch (const wtc::InvalidInputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string checked = message([&] { wtc::study::checkStudyRuns(plan); });
  EXPECT_THAT(checked, testing::AllOf(HasSubstr("2 of 5 runs would be refused"), HasSubstr("s.yaml:5:53:"),
                                      HasSubstr("sweeps.step.dt: value -1 is refused by scenario towed"),
                                      HasSubstr("dt: must be > 0 s")));
  EXPECT_THAT(checked, testing::Not(HasSubstr("towed_incline.yaml:1:1")));
  // runPlan checks first: nothing is started, no run's directory made.
  EXPECT_EQ(message([&] { wtc::study::runPlan(plan, dir / "out", 2, WTC_SIM_EXE); }), checked);
  EXPECT_FALSE(fs::exists(dir / "out" / "runs"));
  fs::remove_all(dir);
}

TEST(StudyRunTest, ResultsDoNotDependOnTheNumberOfWorkers) {
  const StudyPlan plan = wtc::study::loadStudyPlan(kTinyStudy);
  const fs::path one = freshDirectory("one"), two = freshDirectory("two");
  std::size_t made = 0;
  wtc::study::runPlan(plan, one, 1, WTC_SIM_EXE, [&](const wtc::study::RunDone& d) { made += d.summary != nullptr; });
  EXPECT_EQ(made, plan.runs.size());
  wtc::study::runPlan(plan, two, 2, WTC_SIM_EXE);
  const std::vector<RunResult> a = wtc::study::gatherResults(plan, one);
  expectSameResults(a, wtc::study::gatherResults(plan, two));
  // Against the reference: zero for itself, not for a coarser step.
  EXPECT_EQ(a[0].rms_position_error, 0.0);
  EXPECT_TRUE(a[0].on_front);
  EXPECT_GT(a[2].rms_position_error, 0.0);  // bullet at 1 ms
  EXPECT_TRUE(a[0].path_error.has_value());
  // The robot runs are 0.4 s long, short of their scene's distance: failed, so never on the front, and
  // the tables say why (issue 35).
  for (const RunResult& r : a) {
    if (r.run->scenario == "robot") {
      EXPECT_FALSE(r.on_front) << r.run->label;
      ASSERT_EQ(r.summary.failed_criteria.size(), 1u) << r.run->label;
      EXPECT_EQ(r.summary.failed_criteria[0].criterion, "min_distance") << r.run->label;
    }
  }
  wtc::study::writeResultsMarkdown(one / "results.md", plan, a);
  wtc::study::writeResultsCsv(one / "results.csv", a);
  std::ifstream md(one / "results.md"), csv(one / "results.csv");
  const std::string tables((std::istreambuf_iterator<char>(md)), std::istreambuf_iterator<char>());
  const std::string rows((std::istreambuf_iterator<char>(csv)), std::istreambuf_iterator<char>());
  EXPECT_THAT(tables, testing::AllOf(HasSubstr("| failed criteria |"), HasSubstr("| min_distance: 0.")));
  EXPECT_THAT(rows, testing::AllOf(HasSubstr(",failed_criteria\n"), HasSubstr(",min_distance: 0.")));
  fs::remove_all(one);
  fs::remove_all(two);
}

TEST(StudyRunTest, AJobListThroughGnuParallelGathersToTheSameTable) {
  const StudyPlan plan = wtc::study::loadStudyPlan(kTinyStudy);
  const fs::path local = freshDirectory("local"), jobs = freshDirectory("jobs");
  wtc::study::runPlan(plan, local, 2, WTC_SIM_EXE);
  {
    std::ofstream list(jobs / "jobs.txt");
    for (const std::string& line : wtc::study::jobLines(plan, jobs, WTC_SIM_EXE)) list << line << '\n';
  }
  // Exit 1 of a line is a run whose scene failed (the short robot runs), not an error: parallel counts them.
  const std::string command = std::string(WTC_GNU_PARALLEL) + " -j 2 < '" + (jobs / "jobs.txt").string() + "'";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 6) << "the 6 robot runs fail their scene, nothing else";
  expectSameResults(wtc::study::gatherResults(plan, local), wtc::study::gatherResults(plan, jobs));
  // Every line is idempotent: run again, nothing is made and the results stay.
  const auto before = fs::last_write_time(jobs / "runs" / plan.runs[1].key / "summary.json");
  ASSERT_EQ(std::system((command + " > /dev/null").c_str()) >> 8, 0);
  EXPECT_EQ(fs::last_write_time(jobs / "runs" / plan.runs[1].key / "summary.json"), before);
  fs::remove_all(local);
  fs::remove_all(jobs);
}

TEST(StudyRunTest, RunsOfDifferentBuildsAreSaidToBeMixed) {
  const StudyPlan plan = wtc::study::loadStudyPlan(kTinyStudy);
  const fs::path out = freshDirectory("builds");
  wtc::study::runPlan(plan, out, 2, WTC_SIM_EXE);
  std::vector<RunResult> results = wtc::study::gatherResults(plan, out);
  // Every run names the build that made it, and here it is one build.
  const auto one = wtc::study::programsOf(results);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one.begin()->first.size(), 16u);
  EXPECT_EQ(one.begin()->second, static_cast<int>(plan.runs.size()));
  // As if run 3 had been made by another build (and read back from its file).
  const fs::path file = wtc::study::runDirectory(out, plan.runs[3]) / "summary.json";
  wtc::sim::RunSummary other = wtc::sim::readRunSummary(file);
  EXPECT_EQ(other.program, one.begin()->first);
  other.program = "0123456789abcdef";
  wtc::sim::writeRunSummary(file, other);
  results = wtc::study::gatherResults(plan, out);
  EXPECT_EQ(wtc::study::programsOf(results).size(), 2u);
  wtc::study::writeResultsMarkdown(out / "results.md", plan, results);
  std::ifstream in(out / "results.md");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_THAT(
      text, testing::AllOf(HasSubstr("made by 2 different builds of wtc-sim"), HasSubstr("0123456789abcdef: 1 runs")));
  fs::remove_all(out);
}

TEST(StudyRunTest, AnInterruptedRunIsMadeAgainAndOnlyIt) {
  const StudyPlan plan = wtc::study::loadStudyPlan(kTinyStudy);
  const fs::path out = freshDirectory("resume");
  wtc::study::runPlan(plan, out, 2, WTC_SIM_EXE);
  const std::vector<RunResult> first = wtc::study::gatherResults(plan, out);
  // A run killed mid-way leaves its "running" summary and partial series.
  const fs::path killed = wtc::study::runDirectory(out, plan.runs[4]);
  const wtc::sim::Scene scene = wtc::sim::loadScene(plan.runs[4].scene_file, plan.runs[4].overrides);
  wtc::sim::writeRunStarted(killed / "summary.json", scene);
  fs::resize_file(killed / "bodies.csv", fs::file_size(killed / "bodies.csv") / 2);
  EXPECT_THAT([&] { wtc::study::gatherResults(plan, out); },
              testing::ThrowsMessage<wtc::InvalidInputError>(HasSubstr(plan.runs[4].key)));
  std::vector<std::string> made;
  wtc::study::runPlan(plan, out, 2, WTC_SIM_EXE, [&](const wtc::study::RunDone& d) {
    if (d.summary != nullptr) made.push_back(d.run.key);
  });
  EXPECT_EQ(made, std::vector<std::string>{plan.runs[4].key});
  expectSameResults(first, wtc::study::gatherResults(plan, out));
  fs::remove_all(out);
}

// ODE's "LCP internal error, s <= 0", which went only to stderr, is a
// warning of the run in the study's tables (issue 35, row 11): the robot
// spinning its wheels at their top speed on ODE's own cylinder wheels on a
// slab given twice, where ODE still gives up in one step
// (tests/sim/solver_messages_test.cpp), ODE's only warning there beside
// the six drives held at their top speed.
TEST(StudyRunTest, OdesLcpGivingUpIsAWarningInTheTables) {
  const fs::path dir = freshDirectory("lcp");
  const fs::path file = writeFile(
      dir, "s.yaml",
      "name: lcp\nbase: {engine: ode, mode: engine_cylinder, dt: 0.0004}\nreference: {dt: 0.0004}\nsweeps: {}\n"
      "scenarios: {standing: {scene: " WTC_SOURCE_DIR
      "/scenes/robot_standing.yaml, set: {duration: 0.2, controller.schedules.0.points: [[0, 10]], "
      "terrain: {materials: {asphalt: {mu_max: 0.8, s1: 0.1, "
      "s2: 0.0, rolling_resistance: 0.018}}, pieces: [{type: slab, material: asphalt, size: [4, 4], thickness: 0.5}, "
      "{type: slab, material: asphalt, size: [4, 4], thickness: 0.5}]}}}}\n");
  const StudyPlan plan = wtc::study::loadStudyPlan(file);
  ASSERT_EQ(plan.runs.size(), 1u);
  wtc::study::runPlan(plan, dir / "out", 1, WTC_SIM_EXE);
  const std::vector<RunResult> results = wtc::study::gatherResults(plan, dir / "out");
  ASSERT_EQ(results[0].summary.warnings.size(), 7u);
  EXPECT_EQ(results[0].summary.warnings.back(), "ODE: 'LCP internal error, s <= 0' in 1 step (first at t = 0.0108 s)");
  wtc::study::writeResultsCsv(dir / "results.csv", results);
  std::ifstream csv(dir / "results.csv");
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  const auto cells = [](const std::string& line) {
    std::vector<std::string> out(1);
    for (const char c : line) {
      if (c == ',') {
        out.emplace_back();
      } else {
        out.back().push_back(c);
      }
    }
    return out;
  };
  const std::vector<std::string> names = cells(header), values = cells(row);
  const auto warnings = std::find(names.begin(), names.end(), "warnings");
  ASSERT_NE(warnings, names.end());
  ASSERT_EQ(values.size(), names.size());
  EXPECT_EQ(values[warnings - names.begin()], "7");
  fs::remove_all(dir);
}

TEST(StudyRunTest, ARunThatCannotLoadIsNamed) {
  const fs::path dir = freshDirectory("badrun");
  const fs::path file = writeFile(dir, "s.yaml", towedStudy("e", "{dt: 0.0002}", "{bad: {engine: [bulet]}}"));
  const StudyPlan plan = wtc::study::loadStudyPlan(file);
  EXPECT_THAT([&] { wtc::study::runPlan(plan, dir / "out", 2, WTC_SIM_EXE); },
              testing::ThrowsMessage<wtc::InvalidInputError>(
                  testing::AllOf(HasSubstr("bulet force 0.4 ms"), HasSubstr("engine"))));
  fs::remove_all(dir);
}

TEST(StudyRunTest, ARunWhoseProcessDiesIsRecordedAsCrashedAndTheStudyGoesOn) {
  const StudyPlan plan = wtc::study::loadStudyPlan(kTinyStudy);
  const fs::path dir = freshDirectory("crash");
  // A wtc-sim that dies as an engine's failed assertion does.
  const fs::path fake =
      writeFile(dir, "dying-wtc-sim", "#!/bin/sh\necho 'ODE INTERNAL ERROR 1: assertion failed' >&2\nkill -ABRT $$\n");
  fs::permissions(fake, fs::perms::owner_all);
  std::size_t crashed = 0;
  wtc::study::runPlan(plan, dir / "out", 2, fake, [&](const wtc::study::RunDone& d) {
    ASSERT_NE(d.summary, nullptr);
    crashed += d.summary->crashed && !d.summary->success;
    EXPECT_THAT(d.summary->warnings.at(0), testing::AllOf(HasSubstr("signal 6"), HasSubstr("ODE INTERNAL ERROR")));
  });
  EXPECT_EQ(crashed, plan.runs.size());
  EXPECT_TRUE(wtc::sim::runEnded(wtc::study::runDirectory(dir / "out", plan.runs[3])));
  EXPECT_THAT([&] { wtc::study::gatherResults(plan, dir / "out"); },
              testing::ThrowsMessage<wtc::InvalidInputError>(HasSubstr("the reference of towed")));
  fs::remove_all(dir);
}

}  // namespace
