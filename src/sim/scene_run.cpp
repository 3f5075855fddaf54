#include "wtc/sim/scene_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "recorder.hpp"
#include "start_overlap.hpp"
#include "tilt_watch.hpp"
#include "wtc/base/constants.hpp"
#include "wtc/base/error.hpp"
#include "wtc/base/tolerances.hpp"
#include "wtc/sim/run.hpp"
#include "wtc/sim/sim_constants.hpp"
#include "wtc/sim/start_velocity.hpp"
#include "wtc/sim/step_count.hpp"
#include "wtc/tyre/ground_memory.hpp"

namespace wtc::sim {
namespace {

// The bounds on a joint's error through a scene (warned above).
// A wheel's peak slip ratio counts only while its centre moves at least
// this fast (m/s): below, s = |V_s| / max(V_t, eps) is eps's figure, not
// the tyre's.
constexpr double kSlipSpeedFloorMps = 0.1;

double tiltRad(const Eigen::Matrix3d& axes) { return std::acos(std::clamp(axes.col(2).z(), -1.0, 1.0)); }
double yawRad(const Eigen::Matrix3d& axes) { return std::atan2(axes(1, 0), axes(0, 0)); }

// The vehicle frame's axes in the world, from body `body`'s pose: a body's
// frame is its principal frame, turned from V's axes by its reference
// rotation where a URDF's tensor had products of inertia
// (wtc/vehicle/principal_inertia.hpp), R_WV = R_WB R_VB^T. The tilt and
// yaw are V's. (A body not turned gives its own axes, untouched.)
Eigen::Matrix3d vehicleAxes(const Eigen::Isometry3d& pose_WB, const vehicle::Body& body) {
  if (body.pose.linear().isIdentity(0.0)) return pose_WB.linear();
  return pose_WB.linear() * body.pose.linear().transpose();
}

std::string mmOrDeg(double v, int digits) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

}  // namespace

// (Named, not in the anonymous namespace: SceneRun::State, a member of a
// class with linkage, holds both watches, and GCC warns of that
// (-Wsubobject-linkage) once this file is not its unity batch's main file.)
namespace detail {

// The first unstable tyre-spring step of each wheel, read from its state
// after each step (WheelState::firstUnstableStep, the one channel the
// summary's count comes from too), said as it happens (RunOptions::warn)
// and kept for the summary.
class UnstableSpringWatch {
 public:
  UnstableSpringWatch(const vehicle::VehicleDescription& v, const std::function<void(const std::string&)>& warn)
      : warn_(warn), wheels_(v.wheels()) {
    for (const int w : wheels_) names_.push_back(v.bodies[w].name);
    first_.resize(names_.size());
  }
  void look(const Engine& engine, const Run& run) {
    for (std::size_t k = 0; k < wheels_.size(); ++k) {
      if (!engine.wheelState(wheels_[k]).firstUnstableStep()) continue;
      first_[k] = describe(run.wheelForces(wheels_[k]).normal_stability);
      if (warn_) warn_("wheel " + names_[k] + ": " + first_[k] + ", first at this step");
    }
  }
  /// describe() of the wheel's first unstable step ("" if none).
  const std::string& first(std::size_t k) const { return first_[k]; }

 private:
  std::function<void(const std::string&)> warn_;
  std::vector<int> wheels_;
  std::vector<std::string> names_, first_;
};

// How far the vehicle's bodies went beyond the terrain: each centre's
// horizontal distance outside the terrain's box, and its depth below the
// box's bottom (m). Past kTerrainBoundsMarginM the vehicle has left the
// ground it was set on (driven off its edge, fallen through it): whatever
// it does there is not the scene's.
class BoundsWatch {
 public:
  BoundsWatch(const Terrain& terrain, const vehicle::VehicleDescription& v) : box_(terrain.bounds()), vehicle_(v) {}

