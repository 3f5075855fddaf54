// A study's runs loaded before any is made (study::checkStudyRuns).
#include <set>
#include <string>
#include <vector>

#include "wtc/base/error.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/scene_file.hpp"
#include "wtc/study/study_file.hpp"

namespace wtc::study {
namespace {

// The scene's message for `run` with `overrides`, or "" if it loads.
std::string loadProblem(const PlannedRun& run, const std::vector<sim::Override>& overrides) {
  try {
    // The scene reader keeps the engine's name; the engine table judges it.
    (void)sim::loadScene(run.scene_file, overrides, sim::requireEngine);
    return {};
  } catch (const std::exception& e) {
    return e.what();
  }
}

// `message` without a leading "<scene file>:<line>:<col>: ": a place in
// the scene file says nothing when an override put the value there.
std::string withoutScenePlace(const std::string& message, const std::string& scene_file) {
  if (message.rfind(scene_file + ":", 0) != 0) return message;
  std::size_t i = scene_file.size() + 1;
  for (int field = 0; field < 2; ++field) {
    const std::size_t start = i;
    while (i < message.size() && message[i] >= '0' && message[i] <= '9') ++i;
    if (i == start || i >= message.size() || message[i] != ':') return message;
    ++i;
  }
  return message.substr(message[i] == ' ' ? i + 1 : i);
}

// What is wrong with `run`, blaming the one override without which it
// loads, if there is one.
std::string blame(const PlannedRun& run, const std::string& problem) {
  for (std::size_t i = 0; i < run.overrides.size(); ++i) {
    std::vector<sim::Override> without = run.overrides;
    without.erase(without.begin() + static_cast<std::ptrdiff_t>(i));
    if (!loadProblem(run, without).empty()) continue;
    const std::string where = i < run.origins.size() ? run.origins[i] : run.overrides[i].path;
    return where + ": value " + run.overrides[i].value + " is refused by scenario " + run.scenario + ", run " +
           run.label + " (" + run.scene_file.filename().string() +
           "): " + withoutScenePlace(problem, run.scene_file.string());
  }
  std::string settings;
  for (const sim::Override& o : run.overrides) settings += (settings.empty() ? "" : ", ") + o.path + "=" + o.value;
  return "scenario " + run.scenario + ", run " + run.label + " (" + settings + "): " + problem;
}

}  // namespace

void checkStudyRuns(const StudyPlan& plan) {
  constexpr std::size_t kMostProblemsSaid = 10;
  std::vector<std::string> problems;  // each said once, in the plan's order
  std::set<std::string> said;
  std::size_t refused = 0;
  for (const PlannedRun& run : plan.runs) {
    const std::string problem = loadProblem(run, run.overrides);
    if (problem.empty()) continue;
    ++refused;
    const std::string text = blame(run, problem);
    if (said.insert(text).second) problems.push_back(text);
  }
  if (problems.empty()) return;
  std::string message = "study " + plan.name + ": " + std::to_string(refused) + " of " +
                        std::to_string(plan.runs.size()) + " runs would be refused; nothing was run:";
  for (std::size_t i = 0; i < problems.size() && i < kMostProblemsSaid; ++i) message += "\n  " + problems[i];
  if (problems.size() > kMostProblemsSaid) {
    message += "\n  (and " + std::to_string(problems.size() - kMostProblemsSaid) + " more)";
  }
  throw InvalidInputError(message);
}

}  // namespace wtc::study
