// Scene files: the format is in include/wtc/sim/scene_file.hpp and
// scenes/README.md.
#include "wtc/sim/scene_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/file_support.hpp"
#include "io/terrain_node.hpp"
#include "io/yaml_reader.hpp"
#include "vehicle/controllers/controller_types.hpp"
#include "wtc/base/error.hpp"
#include "wtc/io/ground_memory_file.hpp"
#include "wtc/vehicle/plausibility.hpp"
#include "wtc/sim/sim_constants.hpp"
#include "wtc/sim/step_count.hpp"
#include "wtc/vehicle/vehicle_file.hpp"

namespace wtc::sim {
namespace {

using io::detail::YamlReader;

constexpr const char* kVehicleEffects[] = {"actuator_limits", "hitch_damping"};

// A scene's name becomes part of a directory's name (wtc-sim's default
// runs/<name>_<engine>_<mode>): letters, digits, '_', '-' and '.', not
// first, so that it can neither leave the runs directory ('/', "..") nor
// hide (a leading dot) nor carry a control character; at most this long,
// so the directory's name stays under the file systems' 255 bytes.
constexpr std::size_t kMaxNameLength = 128;  // (characters)

// `text` with control characters and bytes above ASCII as \xNN, for a message.
std::string printable(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f) {
      out.push_back(c);
    } else {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      out.append(escaped);
    }
  }
  return out;
}

// Why `name` cannot name a scene, or "" if it can.
std::string nameProblem(const std::string& name) {
  if (name.empty()) return "is empty";
  if (name.size() > kMaxNameLength) {
    return "is " + std::to_string(name.size()) + " characters long (at most " + std::to_string(kMaxNameLength) + ")";
  }
  if (name.front() == '.') return "starts with '.' (allowed: letters, digits, '_', '-' and '.' but not first)";
  for (const char c : name) {
    const bool allowed =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
    if (!allowed) {
      return "has the character '" + printable(std::string(1, c)) + "'" +
             " (allowed: letters, digits, '_', '-' and '.' but not first; it names the output directory)";
    }
  }
  return {};
}