  void observe(const vehicle::VehicleState& state) {
    for (std::size_t i = 0; i < state.bodies.size(); ++i) {
      const Eigen::Vector3d p = state.bodies[i].pose.translation();
      const Eigen::Vector2d outside = (box_.min - p).head<2>().cwiseMax((p - box_.max).head<2>()).cwiseMax(0.0);
      const double beyond = outside.norm(), below = box_.min.z() - p.z();
      const bool first = worst_ <= kTerrainBoundsMarginM;
      if (beyond > worst_) {
        worst_ = beyond;
        where_ = "beyond the terrain's edge";
      }
      if (below > worst_) {
        worst_ = below;
        where_ = "below the terrain's lowest point";
      }
      if (first && worst_ > kTerrainBoundsMarginM) {
        left_ = "body " + vehicle_.bodies[i].name + "'s centre went " + std::string(where_) +
                " at t = " + mmOrDeg(state.time, 4) + " s";
      }
    }
  }
  /// The farthest a centre went beyond the box or below it (m).
  double worst() const { return worst_; }
  /// Which body first went past the margin, where and when.
  const std::string& left() const { return left_; }

 private:
  Aabb box_;
  const vehicle::VehicleDescription& vehicle_;
  double worst_ = 0.0;
  const char* where_ = "";
  std::string left_;
};

}  // namespace detail
using detail::BoundsWatch;
using detail::UnstableSpringWatch;

namespace {

// A number for a failed criterion's line: 4 significant digits.
std::string shortNumber(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

// Sets a vehicle that starts moving (vehicle.velocity) going before the run
// reads its first state, then makes the scene's controller. A vehicle at
// rest is not told, so that the engines start exactly as they always have.
std::unique_ptr<vehicle::Controller> startAndMakeController(const Scene& scene, Engine& engine) {
  if (!scene.start_velocity_V.isZero(0.0)) {
    engine.setVelocities(startVelocities(scene.vehicle, scene.placement, scene.start_velocity_V));
  }
  return scene.make_controller();
}

// The engine's ground memory starts as the scene's ruts (the same terrain's
// regions, so every node has its place).
void startOnRuts(const Scene& scene, Engine& engine) {
  if (!scene.start_ruts) return;
  GroundMemory* memory = groundMemory(engine);
  if (memory == nullptr) {
    throw InvalidInputError(scene.source + ": ground_memory_from: the engine's wheels keep no ground memory (" +
                            std::string(modeName(scene.engine)) + ")");
  }
  memory->clear();
  scene.start_ruts->forEachTouchedNode([memory](double x, double y, const SoilMemory& m) {
    if (!memory->setNode(x, y, m)) throw std::logic_error("a rut's node is not a node of the engine's terrain");
  });
}

}  // namespace

std::string describe(const FailedCriterion& f) {
  // Built with append: GCC 12 warns falsely (-Wrestrict) on chains of std::string +.
  const std::string unit = f.unit.empty() ? "" : " " + f.unit;
  std::string text = f.criterion + ":";
  if (f.measured) text.append(" ").append(shortNumber(*f.measured)).append(unit);
  if (f.limit) text.append(" (limit ").append(shortNumber(*f.limit)).append(unit).append(")");
  if (!f.detail.empty()) text.append(f.measured || f.limit ? "; " : " ").append(f.detail);
  return text;
}

// Everything runScene kept in its locals, kept between stretches of steps.
struct SceneRun::State {
  State(const Scene& scene, Engine& engine, const RunOptions& options)
      : scene(scene),
        engine(engine),
        options(options),
        controller(startAndMakeController(scene, engine)),
        run(engine, controller.get(), scene.vehicle_effects, scene.drawbar),
        spring_watch(scene.vehicle, options.warn),
        bounds(*scene.terrain, scene.vehicle) {}

