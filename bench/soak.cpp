// wtc_soak: every shipped scene for a long simulated time (10 minutes by
// default), checking what a long run must keep (issue 16, item 5):
//   - no non-finite state;
//   - energy: the vehicle's mechanical energy E (kinetic, gravity, the
//     hitch's spring, the tyres' springs 1/2 c Z^2) never exceeds its start
//     plus the work the drives put in, W = sum effort x joint rate x h
//     (midpoint rule); friction, damping and rolling resistance only take
//     energy out. Allowed excess: kEnergySlackFraction of the work the drives
//     moved either way, plus kEnergySlackJ;
//   - memory: the resident set after the first simulated minute stays
//     within kMemoryGrowthBytes.
//
//   - what the engine's solver said (ODE's LCP giving up: Engine::
//     solverMessages), reported per scene; not a failure of the soak.
//
//   build/bench/wtc_soak [--minutes M] [--engine bullet|ode|ode_quick] [--mode force|constraint] [scene.yaml ...]
//
// Without scenes: every scenes/*.yaml. Exit status 1 if any check fails.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "wtc/base/constants.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/run.hpp"
#include "wtc/sim/scene_file.hpp"

namespace {

namespace fs = std::filesystem;

constexpr double kEnergySlackFraction = 0.01;  // of the drives' gross work: the quadrature of W and the integrators'
constexpr double kEnergySlackJ = 5.0;          // an absolute floor for runs where the drives barely work
constexpr long kMemoryGrowthBytes = 4 << 20;   // 4 MiB: what a leak of one allocation per step passes in a minute

long residentBytes() {
  long pages = 0, resident = 0;
  std::ifstream("/proc/self/statm") >> pages >> resident;
  return resident * sysconf(_SC_PAGESIZE);
}

double energy(const wtc::sim::Run& run) {
  const wtc::vehicle::VehicleDescription& v = run.engine().vehicle();
  double e = 0.0;
  for (std::size_t i = 0; i < v.bodies.size(); ++i) {
    const wtc::vehicle::Body& b = v.bodies[i];
    const wtc::vehicle::BodyKinematics& k = run.state().bodies[i];
    const Eigen::Matrix3d r = k.pose.linear();
    const Eigen::Vector3d w_body = r.transpose() * k.angular_velocity;
    e += 0.5 * b.mass * k.linear_velocity.squaredNorm() + 0.5 * w_body.dot(b.inertia.cwiseProduct(w_body)) +
         b.mass * wtc::kGravityMps2 * k.pose.translation().z();
    if (b.wheel) {
      for (const wtc::ContactForce& c : run.engine().wheelForces(static_cast<int>(i)).contacts) {
        e += 0.5 * b.wheel->tyre.radial_stiffness * c.contact.deflection * c.contact.deflection;
      }
    }
  }
  if (run.hitch() && v.hitch)
    e += 0.5 * run.hitch()->deflection.dot(v.hitch->stiffness.cwiseProduct(run.hitch()->deflection));
  return e;
}

struct Result {
  std::string scene;
  double sim_time = 0.0, wall = 0.0, work = 0.0, gross_work = 0.0, max_excess = 0.0;
  long rss_minute = 0, rss_end = 0;
  bool nan = false, ok = true;
  std::string solver;  // what the engine's solver said: "none", or each message with its steps and first time
};

std::string solverSaid(const wtc::sim::Engine& engine) {
  std::string said;
  for (const wtc::sim::SolverMessage& m : engine.solverMessages()) {
    char line[256];
    std::snprintf(line, sizeof line, "%s%s '%s' in %llu steps (first at t = %.4f s)", said.empty() ? "" : "; ",
                  m.engine.c_str(), m.text.c_str(), static_cast<unsigned long long>(m.steps), m.first_time_s);
    said += line;
  }
  return said.empty() ? "none" : said;
}

Result soak(const fs::path& file, const std::string& engine, const std::string& mode, double minutes) {
  std::vector<wtc::sim::Override> overrides = {{"duration", std::to_string(60.0 * minutes)}};
  if (!engine.empty()) overrides.push_back({"engine", engine});
  if (!mode.empty()) overrides.push_back({"mode", mode});
  const wtc::sim::Scene scene = wtc::sim::loadScene(file, overrides);
  const auto e = wtc::sim::makeEngine(scene.engine, *scene.terrain, scene.vehicle, scene.placement);
  const auto controller = scene.make_controller();
  wtc::sim::Run run(*e, controller.get(), scene.vehicle_effects);
  Result r;
  r.scene = scene.name + " (" + scene.engine.engine + ")";
  const double h = scene.engine.step_seconds;
  const std::vector<int> drives = scene.vehicle.actuated();
  std::vector<double> rate_before(scene.vehicle.bodies.size());
  double e0 = 0.0;
  bool started = false;
  const auto t0 = std::chrono::steady_clock::now();
  while (run.time() < scene.duration_seconds) {
    for (const int b : drives) rate_before[b] = run.state().joint_rate[b];
    run.step();
    if (!started) {  // the energy from the first step on (the hitch force exists from then)
      e0 = energy(run);
      started = true;
      continue;
    }
    for (const int b : drives) {
      const double p = run.drives()[b].last_effort * 0.5 * (rate_before[b] + run.state().joint_rate[b]);
      r.work += p * h;
      r.gross_work += std::abs(p) * h;
    }
    if (run.nonFinite()) {
      r.nan = true;
      break;
    }
    if (run.steps() % 250 == 0) {
      r.max_excess = std::max(r.max_excess, energy(run) - e0 - r.work);
      if (r.rss_minute == 0 && run.time() >= 60.0) r.rss_minute = residentBytes();
    }
  }
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.sim_time = run.time();
  r.rss_end = residentBytes();
  r.solver = solverSaid(*e);
  const bool memory_flat = r.rss_minute == 0 || r.rss_end - r.rss_minute <= kMemoryGrowthBytes;
  r.ok = !r.nan && r.max_excess <= kEnergySlackFraction * r.gross_work + kEnergySlackJ && memory_flat;
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  double minutes = 10.0;
  std::string engine, mode;
  std::vector<fs::path> scenes;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--minutes" && i + 1 < argc) {
      minutes = std::stod(argv[++i]);
    } else if (a == "--engine" && i + 1 < argc) {
      engine = argv[++i];
    } else if (a == "--mode" && i + 1 < argc) {
      mode = argv[++i];
    } else {
      scenes.emplace_back(a);
    }
  }
  if (scenes.empty()) {
    for (const auto& entry : fs::directory_iterator(fs::path(WTC_SOURCE_DIR) / "scenes")) {
      if (entry.path().extension() == ".yaml") scenes.push_back(entry.path());
    }
    std::sort(scenes.begin(), scenes.end());
  }
  std::printf(
      "| scene | simulated (s) | wall (s) | NaN | drive work (J) | largest energy excess (J) | allowed (J) | "
      "RSS after 1 min / end (MB) | ok | solver messages |\n|---|---:|---:|---|---:|---:|---:|---:|---|---|\n");
  bool all = true;
  for (const fs::path& file : scenes) {
    try {
      const Result r = soak(file, engine, mode, minutes);
      std::printf("| %s | %.0f | %.1f | %s | %.0f | %.2f | %.1f | %.1f / %.1f | %s | %s |\n", r.scene.c_str(),
                  r.sim_time, r.wall, r.nan ? "yes" : "no", r.work, r.max_excess,
                  kEnergySlackFraction * r.gross_work + kEnergySlackJ, r.rss_minute / 1e6, r.rss_end / 1e6,
                  r.ok ? "yes" : "NO", r.solver.c_str());
      std::fflush(stdout);
      all = all && r.ok;
    } catch (const std::exception& e) {
      std::printf("| %s | error: %s |\n", file.c_str(), e.what());
      all = false;
    }
  }
  return all ? 0 : 1;
}
