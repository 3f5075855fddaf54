#include "wtc/sim/run_summary_file.hpp"

#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

#include "io/atomic_file.hpp"
#include "wtc/base/constants.hpp"
#include "wtc/base/error.hpp"

namespace wtc::sim {
namespace {

std::string engineText(const sim::Scene& scene) { return scene.engine.engine; }

void writeJson(const std::filesystem::path& path, const nlohmann::json& j) {
  io::writeFileAtomically(path, j.dump(2) + '\n');
}

// Top-level keys that are not the scene's own figures (RunSummary::fields).
const std::set<std::string>& fixedKeys() {
  static const std::set<std::string> keys = {"scene",
                                             "status",
                                             "engine",
                                             "mode",
                                             "dt",
                                             "sim_time",
                                             "wall_time",
                                             "real_time_factor",
                                             "wtc_time",
                                             "wtc_share",
                                             "steps",
                                             "success",
                                             "failed_criteria",
                                             "nan",
                                             "diverged",
                                             "interrupted",
                                             "max_penetration",
                                             "max_joint_gap_m",
                                             "max_joint_angle_deg",
                                             "saturation_steps",
                                             "warnings",
                                             "parameters",
                                             "drives",
                                             "wheels",
                                             "note"};
  return keys;
}

nlohmann::json failedJson(const std::vector<sim::FailedCriterion>& failed) {
  nlohmann::json list = nlohmann::json::array();
  for (const sim::FailedCriterion& f : failed) {
    list.push_back({{"criterion", f.criterion},
                    {"limit", f.limit ? nlohmann::json(*f.limit) : nlohmann::json(nullptr)},
                    {"measured", f.measured ? nlohmann::json(*f.measured) : nlohmann::json(nullptr)},
                    {"unit", f.unit},
                    {"detail", f.detail}});
  }
  return list;
}

std::vector<sim::FailedCriterion> readFailed(const nlohmann::json& list) {
  std::vector<sim::FailedCriterion> failed;
  const auto number = [](const nlohmann::json& j, const char* key) -> std::optional<double> {
    return j.contains(key) && !j.at(key).is_null() ? std::optional<double>(j.at(key).get<double>()) : std::nullopt;
  };
  for (const nlohmann::json& f : list) {
    failed.push_back({.criterion = f.at("criterion").get<std::string>(),
                      .limit = number(f, "limit"),
                      .measured = number(f, "measured"),
                      .unit = f.value("unit", std::string()),
                      .detail = f.value("detail", std::string())});
  }
  return failed;
}

}  // namespace

std::string runSummaryText(const sim::RunSummary& s) {
  nlohmann::json j = {{"scene", s.scene},
                      {"program", s.program},
                      {"status", s.interrupted ? "interrupted" : "completed"},
                      {"engine", s.engine},
                      {"mode", s.mode},
                      {"dt", s.dt},
                      {"sim_time", s.sim_time},
                      {"wall_time", s.wall_time},
                      {"real_time_factor", s.real_time_factor},
                      {"wtc_time", s.wtc_time},
                      {"wtc_share", s.wtcShare()},
                      {"steps", s.steps},
                      {"success", s.success},
                      {"failed_criteria", failedJson(s.failed_criteria)},
                      {"nan", s.nan},
                      {"diverged", s.diverged},
                      {"interrupted", s.interrupted},
                      {"max_penetration", s.max_penetration},
                      {"max_joint_gap_m", s.max_joint_gap},
                      {"max_joint_angle_deg", s.max_joint_angle * kDegPerRad},
                      {"saturation_steps", s.saturation_steps},
                      {"warnings", s.warnings},
                      {"parameters", s.parameters}};
  for (const auto& [key, value] : s.fields) j[key] = value;
  for (const sim::DriveSummary& d : s.drives) {
    j["drives"][d.name] = {{"joint", d.joint},
                           {"steps", d.steps},
                           {"saturated_steps", d.saturated_steps},
                           {"peak_effort", d.peak_effort},
                           {"mean_effort", d.mean_effort}};
  }
  for (const auto& [name, slip] : s.wheel_peak_slip) j["wheels"][name]["peak_slip"] = slip;
  return j.dump(2) + '\n';
}

void writeRunSummary(const std::filesystem::path& file, const sim::RunSummary& s) {
  io::writeFileAtomically(file, runSummaryText(s));
}

void writeRunStarted(const std::filesystem::path& file, const sim::Scene& scene) {
  writeJson(file, {{"scene", scene.name},
                   {"engine", engineText(scene)},
                   {"mode", sim::modeName(scene.engine)},
                   {"dt", scene.engine.step_seconds},
                   {"status", "running"},
                   {"interrupted", true},
                   {"success", false},
                   {"failed_criteria",
                    failedJson({{.criterion = "interrupted",
                                 .limit = scene.duration_seconds,
                                 .measured = std::nullopt,
                                 .unit = "s",
                                 .detail = "the run has not ended: this summary is the one written at its start (a run "
                                           "killed before its end leaves it)"}})},
                   {"note", "written when the run started; a run that ends replaces it"}});
}

namespace {

// Over the summary a run left (its start's, or none): the run ended without
// a summary of its own, with `status`, `criterion` and `reason`.
void writeRunEndedWithout(const std::filesystem::path& file, const char* status, const char* criterion,
                          const std::string& reason, const char* note) {
  nlohmann::json j;
  if (std::ifstream in(file); in) j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object()) j = nlohmann::json::object();
  j["status"] = status;
  j["success"] = false;
  j["interrupted"] = false;
  j["warnings"] = std::vector<std::string>{reason};
  j["failed_criteria"] = failedJson(
      {{.criterion = criterion, .limit = std::nullopt, .measured = std::nullopt, .unit = "", .detail = reason}});
  j["note"] = note;
  for (const char* key : {"scene", "engine", "mode"}) {
    if (!j.contains(key)) j[key] = "?";
  }
  if (!j.contains("dt")) j["dt"] = 0.0;
  writeJson(file, j);
}

}  // namespace

