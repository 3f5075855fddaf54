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
#include "added_wrench.hpp"
#include "euler_stages.hpp"
#include "model_checks.hpp"
#include "soft_contact.hpp"
#include "soil_bodies.hpp"
#include "src/conversions.hpp"
#include "wtc/base/error.hpp"

namespace wtc::mujoco {

struct WheelEntry {
  WheelEntry(const WheelDescription& description, EffectSet effects, ContactMode mode)
      : mounted(description, effects, mode) {}
  int body = -1;
  int geom = -1;  // the body's first geom: geom2 of its MuJoCo contacts (engine-solved modes)
  Eigen::Vector3d axle_local, centre_local;
  MountedWheel mounted;  // tyre model, state, this step's result
  // Engine-solved modes: the mjData::contact index of each of this step's
  // contacts (mounted.last().contacts, in order; -1: not handed over), and
  // the forces MuJoCo's solver applied at them.
  std::vector<int> contact_ids;
  std::vector<Eigen::Vector3d> solved;
  // The wheel's wrench in xfrc_applied this step, taken back by clearForces.
  AddedWrench wrench;
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

  void runWheels(const mjModel& m, mjData& d, bool contacts);

  const mjModel& model;
  const Terrain& terrain;
  GroundMemory ground_memory;
  ContactMode mode;
  std::vector<std::unique_ptr<WheelEntry>> wheels;
  SoilBodies soil_bodies;
  WheelListener* listener = nullptr;
  StepClock clock;       // the wheels' part of a step
  int ground_geom = -1;  // geom1 of WTC's MuJoCo contacts: a geom of the world body or welded to it
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
  if (mode == ContactMode::kImplicit) {
    fail(kWhere,
         "contact mode implicit: MuJoCo 2.2.2's friction rows take no target velocity and their compliance is the "
         "normal's divided by impratio, so the tread's compliant rows cannot be handed to it; use constraint mode (the "
         "tyre's spring solved by MuJoCo, docs/mujoco-plugin.md) or force mode");
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
  if (!engineSolvesContacts(mode)) return;
  if (model.opt.integrator != mjINT_EULER) {
    fail(kWhere,
         "constraint mode with the model's implicit integrator: WTC's contacts go in between mj_collision and "
         "mj_makeConstraint of a step run stage by stage, and MuJoCo 2.2.2 does not export mj_implicit; use "
         "integrator=\"Euler\", or force mode");
  }
  if ((model.opt.disableflags & mjDSBL_CONTACT) != 0) {
    fail(kWhere,
         "constraint mode on a model whose contacts are disabled (<flag contact=\"disable\"/>): MuJoCo would "
         "drop WTC's contacts too");
  }
  for (int g = 0; g < model.ngeom && state_->ground_geom < 0; ++g) {
    if (model.body_weldid[model.geom_bodyid[g]] == 0) state_->ground_geom = g;  // the world's, or welded to it
  }
  if (state_->ground_geom < 0) {
    fail(kWhere,
         "constraint mode needs a geom of the world body (or of a body welded to it), which WTC's contacts name as "
         "their geom1 (any: "
         "<geom type=\"plane\" size=\"1 1 1\" contype=\"0\" conaffinity=\"0\"/> in <worldbody>)");
  }
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
  if (state_->soil_bodies.has(spec.body)) fail(kWhere, "body " + bodyName(m, spec.body) + " is a soil body");
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
  for (int g = 0; g < m.ngeom && w->geom < 0; ++g) {
    if (m.geom_bodyid[g] == spec.body) w->geom = g;
  }
  if (engineSolvesContacts(state_->mode) && w->geom < 0) {
    fail(kWhere, "wheel body " + bodyName(m, spec.body) +
                     " has no geom, which WTC's MuJoCo contacts name as their geom2 in constraint mode (give it one, "
                     "with contype=\"0\" conaffinity=\"0\")");
  }
  w->axle_local = spec.axle_local;
  w->centre_local = spec.centre_local;
  if (state_->ground_memory.regionCount() > 0) w->mounted.state().setGroundMemory(&state_->ground_memory);
  state_->wheels.push_back(std::move(w));
  return static_cast<WheelId>(state_->wheels.size() - 1);
}

void Plugin::step(const mjModel& model, mjData& data) {
  state_->requireModel(model, "wtc::mujoco::Plugin::step");
  if (engineSolvesContacts(state_->mode)) {
    eulerStep(model, data,
              {.after_collision =
                   [&] {
                     dropRigidSoilContacts(model, data);
                     addContacts(model, data);
                   },
               .after_solve = [&] { collectSolvedForces(model, data); }});
  } else if (state_->soil_bodies.count() > 0) {
    // The soil bodies' rigid contacts go before mj_makeConstraint.
    eulerStep(model, data,
              {.after_collision = [&] { dropRigidSoilContacts(model, data); },
               .after_velocity = [&] { applyForces(model, data); }});
  } else {
    mj_step1(&model, &data);
    applyForces(model, data);
    mj_step2(&model, &data);
  }
  clearForces(data);
}

void Plugin::applyForces(const mjModel& model, mjData& data) {
  state_->requireModel(model, "wtc::mujoco::Plugin::applyForces");
  if (engineSolvesContacts(state_->mode)) {
    fail("wtc::mujoco::Plugin::applyForces",
         "in constraint mode the wheels go in with addContacts, after mj_collision");
  }
  state_->runWheels(model, data, false);
}

void Plugin::addContacts(const mjModel& model, mjData& data) {
  state_->requireModel(model, "wtc::mujoco::Plugin::addContacts");
  if (!engineSolvesContacts(state_->mode)) {
    fail("wtc::mujoco::Plugin::addContacts", "in force mode the wheels go in with applyForces, after mj_step1");
  }
  if (state_->wheels.empty() && state_->soil_bodies.count() == 0) return;  // mj_step's stages untouched
  // The wheels' velocities of this step: mj_fwdVelocity, which computes
  // cvel, comes after mj_makeConstraint; mj_comVel is a pure function of
  // the kinematics and qvel, so computing it early changes nothing.
  mj_comVel(&model, &data);
  state_->runWheels(model, data, true);
}

void Plugin::collectSolvedForces(const mjModel& model, const mjData& data) {
  state_->requireModel(model, "wtc::mujoco::Plugin::collectSolvedForces");
  const StepClock::Section timed(state_->clock);
  for (const auto& w : state_->wheels) {
    if (w->mounted.last().skipped) continue;
    w->solved.assign(w->contact_ids.size(), Eigen::Vector3d::Zero());
    for (std::size_t k = 0; k < w->contact_ids.size(); ++k) {
      const int id = w->contact_ids[k];
      if (id < 0 || id >= data.ncon) continue;
      const mjContact& c = data.contact[id];
      if (c.efc_address < 0 && c.exclude == 0) {
        fail("wtc::mujoco::Plugin::step",
             "the model's njmax (" + std::to_string(model.njmax) +
                 " constraint rows) is full: WTC's contacts did not all become rows; raise <size njmax=\"...\"/>");
      }
      // mj_contactForce: in the contact frame, on geom2 (the wheel).
      mjtNum local[6];
      mj_contactForce(&model, &data, id, local);
      w->solved[k] = mat3(c.frame).transpose() * vec3(local);
    }
    w->mounted.setSolvedForces(w->solved);
  }
}

namespace detail {

void PluginState::runWheels(const mjModel& m, mjData& d, bool contacts) {
  const StepClock::Section timed(clock);
  const double h = m.opt.timestep;
  const Eigen::Vector3d gravity = vec3(m.opt.gravity);
  ContactSetting setting;
  setting.step_seconds = h;
  setting.pyramidal = m.opt.cone == mjCONE_PYRAMIDAL;
  setting.impratio = m.opt.impratio;
  setting.ground_geom = ground_geom;
  SoftContact soft;
  for (std::size_t id = 0; id < wheels.size(); ++id) {
    WheelEntry& w = *wheels[id];
    const int b = w.body;
    w.mounted.setRestLoad(gravity);
    const Eigen::Matrix3d rotation = mat3(d.xmat + 9 * b);
    const Eigen::Vector3d centre = vec3(d.xpos + 3 * b) + rotation * w.centre_local;
    const PointVelocity v = velocityAt(m, d, b, centre);
    const WheelMotion motion{.velocity = v.linear, .angular_velocity = v.angular};
    const MountedWheelStep& r = w.mounted.step(terrain, {centre, rotation * w.axle_local}, motion, h);
    w.contact_ids.clear();
    // Force mode: the tyre's wrench; constraint mode: what stays explicit
    // (rolling resistance, the soil's shear).
    if (!r.skipped) w.wrench.add(d, b, r.force, r.torque, centre);
    if (contacts && !r.skipped) {
      setting.inverse_weight = m.body_invweight0[2 * m.geom_bodyid[ground_geom]] + m.body_invweight0[2 * b];
      setting.wheel_geom = w.geom;
      for (const SolverContact& c : r.contacts) {
        int index = -1;
        if (toSoftContact(c, setting, soft)) {
          if (mj_addContact(&m, &d, &soft.contact) != 0) {
            fail("wtc::mujoco::Plugin::step", "the model's nconmax (" + std::to_string(m.nconmax) +
                                                  " contacts) is full: WTC's contacts did not fit; raise <size "
                                                  "nconmax=\"...\"/>");
          }
          index = d.ncon - 1;
        }
        w.contact_ids.push_back(index);
      }
    }
    w.mounted.tell(listener, static_cast<WheelId>(id), h);
  }
  soil_bodies.step(m, d, terrain, ground_memory.regionCount() > 0 ? &ground_memory : nullptr, h);
}

}  // namespace detail

void Plugin::clearForces(mjData& data) {
  const StepClock::Section timed(state_->clock);
  state_->soil_bodies.restore(data);
  for (const auto& w : state_->wheels) w->wrench.restore(data);
}

SoilBodyId Plugin::addSoilBody(const SoilBody& body) {
  const mjModel& m = state_->model;
  if (m.opt.integrator != mjINT_EULER) {
    fail("wtc::mujoco::Plugin::addSoilBody",
         "a soil body's rigid contacts are dropped between mj_collision and mj_makeConstraint of a step run stage by "
         "stage, which MuJoCo 2.2.2 serves for the Euler integrator only; use integrator=\"Euler\"");
  }
  const bool is_wheel =
      std::any_of(state_->wheels.begin(), state_->wheels.end(), [&](const auto& w) { return w->body == body.body; });
  return state_->soil_bodies.add(m, body, is_wheel);
}
const BodySoilForces& Plugin::soilForces(SoilBodyId body) const { return state_->soil_bodies.forces(body); }
int Plugin::soilBodyCount() const { return state_->soil_bodies.count(); }
void Plugin::dropRigidSoilContacts(const mjModel& model, mjData& data) const {
  state_->requireModel(model, "wtc::mujoco::Plugin::dropRigidSoilContacts");
  const StepClock::Section timed(state_->clock);
  state_->soil_bodies.dropRigidContacts(model, data, state_->terrain);
}

const WheelForces& Plugin::forces(WheelId wheel) const { return state_->wheel(wheel).mounted.forces(); }
const WheelForces& Plugin::applied(WheelId wheel) const { return state_->wheel(wheel).mounted.applied(); }
const WheelState& Plugin::state(WheelId wheel) const { return state_->wheel(wheel).mounted.state(); }
const GroundMemory& Plugin::groundMemory() const { return state_->ground_memory; }
GroundMemory& Plugin::groundMemory() { return state_->ground_memory; }
int Plugin::wheelCount() const { return static_cast<int>(state_->wheels.size()); }
double Plugin::contactSeconds() const { return state_->clock.seconds(); }
ContactMode Plugin::mode() const { return state_->mode; }
void Plugin::setListener(WheelListener* listener) { state_->listener = listener; }

}  // namespace wtc::mujoco
