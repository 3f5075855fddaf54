#include "wtc/mobility/mobility_report.hpp"

#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "short_number.hpp"
#include "wtc/base/error.hpp"

namespace wtc::mobility {
namespace {

// measured / bound - 1, as a signed percentage, or "".
std::string against(const EventResult& r) {
  if (!r.measured || r.bound == 0.0) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%+.1f %%", 100.0 * (*r.measured / r.bound - 1.0));
  return text;
}

}  // namespace

std::string reportTable(const MobilityOutcome& outcome) {
  std::string t =
      "| event | engine | mode | measured | bound | measured / bound | governing limit | how |\n"
      "|---|---|---|---|---|---|---|---|\n";
  for (const EventResult& r : outcome.results) {
    const std::string unit = r.unit.empty() ? "" : " " + r.unit;
    std::string bound = shortNumber(r.bound) + unit;
    if (r.bound_lower) bound = shortNumber(*r.bound_lower) + "–" + shortNumber(r.bound) + unit;
    if (r.governs.empty()) bound = "—";
    std::string measured = r.measured ? shortNumber(*r.measured) + unit : "—";
    if (r.torque_coefficient) measured += " (ΣT/(r W) " + shortNumber(*r.torque_coefficient) + ")";
    std::string how = r.note;
    if (!r.trials.empty()) how = std::to_string(r.trials.size()) + " runs; " + how;
    t += "| " + r.quantity + " | " + r.engine + " | " + r.mode + " | " + measured + " | " + bound + " | " + against(r) +
         " | " + r.governs + " | " + how + " |\n";
  }
  return t;
}

void writeReport(const EventVehicle& v, const MobilitySettings& s, const MobilityOutcome& outcome,
                 const std::filesystem::path& out, const std::string& command) {
  nlohmann::json j;
  j["vehicle"] = {{"name", v.description.name},
                  {"file", v.file.string()},
                  {"mass_kg", v.statics.mass_kg},
                  {"com_m", {v.statics.com.x(), v.statics.com.y(), v.statics.com.z()}}};
  j["ground"] = {{"mu_max", s.ground.mu_max},
                 {"s1", s.ground.s1},
                 {"s2", s.ground.s2},
                 {"rolling_resistance", s.ground.rolling_resistance}};
  if (s.ground.soil) j["ground"]["soil"] = s.ground.soil->name;
  j["command"] = command;
  j["complete"] = outcome.pending_jobs == 0;
  nlohmann::json results = nlohmann::json::array();
  for (const EventResult& r : outcome.results) {
    nlohmann::json e = {{"event", r.event}, {"engine", r.engine}, {"mode", r.mode},       {"quantity", r.quantity},
                        {"unit", r.unit},   {"bound", r.bound},   {"governs", r.governs}, {"note", r.note}};
    e["measured"] = r.measured ? nlohmann::json(*r.measured) : nlohmann::json(nullptr);
    if (r.bound_lower) e["bound_lower"] = *r.bound_lower;
    if (r.slip >= 0.0) e["slip"] = r.slip;
    if (r.torque_coefficient) e["torque_coefficient"] = *r.torque_coefficient;
    nlohmann::json trials = nlohmann::json::array();
    for (const Trial& t : r.trials) {
      trials.push_back({{"value", t.value}, {"passed", t.passed}, {"failure", t.failure}, {"run", t.run}});
    }
    e["trials"] = trials;
    results.push_back(e);
  }
  j["results"] = results;
  const std::filesystem::path json = out / "report.json";
  std::ofstream(json) << j.dump(2) << '\n';
  std::ofstream md(out / "report.md");
  if (!md) throw InvalidInputError("wtc::mobility::writeReport: cannot write " + (out / "report.md").string());
  md << "# Mobility events: " << v.description.name << "\n\n"
     << "`" << command << "`\n\n"
     << "Vehicle " << v.file.string() << ": " << shortNumber(v.statics.mass_kg) << " kg. Ground: mu_max "
     << shortNumber(s.ground.mu_max) << ", s1 " << shortNumber(s.ground.s1) << ", s2 " << shortNumber(s.ground.s2)
     << ", f_r " << shortNumber(s.ground.rolling_resistance)
     << (s.ground.soil ? "; soft soil " + s.ground.soil->name + " (soft_soil: docs/soft-soil.md)" : std::string())
     << ".\n\n"
     << (outcome.pending_jobs ? "**Incomplete**: " + std::to_string(outcome.pending_jobs) +
                                    " runs of the next round are in jobs.txt.\n\n"
                              : std::string())
     << reportTable(outcome);
}

}  // namespace wtc::mobility
