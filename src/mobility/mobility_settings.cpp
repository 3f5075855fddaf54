// The mobility settings file (wtc/mobility/mobility_settings.hpp): one
// table of every numeric setting, read from the file and checked alike for
// settings made in code.
#include "wtc/mobility/mobility_settings.hpp"

#include <algorithm>
#include <cmath>

#include "io/material_node.hpp"
#include "io/yaml_reader.hpp"
#include "wtc/base/error.hpp"
#include "wtc/sim/engine.hpp"
#include "wtc/sim/engine_table.hpp"

namespace wtc::mobility {
namespace {

using io::detail::YamlReader;

// A number of the file: its key, where it goes, and the range it must be in.
struct NumberField {
  const char* key;
  double* value;
  double min;
  bool above;  // true: > min, false: >= min
};
struct SearchField {
  const char* key;
  Search* value;
};
struct Section {
  const char* name;
  std::vector<NumberField> numbers;
  std::vector<SearchField> searches;
  bool* flag = nullptr;  // the one boolean (step.vehicle_controller)
  const char* flag_key = nullptr;
};

std::vector<Section> sections(MobilitySettings& s) {
  return {
      {"step",
       {{"approach_speed", &s.step.approach_speed_mps, 0.0, true},
        {"approach", &s.step.approach_m, 0.0, true},
        {"top", &s.step.top_m, 0.0, true},
        {"duration", &s.step.duration_s, 0.0, true}},
       {{"height", &s.step.height_m}},
       &s.step.vehicle_controller,
       "vehicle_controller"},
      {"grade",
       {{"wheel_rate", &s.grade.wheel_rate_radps, 0.0, true},
        {"min_progress", &s.grade.min_progress_m, 0.0, true},
        {"duration", &s.grade.duration_s, 0.0, true}},
       {{"degrees", &s.grade.degrees}}},
      {"parked",
       {{"tilt_rate", &s.parked.tilt.rate_deg_s, 0.0, false},
        {"tilt_slide", &s.parked.tilt.slide_m, 0.0, true},
        {"max_final_speed", &s.parked.max_final_speed_mps, 0.0, true},
        {"max_slide", &s.parked.max_slide_m, 0.0, true},
        {"duration", &s.parked.duration_s, 0.0, true}},
       {{"degrees", &s.parked.degrees}}},
      {"side_slope",
       {{"tilt_rate", &s.side_slope.tilt.rate_deg_s, 0.0, false},
        {"tilt_slide", &s.side_slope.tilt.slide_m, 0.0, true},
        {"max_final_speed", &s.side_slope.max_final_speed_mps, 0.0, true},
        {"max_slide", &s.side_slope.max_slide_m, 0.0, true},
        {"max_tilt", &s.side_slope.max_tilt_deg, 0.0, true},
        {"duration", &s.side_slope.duration_s, 0.0, true}},
       {{"degrees", &s.side_slope.degrees}}},
      {"drawbar",
       {{"speed", &s.drawbar.speed_mps, 0.0, true},
        {"stiffness_per_weight", &s.drawbar.stiffness_per_weight, 0.0, true},
        {"damping_ratio", &s.drawbar.damping_ratio, 0.0, false},
        {"settle", &s.drawbar.settle_s, 0.0, false},
        {"mean", &s.drawbar.mean_s, 0.0, true}},
       {}},
      {"coast",
       {{"speed", &s.coast.speed_mps, 0.0, true},
        {"fit_from", &s.coast.fit_from_s, 0.0, false},
        {"duration", &s.coast.duration_s, 0.0, true}},
       {}},
      {"braking", {{"speed", &s.braking.speed_mps, 0.0, true}, {"duration", &s.braking.duration_s, 0.0, true}}, {}},
      {"gap",
       {{"approach_speed", &s.gap.approach_speed_mps, 0.0, true},
        {"approach", &s.gap.approach_m, 0.0, true},
        {"duration", &s.gap.duration_s, 0.0, true}},
       {{"width", &s.gap.width_m}}},
      {"turn", {{"wheel_rate", &s.turn.wheel_rate_radps, 0.0, true}, {"duration", &s.turn.duration_s, 0.0, true}}, {}},
  };
}

// Why `value` is out of its field's range, or "".
std::string numberProblem(const NumberField& f, double value) {
  if (!std::isfinite(value)) return "must be finite";
  if (f.above ? value > f.min : value >= f.min) return {};
  return formatNumber(value) + " must be " + (f.above ? "> " : ">= ") + formatNumber(f.min);
}

std::string searchProblem(const Search& s) {
  if (!std::isfinite(s.low) || !std::isfinite(s.high) || !std::isfinite(s.resolution)) return "must be finite";
  if (!(s.low >= 0.0)) return "low " + formatNumber(s.low) + " must be >= 0";
  if (!(s.high > s.low)) return "high " + formatNumber(s.high) + " must exceed low " + formatNumber(s.low);
  if (!(s.resolution > 0.0)) return "resolution " + formatNumber(s.resolution) + " must be > 0";
  return {};
}

std::string slipProblem(double i) {
  if (!(i >= 0.0 && i < 1.0)) return "slip " + formatNumber(i) + " must be in [0, 1) (the driving slip i)";
  return {};
}

std::string eventProblem(const std::string& name) {
  const auto& all = eventNames();
  if (std::find(all.begin(), all.end(), name) != all.end()) return {};
  std::string known;
  for (const std::string& e : all) known += (known.empty() ? "" : ", ") + e;
  return "'" + name + "' is not an event (known: " + known + ")";
}

// The engine table's and the scene's own refusals of a name, as a problem
// ("" for a known one): the settings file and the command line say the same.
std::string engineProblem(const std::string& name) {
  sim::EngineSettings settings;
  settings.engine = name;
  settings.engine_where = "engines";
  try {
    sim::requireEngine(settings);
  } catch (const InvalidInputError& error) {
    return error.what();
  }
  return {};
}

std::string modeProblem(const std::string& name) {
  sim::EngineSettings settings;
  try {
    sim::parseMode(name, settings, "modes");
  } catch (const InvalidInputError& error) {
    return error.what();
  }
  return {};
}

std::vector<std::string> readNames(const YamlReader& in, const YAML::Node& node, const std::string& key) {
  if (!node.IsSequence() || node.size() == 0) in.fail(node, key + ": expected a list of names");
  std::vector<std::string> names;
  for (const auto& n : node) names.push_back(in.string(n, key));
  return names;
}

void readGround(const YamlReader& in, const YAML::Node& node, Material& m) {
  m = io::detail::readMaterial(in.with("ground: "), node, "ground");
  try {
    validate(m, "ground");
  } catch (const InvalidInputError& e) {
    in.fail(node, e.what());
  }
}

MobilitySettings readSettings(const std::filesystem::path& path) {
  const YAML::Node root = io::detail::loadYamlFile(path);
  const YamlReader in(path);
  MobilitySettings s;
  if (root.IsNull()) return s;  // an empty file: the defaults
  in.requireMap(root, "mobility settings");
  std::vector<Section> all = sections(s);
  std::vector<const char*> keys{"ground", "engines", "modes", "dt", "events"};
  for (const Section& section : all) keys.push_back(section.name);
  for (const auto& entry : root) {
    const std::string key = entry.first.Scalar();
    if (std::none_of(keys.begin(), keys.end(), [&](const char* k) { return key == k; })) {
      std::string known;
      for (const char* k : keys) known += (known.empty() ? "" : ", ") + std::string(k);
      in.fail(entry.first, "unknown key '" + key + "' (known: " + known + ")");
    }
  }
  if (const auto g = YamlReader::get(root, "ground")) readGround(in, *g, s.ground);
  if (const auto e = YamlReader::get(root, "engines")) {
    s.engines = readNames(in, *e, "engines");
    for (std::size_t i = 0; i < s.engines.size(); ++i) {
      if (const std::string p = engineProblem(s.engines[i]); !p.empty()) in.fail((*e)[i], p);
    }
  }
  if (const auto m = YamlReader::get(root, "modes")) {
    s.modes = readNames(in, *m, "modes");
    for (std::size_t i = 0; i < s.modes.size(); ++i) {
      if (const std::string p = modeProblem(s.modes[i]); !p.empty()) in.fail((*m)[i], p);
    }
  }
  if (const auto d = YamlReader::get(root, "dt")) {
    s.dt_s = in.number(*d, "dt");
    if (!(s.dt_s > 0.0)) in.fail(*d, "dt: must be > 0 s");
  }
  if (const auto e = YamlReader::get(root, "events")) {
    s.events = readNames(in, *e, "events");
    for (std::size_t i = 0; i < s.events.size(); ++i) {
      if (const std::string p = eventProblem(s.events[i]); !p.empty()) in.fail((*e)[i], "events: " + p);
    }
  }
  for (const Section& section : all) {
    const auto node = YamlReader::get(root, section.name);
    if (!node) continue;
    const std::string name = section.name;
    in.requireMap(*node, section.name);
    for (const auto& entry : *node) {
      const std::string key = entry.first.Scalar();
      const std::string where = name + "." + key;
      const auto number = std::find_if(section.numbers.begin(), section.numbers.end(),
                                       [&](const NumberField& f) { return key == f.key; });
      const auto search = std::find_if(section.searches.begin(), section.searches.end(),
                                       [&](const SearchField& f) { return key == f.key; });
      if (number != section.numbers.end()) {
        *number->value = in.number(entry.second, where);
        if (const std::string p = numberProblem(*number, *number->value); !p.empty()) {
          in.fail(entry.second, where + ": " + p);
        }
      } else if (search != section.searches.end()) {
        const Eigen::Vector3d v = in.vector<3>(entry.second, where + " ([low, high, resolution])");
        *search->value = {v.x(), v.y(), v.z()};
        if (const std::string p = searchProblem(*search->value); !p.empty()) in.fail(entry.second, where + ": " + p);
      } else if (section.flag != nullptr && key == section.flag_key) {
        *section.flag = in.boolean(entry.second, where);
      } else if (name == "drawbar" && key == "slips") {
        if (!entry.second.IsSequence() || entry.second.size() == 0) in.fail(entry.second, where + ": expected a list");
        s.drawbar.slips.clear();
        for (const auto& n : entry.second) {
          s.drawbar.slips.push_back(in.number(n, where));
          if (const std::string p = slipProblem(s.drawbar.slips.back()); !p.empty()) in.fail(n, where + ": " + p);
        }
      } else {
        std::string known;
        for (const NumberField& f : section.numbers) known += (known.empty() ? "" : ", ") + std::string(f.key);
        for (const SearchField& f : section.searches) known += ", " + std::string(f.key);
        if (section.flag_key != nullptr) known += ", " + std::string(section.flag_key);
        if (name == "drawbar") known += ", slips";
        in.fail(entry.first, name + ": unknown key '" + key + "' (known: " + known + ")");
      }
    }
  }
  return s;
}

}  // namespace

const std::vector<std::string>& eventNames() {
  static const std::vector<std::string> names{"step",  "grade",   "parked", "side_slope", "drawbar",
                                              "coast", "braking", "gap",    "turn"};
  return names;
}

MobilitySettings loadMobilitySettings(const std::filesystem::path& path) {
  return io::detail::withYamlErrors(path, [&] { return readSettings(path); });
}

void validate(const MobilitySettings& settings) {
  MobilitySettings copy = settings;
  const std::string where = "wtc::mobility::MobilitySettings: ";
  validate(copy.ground, where + "ground");
  if (!(copy.dt_s > 0.0) || !std::isfinite(copy.dt_s)) throw InvalidInputError(where + "dt must be finite and > 0 s");
  if (copy.engines.empty() || copy.modes.empty() || copy.events.empty()) {
    throw InvalidInputError(where + "engines, modes and events must each name at least one");
  }
  for (const std::string& e : copy.events) {
    if (const std::string p = eventProblem(e); !p.empty()) throw InvalidInputError(where + "events: " + p);
  }
  for (const std::string& e : copy.engines) {
    if (const std::string p = engineProblem(e); !p.empty()) throw InvalidInputError(where + p);
  }
  for (const std::string& m : copy.modes) {
    if (const std::string p = modeProblem(m); !p.empty()) throw InvalidInputError(where + p);
  }
  for (const Section& section : sections(copy)) {
    for (const NumberField& f : section.numbers) {
      if (const std::string p = numberProblem(f, *f.value); !p.empty()) {
        throw InvalidInputError(where + section.name + "." + f.key + ": " + p);
      }
    }
    for (const SearchField& f : section.searches) {
      if (const std::string p = searchProblem(*f.value); !p.empty()) {
        throw InvalidInputError(where + section.name + "." + f.key + ": " + p);
      }
    }
  }
  for (const double i : copy.drawbar.slips) {
    if (const std::string p = slipProblem(i); !p.empty()) throw InvalidInputError(where + "drawbar.slips: " + p);
  }
  if (copy.drawbar.slips.empty()) throw InvalidInputError(where + "drawbar.slips: none");
  // On soft soil (docs/soft-soil.md) the drawbar and grade events' bounds
  // come from the soil's steady state; the other events' come from the slip
  // law, which a soil replaces.
  if (copy.ground.soil) {
    for (const std::string& e : copy.events) {
      if (e != "drawbar" && e != "grade") {
        throw InvalidInputError(where + "events: '" + e + "' on a soil ground (" + copy.ground.soil->name +
                                "): on soft soil wtc-mobility runs the drawbar and grade events only "
                                "(docs/soft-soil.md)");
      }
    }
    for (const std::string& m : copy.modes) {
      if (m.starts_with("engine_")) {
        throw InvalidInputError(where + "modes: '" + m + "' on a soil ground (" + copy.ground.soil->name +
                                "): soft soil acts on WTC's wheels, not the engine's own (docs/soft-soil.md)");
      }
    }
  }
}

}  // namespace wtc::mobility