// Applies one override to the document (a parameter's name as its first
// part sets that parameter); returns the value's node, now in the document.
YAML::Node applyOverride(YAML::Node& root, const Override& o, const std::string& where) {
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const std::size_t dot = o.path.find('.', start);
    parts.push_back(o.path.substr(start, dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  if (std::any_of(parts.begin(), parts.end(), [](const std::string& p) { return p.empty(); })) {
    throw InvalidInputError(where + ": '" + o.path + "' has an empty part");
  }
  YAML::Node value;
  try {
    value = YAML::Load(o.value);
  } catch (const YAML::Exception& e) {
    throw InvalidInputError(where + ": value '" + o.value + "' is not YAML: " + e.msg);
  }
  if (const auto duplicate = io::detail::findDuplicateKey(value)) {
    throw InvalidInputError(where + ": " + io::detail::duplicateKeyMessage(*duplicate));
  }
  if (!root[parts.front()] && root["parameters"] && root["parameters"].IsMap() && root["parameters"][parts.front()]) {
    parts.insert(parts.begin(), "parameters");
  }
  // yaml-cpp's Node is a handle: walk with copies, assign through the last.
  // `created`: the first part the document did not have (the override makes
  // it and all below it, so an error at any of them names the override:
  // --set vehicle.rotation.degrees=90 on a vehicle without a rotation makes
  // rotation {degrees: 90}, whose missing axis is the override's fault).
  std::size_t created = parts.size() - 1;
  YAML::Node node = root;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    const std::string& part = parts[i];
    if (created == parts.size() - 1 && (node.IsNull() || (node.IsMap() && !node[part]))) created = i;
    if (node.IsSequence()) {
      const bool digits = std::all_of(part.begin(), part.end(), [](char c) { return c >= '0' && c <= '9'; });
      if (!digits || std::stoul(part) >= node.size()) {
        throw InvalidInputError(where + ": '" + part + "' is not an index of the list at '" + o.path + "' (size " +
                                std::to_string(node.size()) + ")");
      }
      node.reset(node[std::stoul(part)]);
    } else if (node.IsMap() || node.IsNull()) {
      YAML::Node next = node[part];
      node.reset(next);
    } else {
      throw InvalidInputError(where + ": '" + part + "' in '" + o.path + "' is below a value, not a map or list");
    }
  }
  const std::string& last = parts.back();
  if (node.IsScalar()) {
    throw InvalidInputError(where + ": '" + parts[parts.size() - 2] + "' in '" + o.path +
                            "' is below a value, not a map or list");
  }
  if (node.IsSequence()) {
    const bool digits = std::all_of(last.begin(), last.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!digits || std::stoul(last) >= node.size()) {
      throw InvalidInputError(where + ": '" + last + "' is not an index of the list at '" + o.path + "'");
    }
    node[std::stoul(last)] = value;
  } else {
    node[last] = value;
  }
  if (created == parts.size() - 1) return value;
  YAML::Node made = root;
  for (std::size_t i = 0; i <= created; ++i) made.reset(made[parts[i]]);
  return made;
}

// Replaces every scalar "$name" ("-$name") outside `parameters` by the parameter's value.
void substitute(const YamlReader& in, YAML::Node node, const std::map<std::string, double>& parameters) {
  if (node.IsScalar()) {
    // "$name", or "-$name" for its negative.
    const std::string& s = node.Scalar();
    const bool negative = s.size() > 2 && s[0] == '-' && s[1] == '$';
    if (negative || (s.size() > 1 && s.front() == '$')) {
      const auto found = parameters.find(s.substr(negative ? 2 : 1));
      if (found == parameters.end()) in.fail(node, "'" + s + "' names no parameter of the scene");
      node = negative ? -found->second : found->second;
    }
    return;
  }
  if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) substitute(in, node[i], parameters);
  } else if (node.IsMap()) {
    for (auto entry : node) {
      if (entry.first.Scalar() != "parameters") substitute(in, entry.second, parameters);
    }
  }
}

// The controller type's own reader (src/vehicle/controllers) reads the rest.
void readController(const YamlReader& in, const YAML::Node& node, sim::Scene& scene) {
  in.requireMap(node, "controller");
  const YAML::Node type = in.require(node, "type");
  scene.controller_type = in.string(type, "controller.type");
  const vehicle::ControllerType* found = vehicle::findControllerType(scene.controller_type);
  if (found == nullptr) {
    in.fail(type, "controller.type: '" + scene.controller_type + "' (expected " + vehicle::controllerTypeNames() + ")");
  }
  scene.make_controller = found->read(in, node, scene.vehicle);
}

// `cases: {name: {value: {derived: number, ...}, ...}}`: the value of the
// parameter `name` picks a set of further parameters (a friction case
// picks its coefficients).
void applyCases(const YamlReader& in, const YAML::Node& cases, std::map<std::string, double>& parameters) {
  in.requireMap(cases, "cases");
  for (const auto& entry : cases) {
    const std::string name = entry.first.Scalar();
    const auto chosen = parameters.find(name);
    if (chosen == parameters.end()) in.fail(entry.first, "cases: '" + name + "' is not a parameter of the scene");
    in.requireMap(entry.second, ("cases." + name).c_str());
    bool found = false;
    std::string known;
    for (const auto& option : entry.second) {
      const double value = in.number(option.first, "cases." + name + " key");
      known += (known.empty() ? "" : ", ") + option.first.Scalar();
      if (value != chosen->second) continue;
      found = true;
      in.requireMap(option.second, ("cases." + name + "." + option.first.Scalar()).c_str());
      for (const auto& derived : option.second) {
        parameters[derived.first.Scalar()] = in.number(derived.second, "cases." + name + "." + derived.first.Scalar());
      }
    }
    if (!found) {
      in.fail(entry.second, "cases." + name + ": no case " + formatNumber(chosen->second) + " (known: " + known + ")");
    }
  }
}