  const Scene& scene;
  Engine& engine;
  RunOptions options;
  std::unique_ptr<vehicle::Controller> controller;
  Run run;
  UnstableSpringWatch spring_watch;
  std::optional<Recorder> recorder;
  std::uint64_t steps = 0, every = 1, progress_every = 1;
  Eigen::Isometry3d start{Eigen::Isometry3d::Identity()};
  BoundsWatch bounds;
  double max_tilt = 0.0, yaw_change = 0.0, last_yaw = 0.0;
  std::vector<double> effort_sum, peak_slip;
  std::vector<int> wheels;
  // Contact breaks: steps at which a wheel that touched the ground at the
  // step before touches nothing. A wheel rolling on flat ground has none; a
  // chattering contact (a rigid one bouncing on and off) has one in every
  // few steps, so their rate measures jitter.
  std::vector<char> touching;
  std::uint64_t contact_breaks = 0;
  double hitch_peak = 0.0, hitch_sum_x = 0.0;
  double wall_seconds = 0.0, wtc0 = 0.0;
  std::vector<std::string> start_warnings;  // bodies that start inside the ground (start_overlap.hpp)
  std::optional<detail::TiltWatch> tilt;    // the scene's tilt table
};

SceneRun::SceneRun(const Scene& scene, Engine& engine, const RunOptions& options)
    : s_(std::make_unique<State>(scene, engine, options)) {
  startOnRuts(scene, engine);
  State& x = *s_;
  const Run& run = x.run;
  const vehicle::VehicleDescription& v = scene.vehicle;
  const double dt = scene.engine.step_seconds;
  if (options.out_dir) x.recorder.emplace(*options.out_dir, run);
  x.steps = stepCount(scene.duration_seconds, dt);  // throws for a step count not whole
  x.every = std::max<std::uint64_t>(1, std::llround(1.0 / (scene.output.rate_hz * dt)));
  x.progress_every = std::max<std::uint64_t>(1, x.steps / 100);
  x.start = run.state().bodies.front().pose;
  x.start_warnings = detail::startOverlaps(*scene.terrain, v, run.state().bodies);
  if (scene.tilt_table) x.tilt.emplace(*scene.tilt_table, v);
  if (options.warn) {
    for (const std::string& w : x.start_warnings) options.warn(w);
  }
  x.bounds.observe(run.state());
  x.last_yaw = yawRad(vehicleAxes(x.start, v.bodies.front()));
  x.effort_sum.assign(v.bodies.size(), 0.0);
  x.peak_slip.assign(v.bodies.size(), 0.0);
  x.wheels = v.wheels();
  x.touching.assign(v.bodies.size(), 0);
  const auto t0 = std::chrono::steady_clock::now();
  x.wtc0 = engine.contactSeconds();
  if (x.recorder) {
    x.recorder->record(run);
    x.recorder->flush();  // the headers and the start on disk before the first step
  }
  if (options.observer != nullptr) options.observer->observe(run);
  x.wall_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

SceneRun::~SceneRun() = default;

const Run& SceneRun::run() const { return s_->run; }

bool SceneRun::ended() const {
  const State& x = *s_;
  return x.run.steps() >= x.steps || x.run.nonFinite() || x.run.diverged() || (x.tilt && x.tilt->done(x.run.time()));
}

std::uint64_t SceneRun::advance(std::uint64_t n) {
  State& x = *s_;
  Run& run = x.run;
  const RunOptions& options = x.options;
  const vehicle::VehicleDescription& v = x.scene.vehicle;
  const std::uint64_t steps = x.steps, first = run.steps();
  const auto t0 = std::chrono::steady_clock::now();
  while (run.steps() < steps && run.steps() - first < n) {
    if (options.stop != nullptr && options.stop->load()) break;
    if (x.tilt && x.tilt->done(run.time())) break;  // the table's answer is in
    if (x.tilt) x.tilt->before(run);
    run.step();
    if (x.tilt) x.tilt->after(run);
    x.spring_watch.look(x.engine, run);
    if (run.nonFinite() || run.diverged()) break;
    x.bounds.observe(run.state());
    const Eigen::Isometry3d& pose = run.state().bodies.front().pose;
    for (std::size_t i = 0; i < v.bodies.size(); ++i) {
      if (v.bodies[i].parent < 0) {
        x.max_tilt = std::max(x.max_tilt, tiltRad(vehicleAxes(run.state().bodies[i].pose, v.bodies[i])));
      }
    }
    // Yaw unwrapped step by step (a turn in place may pass +-pi).
    const double yaw = yawRad(vehicleAxes(pose, v.bodies.front()));
    x.yaw_change += std::remainder(yaw - x.last_yaw, 2.0 * std::numbers::pi);
    x.last_yaw = yaw;
    for (const int b : v.actuated()) x.effort_sum[b] += std::abs(run.drives()[b].last_effort);
    for (const int w : x.wheels) {
      const bool touches = run.state().wheels[w].contacts > 0;
      x.contact_breaks += x.touching[w] && !touches ? 1 : 0;
      x.touching[w] = touches ? 1 : 0;
      if (run.state().bodies[w].linear_velocity.norm() < kSlipSpeedFloorMps) continue;
      for (const ContactForce& c : run.wheelForces(w).contacts) x.peak_slip[w] = std::max(x.peak_slip[w], c.slip_ratio);
    }
    if (run.hitch()) {
      // P on the towed body in the tug's horizontal axes: x > 0 when pulling.
      x.hitch_peak = std::max(x.hitch_peak, run.hitch()->force_local.head<2>().norm());
      x.hitch_sum_x += run.hitch()->force_local.x();
    }
    if (x.recorder && run.steps() % x.every == 0) x.recorder->record(run);
    if (options.observer != nullptr) options.observer->observe(run);
    if (options.progress && run.steps() % x.progress_every == 0) {
      options.progress(static_cast<double>(run.steps()) / static_cast<double>(steps));
    }
  }
  if (x.recorder) x.recorder->flush();  // every row of the stretch on disk when it returns
  x.wall_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return run.steps() - first;
}

RunSummary SceneRun::summary() const {
  const State& x = *s_;
  const Scene& scene = x.scene;
  const Engine& engine = x.engine;
  const Run& run = x.run;
  const vehicle::VehicleDescription& v = scene.vehicle;
  const std::uint64_t steps = x.steps;
  const std::unique_ptr<vehicle::Controller>& controller = x.controller;
  const UnstableSpringWatch& spring_watch = x.spring_watch;
  const BoundsWatch& bounds = x.bounds;
  const std::vector<int>& wheels = x.wheels;
  const double max_tilt = x.max_tilt, yaw_change = x.yaw_change;
  const Eigen::Isometry3d& start = x.start;
  RunSummary summary;
  summary.scene = scene.name;
  summary.engine = scene.engine.engine;
  summary.mode = std::string(modeName(scene.engine));
  summary.dt = scene.engine.step_seconds;
  summary.parameters = scene.parameters;
  summary.warnings = scene.warnings;  // reading the scene's (a mesh's skipped triangles) first
  summary.warnings.insert(summary.warnings.end(), x.start_warnings.begin(), x.start_warnings.end());
  summary.wall_time = x.wall_seconds;
  summary.wtc_time = engine.contactSeconds() - x.wtc0;

  summary.steps = run.steps();
  summary.sim_time = run.time();
  summary.real_time_factor = summary.wall_time > 0.0 ? summary.sim_time / summary.wall_time : 0.0;
  summary.nan = run.nonFinite();
  summary.diverged = run.diverged() && !run.nonFinite();
  const bool tilt_done = x.tilt && x.tilt->done(run.time());
  summary.interrupted = run.steps() < steps && !summary.nan && !summary.diverged && !tilt_done;
  summary.max_penetration = run.maxDeflection();
  summary.max_joint_gap = run.maxJointError().distance;
  summary.max_joint_angle = run.maxJointError().angle;
  for (const int b : v.actuated()) {
    const vehicle::DriveReport& d = run.drives()[b];
    summary.drives.push_back(
        {.name = v.bodies[b].name,
         .joint = v.bodies[b].joint.type == vehicle::JointType::kPrismatic ? "prismatic" : "revolute",
         .steps = d.steps,
         .saturated_steps = d.saturated_steps,
         .peak_effort = d.peak_effort,
         .mean_effort = d.steps > 0 ? x.effort_sum[b] / static_cast<double>(d.steps) : 0.0});
    summary.saturation_steps += d.saturated_steps;
    if (d.saturated_steps > 0) {
      summary.warnings.push_back("drive " + v.bodies[b].name + " saturated in " + std::to_string(d.saturated_steps) +
                                 " of " + std::to_string(d.steps) + " steps");
    }
  }
  std::size_t wheel_index = 0;
  for (const int w : v.wheels()) {
    const std::uint64_t skipped = engine.wheelState(w).nonFiniteSteps();
    if (skipped > 0) {
      summary.warnings.push_back("wheel " + v.bodies[w].name + ": body state not finite in " + std::to_string(skipped) +
                                 " steps (no tyre force applied in those)");
    }
    const std::uint64_t unstable = engine.wheelState(w).unstableSteps();
    if (unstable > 0) {
      // The spring is the tyre's, or soft soil's (describe names which).
      summary.warnings.push_back("wheel " + v.bodies[w].name + ": spring beyond its explicit stability limit in " +
                                 std::to_string(unstable) + " steps (" + spring_watch.first(wheel_index) +
                                 " at the first; reduce dt or use constraint mode)");
    }
    const std::uint64_t sunk = engine.wheelState(w).sunkSteps();
    if (sunk > 0) {
      summary.warnings.push_back("wheel " + v.bodies[w].name + ": sank to its axle in soft soil in " +
                                 std::to_string(sunk) +
                                 " steps (the soil cannot carry its load: docs/soft-soil.md; the stresses beyond are"
                                 " those of a sinkage of one radius)");
    }
    ++wheel_index;
  }
  // What the ground's memory holds at the end (soil regions: docs/soft-soil.md).
  if (const GroundMemory* memory = groundMemory(engine)) {
    summary.fields["soil_memory_touched_nodes"] = static_cast<double>(memory->touchedNodes());
    summary.fields["soil_memory_bytes"] = static_cast<double>(memory->bytes());
  }
  // What the engine's solver said instead of printing it (ODE's LCP giving up
  // in a step: docs/ode-plugin.md).
  for (const SolverMessage& m : engine.solverMessages()) {
    summary.warnings.push_back(m.engine + ": '" + m.text + "' in " + std::to_string(m.steps) +
                               (m.steps == 1 ? " step" : " steps") + " (first at t = " + mmOrDeg(m.first_time_s, 4) +
                               " s" + (m.count != m.steps ? "; " + std::to_string(m.count) + " times" : "") + ")");
  }
  if (jointsCameApart(summary)) {
    summary.warnings.push_back("joints came apart by up to " + mmOrDeg(summary.max_joint_gap * 1e3, 3) + " mm and " +
                               mmOrDeg(summary.max_joint_angle * kDegPerRad, 3) + " deg (bound: 1 mm, 0.1 deg)");
  }
  if (summary.nan) summary.warnings.push_back("a body state went non-finite at t = " + mmOrDeg(run.time(), 4) + " s");
  if (summary.diverged) {
    summary.warnings.push_back("the run diverged at t = " + mmOrDeg(run.time(), 4) + " s (a body beyond " +
                               formatNumber(kDivergedSpeedMps) + " m/s, " + formatNumber(kDivergedAngularSpeedRadps) +
                               " rad/s or " + formatNumber(kDivergedDistanceM) + " m; stopped there)");
  }

  const vehicle::BodyKinematics& end = run.state().bodies.front();
  const double distance = (end.pose.translation() - start.translation()).head<2>().norm();
  summary.fields["distance_m"] = distance;
  if (scene.success.min_advance) {
    // Along the vehicle's x axis at the start, horizontal (a scene that asks only: the summaries of
    // the others keep their fields).
    const Eigen::Vector3d x_W = vehicleAxes(start, v.bodies.front()).col(0);
    const Eigen::Vector2d heading =
        x_W.head<2>().norm() > 0.0 ? Eigen::Vector2d(x_W.head<2>().normalized()) : Eigen::Vector2d::Zero();
    summary.fields["advance_m"] = heading.dot((end.pose.translation() - start.translation()).head<2>());
  }
  summary.fields["final_speed_mps"] = end.linear_velocity.head<2>().norm();
  summary.fields["yaw_change_deg"] = yaw_change * kDegPerRad;
  summary.fields["max_tilt_deg"] = max_tilt * kDegPerRad;
  if (x.tilt) x.tilt->summarize(run.time(), summary.fields);
  summary.fields["contact_breaks_per_s"] =
      summary.sim_time > 0.0 ? static_cast<double>(x.contact_breaks) / summary.sim_time : 0.0;
  for (const int w : wheels) summary.wheel_peak_slip[v.bodies[w].name] = x.peak_slip[w];
  if (v.hitch && run.steps() > 0) {
    summary.fields["hitch_force_peak_N"] = x.hitch_peak;
    summary.fields["hitch_force_mean_x_N"] = x.hitch_sum_x / static_cast<double>(run.steps());
  }
  const bool controller_failed = controller && controller->failed();
  if (controller) {
    // A controller written by the user (Python) may give a summary that is
    // not numbers: said as a warning, the run's figures kept.
    try {
      controller->summarize(summary.fields);
    } catch (const InvalidInputError& e) {
      summary.warnings.push_back(std::string("controller: ") + e.what());
    }
  }
  if (controller_failed) summary.warnings.push_back("controller: " + controller->failure());
  const SuccessCriteria& c = scene.success;
  double lowest_wheel = std::numeric_limits<double>::infinity();
  for (const int w : v.wheels()) lowest_wheel = std::min(lowest_wheel, run.state().bodies[w].pose.translation().z());
  if (!v.wheels().empty()) summary.fields["lowest_wheel_height_m"] = lowest_wheel;

  // Why the run is not a success, if it is not: what ended it early, then
  // what it did at any time (tilt, controller, energy, bounds), then, for a
  // run that reached its end, the criteria judged there.
  std::vector<FailedCriterion>& failed = summary.failed_criteria;
  const auto fail = [&failed](std::string criterion, std::optional<double> limit, std::optional<double> measured,
                              std::string unit, std::string detail) {
    failed.push_back({std::move(criterion), limit, measured, std::move(unit), std::move(detail)});
  };
  const std::string at = "at t = " + mmOrDeg(run.time(), 4) + " s";
  if (summary.nan) fail("nan", {}, {}, "", "a body state went non-finite " + at);
  if (summary.diverged) {
    fail("diverged", {}, {}, "",
         "a body went beyond " + formatNumber(kDivergedSpeedMps) + " m/s, " + formatNumber(kDivergedAngularSpeedRadps) +
             " rad/s or " + formatNumber(kDivergedDistanceM) + " m " + at);
  }
  if (summary.interrupted) fail("interrupted", scene.duration_seconds, summary.sim_time, "s", "stopped " + at);
  if (max_tilt * kDegPerRad > c.max_tilt_deg) fail("max_tilt_deg", c.max_tilt_deg, max_tilt * kDegPerRad, "deg", "");
  if (controller_failed) fail("controller", {}, {}, "", controller->failure());
  const EnergyBalance& energy = run.energyBalance();
  const double energy_limit = tolerance::kEnergyGrowthHeightM * v.totalMass() * kGravityMps2;
  if (energy.maxGrowth() > energy_limit) {
    fail("energy", energy_limit, energy.maxGrowth(), "J",
         "the vehicle's energy grew beyond its start plus the drives' work, the most at t = " +
             mmOrDeg(energy.maxGrowthTime(), 4) + " s");
  }
  if (bounds.worst() > kTerrainBoundsMarginM) fail("bounds", kTerrainBoundsMarginM, bounds.worst(), "m", bounds.left());
  // Judged at the end, of a run that reached it.
  if (!summary.nan && !summary.diverged && !summary.interrupted) {
    if (c.min_distance && !(distance >= *c.min_distance)) fail("min_distance", *c.min_distance, distance, "m", "");
    if (c.max_distance && !(distance <= *c.max_distance)) fail("max_distance", *c.max_distance, distance, "m", "");
    const double final_speed = summary.fields.at("final_speed_mps");
    if (c.max_final_speed && !(final_speed <= *c.max_final_speed)) {
      fail("max_final_speed", *c.max_final_speed, final_speed, "m/s", "still moving at the end");
    }
    if (c.min_advance && !(summary.fields.at("advance_m") >= *c.min_advance)) {
      fail("min_advance", *c.min_advance, summary.fields.at("advance_m"), "m", "forward, along the start heading");
    }
    if (c.min_wheel_height && !(lowest_wheel >= *c.min_wheel_height)) {
      fail("min_wheel_height", *c.min_wheel_height, lowest_wheel, "m", "the lowest wheel centre at the end");
    }
    const double turned = std::abs(summary.fields.at("yaw_change_deg"));
    if (c.min_turn_deg && !(turned >= *c.min_turn_deg)) {
      fail("min_turn_deg", *c.min_turn_deg, turned, "deg", "about the vertical, either way");
    }
  }
  summary.success = failed.empty();
  return summary;
}

RunSummary runScene(const Scene& scene, Engine& engine, const RunOptions& options) {
  SceneRun run(scene, engine, options);
  run.advance(std::numeric_limits<std::uint64_t>::max());
  return run.summary();
}

}  // namespace wtc::sim
