#include "wtc/study/study_file.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <map>
#include <optional>
#include <utility>

#include "io/file_support.hpp"
#include "wtc/base/error.hpp"
#include "io/content_hash.hpp"
#include "io/yaml_reader.hpp"

namespace wtc::study {
namespace {

using io::detail::YamlReader;

// The settings every run names explicitly, so a label always says them.
constexpr const char* kBaseKeys[] = {"engine", "mode", "dt"};

// A sweep's key that is not a setting: the scenarios it applies to (all if absent).
constexpr const char* kOnlyKey = "only";

// One value a sweep tries: the override's YAML text, its label and where
// the study file set it ("<file>:<line>:<col>: <key>").
struct Choice {
  std::string value, label, where;
};

std::string origin(const YamlReader& in, const YAML::Node& node, const std::string& key) {
  const YAML::Mark mark = node.Mark();
  return in.path().string() + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1) + ": " + key;
}
using Setting = std::map<std::string, Choice>;  // override path -> choice

std::string flowYaml(const YAML::Node& node) {
  YAML::Emitter out;
  out.SetMapFormat(YAML::Flow);
  out.SetSeqFormat(YAML::Flow);
  out << node;
  return out.c_str();
}

// A setting read from a map of path -> one value (base, reference, a scenario's `set`).
Setting readFixed(const YamlReader& in, const YAML::Node& node, const char* what) {
  in.requireMap(node, what);
  Setting s;
  for (const auto& entry : node) {
    const std::string path = entry.first.Scalar();
    s[path] = {flowYaml(entry.second), flowYaml(entry.second),
               origin(in, entry.second, std::string(what) + "." + path)};
  }
  return s;
}

// A sweep: path -> a list of values (labelled by their text) or a map of
// label -> value; expanded into the product of all its paths.
std::vector<Setting> expandSweep(const YamlReader& in, const YAML::Node& node, const std::string& name) {
  in.requireMap(node, ("sweeps." + name).c_str());
  std::vector<Setting> product{Setting{}};
  for (const auto& entry : node) {
    const std::string path = entry.first.Scalar();
    if (path == kOnlyKey) continue;
    std::vector<Choice> choices;
    if (entry.second.IsSequence()) {
      for (const auto& v : entry.second) {
        choices.push_back({flowYaml(v), flowYaml(v), origin(in, v, "sweeps." + name + "." + path)});
      }
    } else if (entry.second.IsMap()) {
      for (const auto& v : entry.second) {
        choices.push_back({flowYaml(v.second), v.first.Scalar(),
                           origin(in, v.second, "sweeps." + name + "." + path + "." + v.first.Scalar())});
      }
    } else {
      in.fail(entry.second, "sweeps." + name + "." + path + ": expected a list of values or a map of label: value");
    }
    if (choices.empty()) in.fail(entry.second, "sweeps." + name + "." + path + ": no values");
    std::vector<Setting> next;
    for (const Setting& s : product) {
      for (const Choice& c : choices) {
        Setting t = s;
        t[path] = c;
        next.push_back(std::move(t));
      }
    }
    product = std::move(next);
  }
  return product;
}

std::string stepLabel(const std::string& dt_text) {
  char text[32];
  std::snprintf(text, sizeof text, "%g ms", std::stod(dt_text) * 1e3);
  return text;
}

PlannedRun plannedRun(const std::string& scenario, const std::filesystem::path& scene, const std::string& scene_bytes,
                      const Setting& scenario_set, const Setting& setting, const std::string& sweep) {
  PlannedRun run;
  run.scenario = scenario;
  run.scene_file = scene;
  run.sweep = sweep;
  Setting all = scenario_set;
  for (const auto& [path, choice] : setting) all[path] = choice;
  run.label = all.at("engine").label + " " + all.at("mode").label + " " + stepLabel(all.at("dt").value);
  std::uint64_t h = io::fnv1a(scene_bytes);
  for (const auto& [path, choice] : all) {  // std::map: sorted, so the key ignores the file's order
    run.overrides.push_back({.path = path, .value = choice.value});
    run.origins.push_back(choice.where);
    h = io::fnv1a(path + "=" + choice.value + "\n", h);
    const bool base = path == kBaseKeys[0] || path == kBaseKeys[1] || path == kBaseKeys[2];
    if (!base && !scenario_set.contains(path)) run.label += " " + path + "=" + choice.label;
  }
  run.key = scenario + "-" + io::hexDigits(h);
  return run;
}

StudyPlan readStudy(const std::filesystem::path& file) {
  const YAML::Node root = io::detail::loadYamlFile(file);
  const YamlReader in(file);
  in.requireMap(root, "study file");
  in.checkKeys(root, {"name", "base", "scenarios", "reference", "sweeps"});
  StudyPlan plan;
  plan.source = file;
  plan.name = in.string(in.require(root, "name"), "name");
  const Setting base = readFixed(in, in.require(root, "base"), "base");
  for (const char* key : kBaseKeys) {
    if (!base.contains(key)) in.fail(root["base"], std::string("base: must give ") + key);
  }
  Setting reference = base;
  for (const auto& [path, c] : readFixed(in, in.require(root, "reference"), "reference")) reference[path] = c;

  struct Sweep {
    std::string name;
    std::vector<Setting> settings;
    std::optional<std::vector<std::string>> only;
    YAML::Node node;
  };
  std::vector<Sweep> sweeps;
  const YAML::Node sweep_node = in.require(root, "sweeps");
  in.requireMap(sweep_node, "sweeps");
  for (const auto& entry : sweep_node) {
    std::vector<Setting> settings;
    for (Setting s : expandSweep(in, entry.second, entry.first.Scalar())) {
      for (const auto& [path, c] : base) s.try_emplace(path, c);
      settings.push_back(std::move(s));
    }
    Sweep sweep{entry.first.Scalar(), std::move(settings), std::nullopt, entry.second};
    if (entry.second.IsMap() && entry.second[kOnlyKey]) {
      const YAML::Node only = entry.second[kOnlyKey];
      if (!only.IsSequence()) in.fail(only, "sweeps." + sweep.name + ".only: expected a list of scenario names");
      sweep.only.emplace();
      for (const auto& n : only) sweep.only->push_back(in.string(n, "sweeps." + sweep.name + ".only"));
    }
    sweeps.push_back(std::move(sweep));
  }

  const YAML::Node scenarios = in.require(root, "scenarios");
  in.requireMap(scenarios, "scenarios");
  if (scenarios.size() == 0) in.fail(scenarios, "scenarios: none (a study needs at least one: name: {scene: file})");
  std::map<std::string, std::size_t> seen;
  for (const auto& entry : scenarios) {
    const std::string name = entry.first.Scalar();
    const YamlReader at = in.with("scenarios." + name + ": ");
    at.requireMap(entry.second, "scenario");
    at.checkKeys(entry.second, {"scene", "set"});
    const std::filesystem::path scene = std::filesystem::weakly_canonical(
        std::filesystem::absolute(file).parent_path() / at.string(at.require(entry.second, "scene"), "scene"));
    std::string bytes;  // the scene's, for the runs' keys
    try {
      bytes = io::detail::readDescriptionFile(scene);
    } catch (const InvalidInputError& e) {
      at.fail(entry.second["scene"], std::string("scene: ") + e.what());
    }
    const Setting set = entry.second["set"] ? readFixed(at, entry.second["set"], "set") : Setting{};
    plan.scenarios.push_back(name);
    auto add = [&](const Setting& s, const std::string& sweep, bool is_reference) {
      PlannedRun run = plannedRun(name, scene, bytes, set, s, sweep);
      run.reference = is_reference;
      if (seen.try_emplace(run.key, plan.runs.size()).second) {
        plan.runs.push_back(std::move(run));
      } else if (is_reference) {
        plan.runs[seen[run.key]].reference = true;
      }
    };
    add(reference, "reference", true);
    for (const Sweep& sweep : sweeps) {
      if (sweep.only && std::find(sweep.only->begin(), sweep.only->end(), name) == sweep.only->end()) continue;
      for (const Setting& s : sweep.settings) add(s, sweep.name, false);
    }
  }
  for (const Sweep& sweep : sweeps) {
    for (const std::string& name : sweep.only.value_or(std::vector<std::string>{})) {
      if (std::find(plan.scenarios.begin(), plan.scenarios.end(), name) == plan.scenarios.end()) {
        in.fail(sweep.node[kOnlyKey], "sweeps." + sweep.name + ".only: no scenario '" + name + "'");
      }
    }
  }
  return plan;
}

}  // namespace

study::StudyPlan loadStudyPlan(const std::filesystem::path& file) {
  return io::detail::withYamlErrors(file, [&] { return readStudy(file); });
}

}  // namespace wtc::study