void readEffects(const YamlReader& in, const YAML::Node& node, sim::Scene& scene) {
  if (!node.IsSequence()) in.fail(node, "effects: expected a list of names");
  std::vector<std::string> tyre;
  scene.vehicle_effects = {.actuator_limits = false, .hitch_damping = false};
  for (const auto& n : node) {
    const std::string name = in.string(n, "effects");
    if (name == "full") {
      scene.vehicle_effects = {};
      tyre.push_back(name);
    } else if (name == kVehicleEffects[0]) {
      scene.vehicle_effects.actuator_limits = true;
    } else if (name == kVehicleEffects[1]) {
      scene.vehicle_effects.hitch_damping = true;
    } else {
      tyre.push_back(name);
    }
  }
  try {
    scene.engine.tyre_effects = EffectSet::parse(tyre, "effects");
  } catch (const InvalidInputError& e) {
    in.fail(node, std::string(e.what()) + " (or a vehicle effect: actuator_limits, hitch_damping)");
  }
}

// The soft_soil effect integrates the soil's stresses over WTC's wheels (a
// cylinder's rim, a ball's slices: docs/soft-soil.md), not the engine's own
// wheels, whose contact knows no soil.
void checkSoilWheels(const YamlReader& in, const YAML::Node& at, const Scene& scene) {
  if (!scene.engine.tyre_effects.has(Effect::kSoftSoil)) return;
  const auto& materials = scene.terrain->materials();
  if (std::none_of(materials.begin(), materials.end(), [](const Material& m) { return m.soil.has_value(); })) return;
  if (scene.engine.native_wheels) {
    in.fail(at, "effects: soft_soil acts on WTC's wheels; mode " + std::string(modeName(scene.engine)) +
                    " gives the wheels to the engine, whose contact knows no soil (docs/soft-soil.md)");
  }
}

// `drawbar: {body, point, force}` or `{body, point, speed, stiffness,
// damping}` (wtc/sim/drawbar.hpp).
Drawbar readDrawbar(const YamlReader& in, const YAML::Node& node, const vehicle::VehicleDescription& vehicle) {
  in.requireMap(node, "drawbar");
  in.checkKeys(node, {"body", "point", "force", "speed", "stiffness", "damping"});
  Drawbar d;
  const YAML::Node body = in.require(node, "body");
  const std::string name = in.string(body, "drawbar.body");
  d.body = vehicle.find(name);
  if (d.body < 0) in.fail(body, "drawbar.body: '" + name + "' is not a body of vehicle '" + vehicle.name + "'");
  d.point_V = in.vector<3>(in.require(node, "point"), "drawbar.point");
  const auto force = YamlReader::get(node, "force");
  const auto speed = YamlReader::get(node, "speed");
  if (force && speed) {
    in.fail(*speed,
            "drawbar: give either force (a constant pull, N) or speed, stiffness and damping (an anchor "
            "moving at that speed), not both");
  }
  if (force) {
    for (const char* key : {"stiffness", "damping"}) {
      if (node[key]) in.fail(node[key], std::string("drawbar.") + key + ": only for an anchor (speed), not with force");
    }
    d.force_N = in.number(*force, "drawbar.force");
  } else {
    if (!speed) in.fail(node, "drawbar: give force (a constant pull, N) or speed, stiffness and damping (an anchor)");
    d.speed_mps = in.number(*speed, "drawbar.speed");
    d.stiffness_Npm = in.number(in.require(node, "stiffness"), "drawbar.stiffness");
    d.damping_Nspm = in.number(node, "damping", 0.0);
  }
  try {
    validate(d, vehicle, "drawbar");
  } catch (const InvalidInputError& e) {
    // The value at fault: the anchor's numbers, else the point.
    const char* keys[] = {"speed", "stiffness", "damping"};
    YAML::Node at = node["point"];
    for (const char* key : keys) {
      if (std::string(e.what()).find(std::string(key) + " =") != std::string::npos && node[key]) at = node[key];
    }
    in.fail(at, e.what());
  }
  return d;
}

