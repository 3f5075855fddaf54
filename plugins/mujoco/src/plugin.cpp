// wtc::mujoco::Plugin: registration and the wheels' step between
// mj_step1 and mj_step2. Design note in include/wtc/mujoco/plugin.hpp.
#include "wtc/mujoco/plugin.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "adapter/mounted_wheel.hpp"
#include "adapter/step_clock.hpp"
#include "model_checks.hpp"
#include "src/conversions.hpp"
#include "wtc/base/error.hpp"

namespace wtc::mujoco {

struct WheelEntry {
  WheelEntry(const WheelDescription& description, EffectSet effects, ContactMode mode)
      : mounted(description, effects, mode) {}
  int body = -1;
  Eigen::Vector3d axle_local, centre_local;
  MountedWheel mounted;  // tyre model, state, this step's result
  // The body's xfrc_applied before applyForces added the wheel's wrench,
  // which clearForces puts back exactly (the user's own, to the bit).
  std::array<mjtNum, 6> users{};
  bool added = false;
};

namespace detail {

struct PluginState {
  PluginState(const mjModel& m, const Terrain& t, ContactMode c) : model(m), terrain(t), ground_memory(t), mode(c) {}

  const WheelEntry& wheel(WheelId id) const {
    if (id < 0 || static_cast<std::size_t>(id) >= wheels.size()) {
      throw std::out_of_range("wtc::mujoco::Plugin: wheel id " + std::to_string(id) + " is not registered (" +
                              std::to_string(wheels.size()) + " wheels)");
    }
    return *wheels[static_cast<std::size_t>(id)];
  }
  void requireModel(const mjModel& m, const char* where) const {
    if (&m != &model) throw InvalidInputError(std::string(where) + ": a model other than the plugin's");
  }

