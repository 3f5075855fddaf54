// The events' rounds (wtc/mobility/mobility_run.hpp): each round asks every
// unfinished search for its next trial and every one-run event for its run,
// makes the runs not yet finished (the study's pool, or a job list), reads
// them back and advances the searches.
#include "wtc/mobility/mobility_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

#include "io/content_hash.hpp"
#include "wtc/base/error.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/run_summary_file.hpp"
#include "wtc/study/study_runner.hpp"
#include "wtc/terrain/terrain_primitives.hpp"

namespace wtc::mobility {
namespace {

namespace fs = std::filesystem;

// A run in which a root tilted more than this went over (deg): its
// measurement is not the event's (a stop over the locked front wheels).
constexpr double kOverturnedDeg = 45.0;

// A held event (parked, side_slope) on a tilt table: one run (TiltSettings).
bool onTiltTable(const std::string& event, const MobilitySettings& s) {
  return (event == "parked" && s.parked.tilt.rate_deg_s > 0.0) ||
         (event == "side_slope" && s.side_slope.tilt.rate_deg_s > 0.0);
}

bool isSearch(const std::string& event, const MobilitySettings& s) {
  return (event == "step" || event == "grade" || event == "parked" || event == "side_slope" || event == "gap") &&
         !onTiltTable(event, s);
}

// A tilt table's answer from its run's summary: the angle where the vehicle
// tipped or slid, or the table's top when it held to the end (at least that).
void readTiltTable(EventResult& r, const sim::RunSummary& summary, const MobilitySettings& s, const std::string& run) {
  const TiltSettings& tilt = r.event == "side_slope" ? s.side_slope.tilt : s.parked.tilt;
  const std::string how = "tilt table at " + formatNumber(tilt.rate_deg_s) + " deg/s";
  for (const auto& [field, what] : {std::pair{"tilt_tipped_deg", "tipped"}, std::pair{"tilt_slid_deg", "slid"}}) {
    if (const auto it = summary.fields.find(field); it != summary.fields.end()) {
      r.measured = it->second;
      r.note = how + ": " + what + " (" + run + ")";
      return;
    }
  }
  const auto top = summary.fields.find("tilt_final_deg");
  if (top != summary.fields.end()) r.measured = top->second;
  r.note = how + ": held to its top, at least this (raise the range) (" + run + ")";
}

Search rangeOf(const std::string& event, const MobilitySettings& s) {
  if (event == "step") return s.step.height_m;
  if (event == "grade") return s.grade.degrees;
  if (event == "parked") return s.parked.degrees;
  if (event == "side_slope") return s.side_slope.degrees;
  return s.gap.width_m;
}

// One event in one engine and mode (a drawbar: at one slip).
struct Unit {
  EventResult result;
  double lo = 0.0, hi = 0.0;  // a search's largest pass and smallest failure so far
  bool done = false;
};

// A search's next value: the range's top first, then halving [lo, hi] on the resolution's grid.
std::optional<double> nextValue(Unit& u, const Search& range) {
  if (u.result.trials.empty()) return range.high;
  if (u.result.trials.front().passed || u.hi - u.lo <= range.resolution * (1.0 + 1e-9)) return std::nullopt;
  const double steps = std::max(1.0, std::round(0.5 * (u.hi - u.lo) / range.resolution));
  return u.lo + steps * range.resolution;
}

void describeSearch(Unit& u, const Search& range) {
  EventResult& r = u.result;
  const bool any = std::any_of(r.trials.begin(), r.trials.end(), [](const Trial& t) { return t.passed; });
  if (r.trials.front().passed) {
    r.measured = range.high;
    r.note = "passed the search's top: at least this (raise the range)";
  } else {
    r.measured = u.lo;
    r.note = "bisection to " + formatNumber(range.resolution) +
             (any ? "" : "; no trial passed (at most the range's low)") +
             "; first failure above: " + r.trials.back().failure;
    for (const Trial& t : r.trials) {
      if (!t.passed && t.value == u.hi) {
        char value[32];
        std::snprintf(value, sizeof value, "%.6g", t.value);
        r.note = "bisection to " + formatNumber(range.resolution) + (any ? "" : "; no trial passed") + "; at " + value +
                 ": " + t.failure;
      }
    }
  }
}

}  // namespace

std::string trialFailure(const sim::RunSummary& summary, const std::string& event) {
  if (summary.crashed) return "crashed";
  if (summary.nan) return "non-finite state";
  if (summary.diverged) return "diverged";
  // A run whose joints came apart did not move the vehicle the description
  // gives (a solver that did not hold a bogie): whatever it reached is not
  // the vehicle's.
  std::string text = sim::jointsCameApart(summary) ? "joints came apart" : "";
  if (summary.success && !text.empty()) return text;
  if (summary.success) return {};
  for (const sim::FailedCriterion& f : summary.failed_criteria) {
    std::string what = f.criterion;
    if (event == "side_slope" && (what == "max_final_speed" || what == "max_distance")) what = "slid";
    if (event == "side_slope" && what == "max_tilt_deg") what = "tipped";
    if (event == "parked" && (what == "max_final_speed" || what == "max_distance")) what = "slid";
    if ((event == "grade" || event == "step" || event == "gap") && what == "min_advance") what = "stopped short";
    if (text.find(what) == std::string::npos) text += (text.empty() ? "" : ", ") + what;
  }
  return text.empty() ? "failed" : text;
}

namespace {

// What each event measures, in what unit, against which of the bounds (the
// turn's is optional: only a skid-steered vehicle has one; the drawbar's
// are per slip, made below).
struct EventQuantity {
  const char* event;
  const char* quantity;
  const char* unit;
  Bound VehicleBounds::*bound;
};

const EventQuantity* quantityOf(const std::string& event) {
  static const EventQuantity table[] = {
      {"step", "tallest step", "m", &VehicleBounds::step_m},
      {"grade", "steepest grade from rest", "deg", &VehicleBounds::grade_deg},
      {"parked", "steepest grade held", "deg", &VehicleBounds::parked_deg},
      {"side_slope", "side slope held", "deg", &VehicleBounds::side_slope_deg},
      {"gap", "widest gap", "m", &VehicleBounds::gap_m},
      {"coast", "coast-down deceleration", "m/s^2", &VehicleBounds::coast_mps2},
      {"braking", "locked stop", "m", &VehicleBounds::braking_m},
      {"turn", "yaw rate turning in place", "rad/s", nullptr},
  };
  for (const EventQuantity& q : table) {
    if (event == q.event) return &q;
  }
  return nullptr;
}

void setBound(EventResult& r, const Bound& b) {
  r.bound = b.value;
  r.bound_lower = b.lower;
  r.governs = b.governs;
}

// Why `engine` refuses to build the vehicle in `mode` ("" if it builds it):
// the engine's own message (ODE refuses a mimic about parallel axes, Bullet
// a wheel that is a root), found once, on `slab`, before any run.
std::string refusal(const vehicle::VehicleDescription& vehicle, const Terrain& slab, const std::string& engine,
                    const std::string& mode, double dt) {
  sim::EngineSettings settings{.engine = engine, .step_seconds = dt};
  sim::parseMode(mode, settings, "modes");
  try {
    sim::makeEngine(settings, slab, vehicle, Eigen::Isometry3d::Identity());
  } catch (const InvalidInputError& e) {
    return e.what();
  }
  return {};
}

}  // namespace

MobilityOutcome runMobility(const EventVehicle& v, const MobilitySettings& s, const MobilityOptions& opt) {
  validate(s);
  MobilityOutcome outcome;
  outcome.bounds = computeBounds(v.statics, s);
  const VehicleBounds& b = outcome.bounds;
  fs::create_directories(opt.out / "scenes");
  fs::create_directories(opt.out / "runs");
  // A job list says what is left: emptied first, so that once every round
  // is done it is empty, not the last round's lines again.
  if (opt.job_list) std::ofstream(opt.out / "jobs.txt", std::ios::trunc);

  // An engine that refuses the vehicle is a row of the report, not the
  // end of the batch: the other engines' events run (issue 57 row 7).
  std::map<std::pair<std::string, std::string>, std::string> refused;
  {
    TerrainBuilder builder;
    addSlab(builder, SlabParams{}, builder.addMaterial(Material{}));
    const Terrain slab = std::move(builder).build();  // one bare slab for every engine and mode asked
    for (const std::string& engine : s.engines) {
      for (const std::string& mode : s.modes) refused[{engine, mode}] = refusal(v.description, slab, engine, mode, s.dt_s);
    }
  }
  std::vector<Unit> units;
  for (const std::string& event : s.events) {
    for (const std::string& engine : s.engines) {
      for (const std::string& mode : s.modes) {
        Unit u;
        u.result.event = event;
        u.result.engine = engine;
        u.result.mode = mode;
        if (const EventQuantity* q = quantityOf(event)) {
          u.result.quantity = q->quantity;
          u.result.unit = q->unit;
          if (q->bound != nullptr) {
            setBound(u.result, b.*(q->bound));
          } else if (b.turn_radps) {
            setBound(u.result, *b.turn_radps);
          } else {
            u.result.note = "not skid-steered: the event does not apply";
            u.done = true;
          }
        }
        if (event == "step" && s.step.vehicle_controller && hasClimbingController(v.description)) {
          u.result.quantity = "tallest step (the vehicle's climbing controller)";
          u.result.governs += "; the bound is a plain drive's: a climbing controller's reach is its geometry's";
        } else if (event == "gap") {
          u.result.governs += " (one wheel dropping into it: a vehicle whose other axles carry it may bridge more)";
        }
        if (isSearch(event, s)) {
          u.lo = rangeOf(event, s).low;
          u.hi = rangeOf(event, s).high;
        }
        if (const std::string& why = refused[{engine, mode}]; !why.empty()) {
          u.result.note = "the engine refuses the vehicle: " + why;
          u.done = true;
        }
        if (event != "drawbar") {
          units.push_back(u);
          continue;
        }
        for (const DrawbarPoint& p : b.drawbar) {
          Unit d = u;
          d.result.slip = p.slip;
          d.result.quantity = "DP/W at i = " + formatNumber(p.slip);
          d.result.unit = "";
          d.result.bound = p.dp_per_weight;
          d.result.governs = s.ground.soil ? "the soil's steady state (" + s.ground.soil->name + ") at the static loads"
                                           : "mu(s) at the driven wheels";
          units.push_back(d);
        }
      }
    }
  }

  for (int round = 0;; ++round) {
    // Each unfinished unit's next run.
    struct Want {
      Unit* unit;
      double value;
      study::PlannedRun run;
    };
    std::vector<Want> wanted;
    std::map<std::string, bool> written;
    for (Unit& u : units) {
      if (u.done) continue;
      double value = onTiltTable(u.result.event, s) ? kTiltTableValue : u.result.slip;
      if (isSearch(u.result.event, s)) {
        const std::optional<double> next = nextValue(u, rangeOf(u.result.event, s));
        if (!next) {
          u.done = true;
          describeSearch(u, rangeOf(u.result.event, s));
          continue;
        }
        value = *next;
      }
      const std::string text = eventScene(v, u.result.event, value, s);
      const std::string name = sceneName(v, u.result.event, value);
      const fs::path scene = opt.out / "scenes" / (name + ".yaml");
      if (!written[name]) {
        std::ofstream(scene) << text;
        written[name] = true;
      }
      study::PlannedRun run;
      run.scenario = u.result.event;
      run.scene_file = fs::absolute(scene);
      run.overrides = {{.path = "engine", .value = u.result.engine},
                       {.path = "mode", .value = u.result.mode},
                       {.path = "dt", .value = formatNumber(s.dt_s)}};
      run.origins = {"engines", "modes", "dt"};
      run.sweep = "mobility";
      run.label = u.result.engine + " " + u.result.mode;
      // The scene's text is in the key: other settings (a ground, a speed) never reuse a run.
      const std::uint64_t h =
          io::fnv1a(text + "\n" + u.result.engine + "\n" + u.result.mode + "\n" + formatNumber(s.dt_s));
      run.key = name + "-" + u.result.engine + "-" + u.result.mode + "-" + io::hexDigits(h);
      wanted.push_back({&u, value, run});
    }
    if (wanted.empty()) break;

    study::StudyPlan pending;
    pending.name = "mobility";
    pending.source = opt.out / "scenes";
    for (const Want& w : wanted) {
      if (sim::runEnded(study::runDirectory(opt.out, w.run))) continue;
      if (std::none_of(pending.runs.begin(), pending.runs.end(),
                       [&](const study::PlannedRun& r) { return r.key == w.run.key; })) {
        pending.runs.push_back(w.run);
        if (std::find(pending.scenarios.begin(), pending.scenarios.end(), w.run.scenario) == pending.scenarios.end()) {
          pending.scenarios.push_back(w.run.scenario);
        }
      }
    }
    if (!pending.runs.empty()) {
      if (opt.job_list) {
        std::ofstream jobs(opt.out / "jobs.txt");
        for (const std::string& line : study::jobLines(pending, opt.out, opt.wtc_sim)) jobs << line << '\n';
        outcome.pending_jobs = pending.runs.size();
        break;
      }
      if (opt.progress) {
        opt.progress("round " + std::to_string(round + 1) + ": " + std::to_string(pending.runs.size()) + " runs");
      }
      study::runPlan(pending, opt.out, opt.workers, opt.wtc_sim);
      outcome.runs_made += pending.runs.size();
    }
    for (const Want& w : wanted) {
      Unit& u = *w.unit;
      const fs::path dir = study::runDirectory(opt.out, w.run);
      const sim::RunSummary summary = sim::readRunSummary(dir / "summary.json");
      if (isSearch(u.result.event, s)) {
        const std::string failure = trialFailure(summary, u.result.event);
        Trial t{.value = w.value, .passed = failure.empty(), .failure = failure, .run = w.run.key};
        (t.passed ? u.lo : u.hi) = w.value;
        u.result.trials.push_back(t);
        continue;
      }
      u.done = true;
      if (summary.crashed || summary.nan || summary.diverged || sim::jointsCameApart(summary)) {
        u.result.note = "the run failed: " + trialFailure(summary, u.result.event) + " (" + w.run.key + ")";
        continue;
      }
      if (onTiltTable(u.result.event, s)) {
        readTiltTable(u.result, summary, s, w.run.key);
        continue;
      }
      // A stop, a coast or a turn that went over is not the vehicle's stop (issue 57 row 6).
      if (const auto tilt = summary.fields.find("max_tilt_deg");
          tilt != summary.fields.end() && tilt->second > kOverturnedDeg) {
        u.result.note = "pitched over: tilted " + formatNumber(tilt->second) + " deg, not a stop on its wheels (" +
                        w.run.key + ")";
        continue;
      }
      double torque = 0.0;
      u.result.measured = measureRun(v, u.result.event, s, dir, &torque);
      if (u.result.event == "drawbar") u.result.torque_coefficient = torque;
      u.result.note = w.run.key;
    }
  }
  for (const Unit& u : units) outcome.results.push_back(u.result);
  return outcome;
}

}  // namespace wtc::mobility