void writeRunCrashed(const std::filesystem::path& file, const std::string& reason) {
  writeRunEndedWithout(file, "crashed", "crashed", reason, "the run's process died; written by the study's runner");
}

void writeRunFailed(const std::filesystem::path& file, const std::string& reason) {
  writeRunEndedWithout(file, "failed", "error", reason,
                       "the run ended early by an error (its message is the warning); no figures were measured");
}

sim::RunSummary readRunSummary(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InvalidInputError(file.string() + ": cannot read the run's summary");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
    sim::RunSummary s;
    s.scene = j.at("scene").get<std::string>();
    s.engine = j.at("engine").get<std::string>();
    s.mode = j.at("mode").get<std::string>();
    s.program = j.value("program", std::string());
    s.dt = j.at("dt").get<double>();
    s.success = j.at("success").get<bool>();
    const std::string status = j.at("status").get<std::string>();
    s.crashed = status == "crashed";
    const bool failed = status == "failed";  // ended by an error (writeRunFailed)
    s.interrupted = status != "completed" && !s.crashed && !failed;
    if (s.crashed || failed) s.warnings = j.at("warnings").get<std::vector<std::string>>();
    // Absent from summaries written before runs said why they failed.
    if (j.contains("failed_criteria")) s.failed_criteria = readFailed(j.at("failed_criteria"));
    if (status != "completed") return s;
    s.sim_time = j.at("sim_time").get<double>();
    s.wall_time = j.at("wall_time").get<double>();
    s.real_time_factor = j.at("real_time_factor").get<double>();
    s.wtc_time = j.value("wtc_time", 0.0);  // absent from summaries written before it was measured
    s.steps = j.at("steps").get<std::uint64_t>();
    s.nan = j.at("nan").get<bool>();
    s.diverged = j.at("diverged").get<bool>();
    s.max_penetration = j.at("max_penetration").get<double>();
    s.max_joint_gap = j.at("max_joint_gap_m").get<double>();
    s.max_joint_angle = j.at("max_joint_angle_deg").get<double>() / kDegPerRad;
    s.saturation_steps = j.at("saturation_steps").get<std::uint64_t>();
    s.warnings = j.at("warnings").get<std::vector<std::string>>();
    s.parameters = j.at("parameters").get<std::map<std::string, double>>();
    for (const auto& [key, value] : j.items()) {
      if (!fixedKeys().contains(key) && value.is_number()) s.fields[key] = value.get<double>();
    }
    if (j.contains("drives")) {
      for (const auto& [name, d] : j["drives"].items()) {
        s.drives.push_back({.name = name,
                            .joint = d.value("joint", std::string()),  // absent from summaries before 2026-11-29
                            .steps = d.at("steps").get<std::uint64_t>(),
                            .saturated_steps = d.at("saturated_steps").get<std::uint64_t>(),
                            .peak_effort = d.at("peak_effort").get<double>(),
                            .mean_effort = d.at("mean_effort").get<double>()});
      }
    }
    if (j.contains("wheels")) {
      for (const auto& [name, w] : j["wheels"].items()) s.wheel_peak_slip[name] = w.at("peak_slip").get<double>();
    }
    return s;
  } catch (const nlohmann::json::exception& e) {
    throw InvalidInputError(file.string() + ": not a run summary: " + e.what());
  }
}

bool runEnded(const std::filesystem::path& dir) {
  const std::filesystem::path file = dir / "summary.json";
  if (!std::filesystem::exists(file)) return false;
  std::ifstream in(file);
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  return j.is_object() && (j.value("status", "") == "completed" || j.value("status", "") == "crashed");
}

}  // namespace wtc::sim
