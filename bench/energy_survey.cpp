// wtc_energy_survey: how near the legitimate runs come to the two checks
// every run passes (wtc::sim::runScene, docs/vehicles-and-scenes.md,
// "Energy and bounds"): each shipped scene at its full duration, in Bullet,
// ODE and ODE's quickstep, force and constraint mode; per run the largest
// unexplained energy growth after the first step (sim::EnergyBalance, J;
// below zero when the run only ever lost energy), the run's limit, the
// drives' work, and how far any body's centre went beyond the terrain's
// bounding box or below it (m).
//
//   build/bench/wtc_energy_survey [scene.yaml ...]
//   MODE=engine_cylinder build/bench/wtc_energy_survey      (one mode: the engines' own wheels)
//
// Without scenes: every scenes/*.yaml. Exit status 1 if a run passes a limit.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "wtc/base/constants.hpp"
#include "wtc/sim/sim_constants.hpp"
#include "wtc/sim/scene_file.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/run.hpp"
#include "wtc/sim/step_count.hpp"
#include "wtc/base/tolerances.hpp"

namespace {

namespace fs = std::filesystem;

struct Survey {
  double max_growth = -std::numeric_limits<double>::infinity();  // after the first step (J)
  double limit = 0.0, work = 0.0;                                // (J)
  double beyond = 0.0;                                           // beyond the box or below it (m)
  bool stopped = false;                                          // non-finite or diverged
};

Survey survey(const wtc::sim::Scene& scene) {
  const auto engine = wtc::sim::makeEngine(scene.engine, *scene.terrain, scene.vehicle, scene.placement);
  const auto controller = scene.make_controller();
  wtc::sim::Run run(*engine, controller.get(), scene.vehicle_effects);
  const std::uint64_t steps = wtc::sim::stepCount(scene.duration_seconds, scene.engine.step_seconds);
  const wtc::Aabb box = scene.terrain->bounds();
  Survey s;
  s.limit = wtc::tolerance::kEnergyGrowthHeightM * scene.vehicle.totalMass() * wtc::kGravityMps2;
  while (run.steps() < steps) {
    run.step();
    if (run.nonFinite() || run.diverged()) {
      s.stopped = true;
      break;
    }
    if (run.steps() > 1) s.max_growth = std::max(s.max_growth, run.energyBalance().growth());
    for (const wtc::vehicle::BodyKinematics& k : run.state().bodies) {
      const Eigen::Vector3d p = k.pose.translation();
      const Eigen::Vector2d outside = (box.min - p).head<2>().cwiseMax((p - box.max).head<2>()).cwiseMax(0.0);
      s.beyond = std::max({s.beyond, outside.norm(), box.min.z() - p.z()});
    }
  }
  s.work = run.energyBalance().driveWork();
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<fs::path> scenes(argv + 1, argv + argc);
  if (scenes.empty()) {
    for (const auto& entry : fs::directory_iterator(fs::path(WTC_SOURCE_DIR) / "scenes")) {
      if (entry.path().extension() == ".yaml") scenes.push_back(entry.path());
    }
    std::sort(scenes.begin(), scenes.end());
  }
  const char* only_mode = std::getenv("MODE");
  std::vector<std::string> modes = {"force", "constraint"};
  if (only_mode != nullptr) modes = {only_mode};
  std::printf(
      "| scene | engine | mode | largest growth after step 1 (J) | limit (J) | drive work (J) | beyond the terrain (m) "
      "| ok |\n|---|---|---|---:|---:|---:|---:|---|\n");
  bool all = true;
  for (const fs::path& file : scenes) {
    for (const char* engine : {"bullet", "ode", "ode_quick"}) {
      for (const std::string& mode : modes) {
        if (std::string(engine) == "ode_quick" && mode == "constraint") continue;  // not an ODE quickstep mode
        try {
          const wtc::sim::Scene scene =
              wtc::sim::loadScene(file, std::vector<wtc::sim::Override>{{"engine", engine}, {"mode", mode}});
          const Survey s = survey(scene);
          const bool ok = !s.stopped && s.max_growth <= s.limit && s.beyond <= wtc::sim::kTerrainBoundsMarginM;
          std::printf("| %s | %s | %s | %.3g | %.3g | %.4g | %.3g | %s |\n", scene.name.c_str(), engine, mode.c_str(),
                      s.max_growth, s.limit, s.work, s.beyond, ok ? "yes" : "NO");
          std::fflush(stdout);
          all = all && ok;
        } catch (const std::exception& e) {
          std::printf("| %s | %s | %s | error: %s |\n", file.c_str(), engine, mode.c_str(), e.what());
          all = false;
        }
      }
    }
  }
  return all ? 0 : 1;
}