// Reads the file that `node` (under `key`) names, relative to the scene;
// its errors are placed at that node too: "scene.yaml:12:10: terrain:
// ../terrains/x.yaml: file not found".
template <class Read>
auto referencedFile(const YamlReader& in, const YAML::Node& node, const std::string& key, Read&& read) {
  const std::string name = in.string(node, key);
  try {
    return read(in.path().parent_path() / name);
  } catch (const InvalidInputError& e) {
    in.fail(node, key + ": " + e.what());
  }
}

// `ground_memory_from: <file>`: ruts a run left (wtc/io/ground_memory_file.hpp),
// read whole here so that a file that does not fit the terrain's soil
// regions is refused before the run.
std::shared_ptr<const GroundMemory> readStartRuts(const YamlReader& in, const YAML::Node& node, const Scene& scene) {
  if (scene.terrain->soilRegions().empty()) {
    in.fail(node, "ground_memory_from: the terrain has no soil_regions to hold ruts");
  }
  if (!scene.engine.tyre_effects.has(Effect::kSoftSoil)) {
    in.fail(node, "ground_memory_from: ruts act through the soft_soil effect, which the scene's effects leave out");
  }
  auto ruts = std::make_shared<GroundMemory>(*scene.terrain);
  referencedFile(in, node, "ground_memory_from", [&](const std::filesystem::path& file) {
    io::readGroundMemoryCsv(file, *ruts);
    return 0;
  });
  return ruts;
}

}  // namespace

Override parseOverride(const std::string& text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw InvalidInputError("--set '" + text + "': expected key.path=value");
  }
  return {.path = text.substr(0, eq), .value = text.substr(eq + 1)};
}