  const mjModel& model;
  const Terrain& terrain;
  GroundMemory ground_memory;
  ContactMode mode;
  std::vector<std::unique_ptr<WheelEntry>> wheels;
  WheelListener* listener = nullptr;
  StepClock clock;  // applyForces and clearForces
};

}  // namespace detail

namespace {

[[noreturn]] void fail(const char* where, const std::string& what) {
  throw InvalidInputError(std::string(where) + ": " + what);
}

std::string bodyName(const mjModel& m, int body) {
  const char* name = mj_id2name(&m, mjOBJ_BODY, body);
  // Appended, not "'" + std::string(name): GCC 12 warns falsely of an
  // overlapping memcpy in that operator+ (its -Wrestrict, GCC bug 105329).
  std::string quoted = name != nullptr ? "'" : "#";
  quoted += name != nullptr ? std::string(name) + "'" : std::to_string(body);
  return quoted;
}

}  // namespace

Plugin::Plugin(const mjModel& model, const Terrain& terrain, ContactMode mode) {
  static constexpr const char* kWhere = "wtc::mujoco::Plugin";
  if (mode != ContactMode::kForce) {
    fail(kWhere,
         "contact mode " + std::string(contactModeName(mode)) +
             ": wtc::mujoco serves force mode; WTC's contacts in MuJoCo's contact list (the engine-solved modes) are "
             "not built yet (issue 56)");
  }
  if (model.opt.integrator == mjINT_RK4) {
    fail(kWhere,
         "the model's integrator is RK4: mj_step1 and mj_step2, between which the wheels run once a step, integrate by "
         "Euler, and RK4's four stages would each need the tyre model; use integrator=\"Euler\" or \"implicit\"");
  }
  if (!(model.opt.timestep > 0.0)) {
    fail(kWhere, "the model's timestep " + std::to_string(model.opt.timestep) + " s is not positive");
  }
  state_ = std::make_unique<detail::PluginState>(model, terrain, mode);
}

Plugin::~Plugin() = default;

WheelId Plugin::addWheel(const Wheel& spec) {
  static constexpr const char* kWhere = "wtc::mujoco::Plugin::addWheel";
  const mjModel& m = state_->model;
  if (spec.body <= 0 || spec.body >= m.nbody) {
    fail(kWhere, "body " + std::to_string(spec.body) +
                     (spec.body == 0 ? " is the world" : " is not a body of the model") +
                     " (the model has bodies 1 to " + std::to_string(m.nbody - 1) + ")");
  }
  for (const auto& w : state_->wheels) {
    if (w->body == spec.body) fail(kWhere, "body " + bodyName(m, spec.body) + " is already a registered wheel");
  }
  validateMounting(spec.axle_local, spec.centre_local, kWhere);
  if (const std::string collision = worldCollision(m, spec.body); !collision.empty()) {
    fail(kWhere, "wheel body " + bodyName(m, spec.body) + ": " + collision +
                     " in MuJoCo, so the ground would carry the wheel twice (MuJoCo's contact and WTC's); give the "
                     "wheel's geoms contype=\"0\" conaffinity=\"0\", or bits the ground lacks");
  }
  // The body's inertia about its centre of mass in its own frame: the
  // principal moments turned from the inertial frame (body_iquat).
  const Eigen::Matrix3d turn = quatMat(m.body_iquat + 4 * spec.body);
  const Eigen::Matrix3d inertia = turn * vec3(m.body_inertia + 3 * spec.body).asDiagonal() * turn.transpose();
  const WheelDescription description = mountedDescription(spec.description, spec.inertia_source, m.body_mass[spec.body],
                                                          inertia, spec.axle_local, kWhere);
  auto w = std::make_unique<WheelEntry>(description, spec.effects, state_->mode);
  w->body = spec.body;
  w->axle_local = spec.axle_local;
  w->centre_local = spec.centre_local;
  if (state_->ground_memory.regionCount() > 0) w->mounted.state().setGroundMemory(&state_->ground_memory);
  state_->wheels.push_back(std::move(w));
  return static_cast<WheelId>(state_->wheels.size() - 1);
}

void Plugin::step(const mjModel& model, mjData& data) {
  state_->requireModel(model, "wtc::mujoco::Plugin::step");
  mj_step1(&model, &data);
  applyForces(model, data);
  mj_step2(&model, &data);
  clearForces(data);
}

void Plugin::applyForces(const mjModel& model, mjData& data) {
  state_->requireModel(model, "wtc::mujoco::Plugin::applyForces");
  const StepClock::Section timed(state_->clock);
  const double h = model.opt.timestep;
  const Eigen::Vector3d gravity = vec3(model.opt.gravity);
  for (std::size_t id = 0; id < state_->wheels.size(); ++id) {
    WheelEntry& w = *state_->wheels[id];
    const int b = w.body;
    w.mounted.setRestLoad(gravity);
    const Eigen::Matrix3d rotation = mat3(data.xmat + 9 * b);
    const Eigen::Vector3d com = vec3(data.xipos + 3 * b);
    const Eigen::Vector3d centre = vec3(data.xpos + 3 * b) + rotation * w.centre_local;
    // [omega; v] at the centre of mass, in world axes (mj_step1 computed cvel).
    mjtNum spin_velocity[6];
    mj_objectVelocity(&model, &data, mjOBJ_BODY, b, spin_velocity, 0);
    WheelMotion motion;
    motion.angular_velocity = vec3(spin_velocity);
    motion.velocity = vec3(spin_velocity + 3) + motion.angular_velocity.cross(centre - com);
    const MountedWheelStep& r = w.mounted.step(state_->terrain, {centre, rotation * w.axle_local}, motion, h);
    if (!r.skipped) {
      // xfrc_applied acts at the centre of mass: the torque about O moved there.
      const Eigen::Vector3d torque = r.torque + (centre - com).cross(r.force);
      mjtNum* applied = data.xfrc_applied + 6 * b;
      std::copy(applied, applied + 6, w.users.begin());
      w.added = true;
      for (int i = 0; i < 3; ++i) {
        applied[i] += r.force[i];
        applied[3 + i] += torque[i];
      }
    }
    w.mounted.tell(state_->listener, static_cast<WheelId>(id), h);
  }
}

void Plugin::clearForces(mjData& data) {
  const StepClock::Section timed(state_->clock);
  for (const auto& w : state_->wheels) {
    if (!w->added) continue;
    std::copy(w->users.begin(), w->users.end(), data.xfrc_applied + 6 * w->body);
    w->added = false;
  }
}

const WheelForces& Plugin::forces(WheelId wheel) const { return state_->wheel(wheel).mounted.forces(); }
const WheelState& Plugin::state(WheelId wheel) const { return state_->wheel(wheel).mounted.state(); }
const GroundMemory& Plugin::groundMemory() const { return state_->ground_memory; }
GroundMemory& Plugin::groundMemory() { return state_->ground_memory; }
int Plugin::wheelCount() const { return static_cast<int>(state_->wheels.size()); }
double Plugin::contactSeconds() const { return state_->clock.seconds(); }
ContactMode Plugin::mode() const { return state_->mode; }
void Plugin::setListener(WheelListener* listener) { state_->listener = listener; }

}  // namespace wtc::mujoco