namespace {

// `tilt_table: {axis: x | y, rate_deg_s, start_s, slide_m, slide_speed_mps}` (tilt_table.hpp).
TiltTable readTiltTable(const YamlReader& in, const YAML::Node& node, double duration_s) {
  in.requireMap(node, "tilt_table");
  in.checkKeys(node, {"axis", "rate_deg_s", "start_s", "slide_m", "slide_speed_mps"});
  TiltTable t;
  if (const auto a = YamlReader::get(node, "axis")) {
    const std::string axis = in.string(*a, "tilt_table.axis");
    if (axis != "x" && axis != "y") in.fail(*a, "tilt_table.axis: '" + axis + "' (expected x or y)");
    t.axis = axis == "x" ? 0 : 1;
  }
  t.rate_deg_s = in.number(node, "rate_deg_s", t.rate_deg_s);
  if (!(t.rate_deg_s > 0.0)) in.fail(node["rate_deg_s"], "tilt_table.rate_deg_s: must be > 0 deg/s");
  t.start_s = in.number(node, "start_s", t.start_s);
  if (!(t.start_s >= 0.0 && t.start_s < duration_s)) {
    in.fail(node["start_s"], "tilt_table.start_s: must be >= 0 s and before the run's end (" +
                                 formatNumber(duration_s) + " s)");
  }
  t.slide_m = in.number(node, "slide_m", t.slide_m);
  if (!(t.slide_m > 0.0)) in.fail(node["slide_m"], "tilt_table.slide_m: must be > 0 m");
  t.slide_speed_mps = in.number(node, "slide_speed_mps", t.slide_speed_mps);
  if (!(t.slide_speed_mps > 0.0)) in.fail(node["slide_speed_mps"], "tilt_table.slide_speed_mps: must be > 0 m/s");
  return t;
}

sim::Scene readSceneFile(const std::filesystem::path& path, std::span<const Override> overrides,
                         const EngineCheck& check_engine) {
  YAML::Node root = io::detail::loadYamlFile(path);
  YamlReader in(path);
  in.requireMap(root, "scene file");
  // An error in an override's value names the override, not a line.
  for (const Override& o : overrides) {
    const std::string name = "--set " + o.path + "=" + o.value;
    in = in.withOrigin({.subtree = applyOverride(root, o, name), .label = name, .replaces_position = true});
  }
  in.checkKeys(root, {"name", "description", "parameters", "engine", "mode", "dt", "duration", "solver_iterations",
                      "solver_residual", "terrain", "vehicle", "effects", "controller", "output", "success", "cases",
                      "drawbar", "tilt_table", "ground_memory_from"});

  sim::Scene scene;
  scene.source = path.string();
  if (const auto p = YamlReader::get(root, "parameters")) {
    in.requireMap(*p, "parameters");
    for (const auto& entry : *p) {
      scene.parameters[entry.first.Scalar()] = in.number(entry.second, "parameters." + entry.first.Scalar());
    }
  }
  if (const auto cases = YamlReader::get(root, "cases")) applyCases(in, *cases, scene.parameters);
  substitute(in, root, scene.parameters);

  scene.name = in.string(in.require(root, "name"), "name");
  if (const std::string problem = nameProblem(scene.name); !problem.empty()) {
    in.fail(root["name"], "name: '" + printable(scene.name) + "' " + problem);
  }
  if (const auto d = YamlReader::get(root, "description")) scene.description = in.string(*d, "description");
  // The engine table (wtc::sim_engines) lies a layer above this reader: the
  // name keeps its place here, and the caller's check (requireEngine), or
  // else makeEngine, refuses a name the table does not have with that place
  // and the names it has.
  if (const auto e = YamlReader::get(root, "engine")) {
    scene.engine.engine = in.string(*e, "engine");
    scene.engine.engine_where = in.describe(*e, "engine");
  }
  if (const auto m = YamlReader::get(root, "mode")) {
    try {
      sim::parseMode(in.string(*m, "mode"), scene.engine, "mode");
    } catch (const InvalidInputError& error) {
      in.fail(*m, error.what());
    }
  }
  if (check_engine) check_engine(scene.engine);
  scene.engine.step_seconds = in.number(root, "dt", scene.engine.step_seconds);
  if (!(scene.engine.step_seconds > 0.0)) in.fail(root["dt"], "dt: must be > 0 s");
  scene.engine.solver_iterations = static_cast<int>(in.integer(root, "solver_iterations", 50));
  if (scene.engine.solver_iterations <= 0) in.fail(root["solver_iterations"], "solver_iterations: must be > 0");
  scene.engine.solver_residual = in.number(root, "solver_residual", scene.engine.solver_residual);
  if (!(scene.engine.solver_residual > 0.0)) in.fail(root["solver_residual"], "solver_residual: must be > 0 (m/s)^2");
  scene.duration_seconds = in.number(in.require(root, "duration"), "duration");
  if (!(scene.duration_seconds > 0.0)) in.fail(root["duration"], "duration: must be > 0 s");
  try {
    sim::stepCount(scene.duration_seconds, scene.engine.step_seconds);
  } catch (const InvalidInputError& e) {
    // Blame the step when it alone is wrong (longer than the run), else the duration.
    in.fail(scene.engine.step_seconds > scene.duration_seconds && root["dt"] ? root["dt"] : root["duration"],
            std::string(scene.engine.step_seconds > scene.duration_seconds ? "dt" : "duration") + ": " + e.what());
  }

  const YAML::Node terrain = in.require(root, "terrain");
  TerrainBuilder builder;
  io::TerrainFileReport terrain_report;
  if (terrain.IsScalar()) {
    terrain_report = referencedFile(
        in, terrain, "terrain", [&](const std::filesystem::path& file) { return io::addTerrainFile(builder, file); });
  } else {
    terrain_report = io::detail::addTerrainNode(builder, in.with("terrain: "), terrain);
  }
  if (builder.pieceCount() == 0) in.fail(terrain, "terrain: no pieces");
  scene.terrain = std::make_shared<const Terrain>(std::move(builder).build());
  scene.warnings = terrain_report.warnings;

  const YAML::Node v = in.require(root, "vehicle");
  if (v.IsScalar()) {
    scene.vehicle = referencedFile(in, v, "vehicle", vehicle::loadVehicle);
  } else {
    in.requireMap(v, "vehicle");
    in.checkKeys(v, {"file", "translation", "rotation", "velocity"});
    scene.vehicle = referencedFile(in, in.require(v, "file"), "vehicle.file", vehicle::loadVehicle);
    scene.placement = in.with("vehicle: ").pose(v);
    if (const auto velocity = YamlReader::get(v, "velocity")) {
      scene.start_velocity_V = in.vector<3>(*velocity, "vehicle.velocity");
      if (scene.start_velocity_V.norm() > kDivergedSpeedMps) {
        in.fail(*velocity, "vehicle.velocity: " + formatNumber(scene.start_velocity_V.norm()) +
                               " m/s is beyond the speed at which a run stops as diverged, " +
                               formatNumber(kDivergedSpeedMps) + " m/s");
      }
    }
  }
  // Valid but what a unit slip gives (grams, millimetres, degrees): said, not refused.
  for (const std::string& w : vehicle::plausibilityWarnings(scene.vehicle)) scene.warnings.push_back("vehicle: " + w);
  if (const auto d = YamlReader::get(root, "drawbar")) scene.drawbar = readDrawbar(in, *d, scene.vehicle);
  if (const auto t = YamlReader::get(root, "tilt_table")) scene.tilt_table = readTiltTable(in, *t, scene.duration_seconds);

  readEffects(in, YamlReader::get(root, "effects").value_or(YAML::Load("[full]")), scene);
  checkSoilWheels(in, YamlReader::get(root, "effects").value_or(root), scene);
  if (const auto g = YamlReader::get(root, "ground_memory_from")) scene.start_ruts = readStartRuts(in, *g, scene);
  readController(in, in.require(root, "controller"), scene);

  if (const auto o = YamlReader::get(root, "output")) {
    in.requireMap(*o, "output");
    in.checkKeys(*o, {"rate_hz", "plots", "replay", "replay_fps"});
    scene.output.rate_hz = in.number(*o, "rate_hz", scene.output.rate_hz);
    if (!(scene.output.rate_hz > 0.0)) in.fail((*o)["rate_hz"], "output.rate_hz: must be > 0");
    scene.output.plots = in.boolean(*o, "plots", scene.output.plots);
    scene.output.replay = in.boolean(*o, "replay", scene.output.replay);
    scene.output.replay_fps = in.number(*o, "replay_fps", scene.output.replay_fps);
    if (!(scene.output.replay_fps > 0.0)) in.fail((*o)["replay_fps"], "output.replay_fps: must be > 0");
  }
  if (const auto s = YamlReader::get(root, "success")) {
    in.requireMap(*s, "success");
    in.checkKeys(
        *s, {"min_distance", "max_distance", "min_advance", "max_final_speed", "max_tilt_deg", "min_wheel_height",
             "min_turn_deg"});
    if (const auto d = YamlReader::get(*s, "min_distance")) scene.success.min_distance = in.number(*d, "min_distance");
    if (const auto d = YamlReader::get(*s, "max_distance")) scene.success.max_distance = in.number(*d, "max_distance");
    if (const auto d = YamlReader::get(*s, "min_advance")) scene.success.min_advance = in.number(*d, "min_advance");
    if (const auto d = YamlReader::get(*s, "max_final_speed")) {
      scene.success.max_final_speed = in.number(*d, "max_final_speed");
    }
    scene.success.max_tilt_deg = in.number(*s, "max_tilt_deg", scene.success.max_tilt_deg);
    if (const auto d = YamlReader::get(*s, "min_wheel_height")) {
      scene.success.min_wheel_height = in.number(*d, "min_wheel_height");
    }
    if (const auto d = YamlReader::get(*s, "min_turn_deg")) scene.success.min_turn_deg = in.number(*d, "min_turn_deg");
  }
  return scene;
}

}  // namespace

sim::Scene loadScene(const std::filesystem::path& path, std::span<const Override> overrides,
                     const EngineCheck& check_engine) {
  return io::detail::withYamlErrors(path, [&] { return readSceneFile(path, overrides, check_engine); });
}

}  // namespace wtc::sim
