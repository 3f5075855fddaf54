// The MuJoCo sim engine (sim_engine.hpp): the model, the step and its hooks,
// the drives, and the wheel strategy chosen once, here.
#include "sim_engine.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <tuple>
#include <vector>

#include "field_contacts.hpp"
#include "mjcf_model.hpp"
#include "mujoco_constants.hpp"
#include "mujoco_wheels.hpp"
#include "sim/body_soil_shapes.hpp"
#include "sim/engine_base.hpp"
#include "src/conversions.hpp"
#include "src/euler_stages.hpp"
#include "wtc/base/constants.hpp"
#include "wtc/base/error.hpp"
#include "wtc/mujoco/plugin.hpp"
#include "wtc/vehicle/drive.hpp"

namespace wtc::mujoco {
namespace {

using vehicle::Body;
using vehicle::JointType;

struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};

class SimEngine final : public sim::EngineBase {
 public:
  SimEngine(const sim::EngineSettings& settings, const Terrain& terrain, const vehicle::VehicleDescription& v,
            const Eigen::Isometry3d& placement)
      : sim::EngineBase("wtc::mujoco sim engine", settings, v),
        built_(buildVehicleModel(settings, terrain, v, placement)),
        m_(*built_.model),
        d_(mj_makeData(&m_)),
        drives_(v.bodies.size()) {
    for (std::size_t i = 0; i < v.bodies.size(); ++i) buildDrive(static_cast<int>(i));
    plugin_ = std::make_unique<Plugin>(m_, terrain, settings.mode);
    std::vector<int> wheel_bodies, treads;
    for (const int body : v.wheels()) {
      wheel_bodies.push_back(built_.body[body]);
      treads.push_back(built_.wheel_geom[body]);
    }
    field_contacts_ = std::make_unique<FieldContacts>(m_, terrain, treads);  // the wheels' geoms are not held
    if (settings.native_wheels) {
      wheels_ = std::make_unique<NativeWheels>(*this, *plugin_, std::move(treads), *settings.native_wheels);
    } else {
      wheels_ = std::make_unique<WtcWheels>(*plugin_, v, wheel_bodies, settings.tyre_effects);
    }
    useWheels(*wheels_);
    for (sim::SoilBodyShape& soil : sim::soilBodyShapes(settings, terrain, v)) {
      plugin_->addSoilBody({.body = built_.body[soil.body], .hulls = std::move(soil.hulls)});
    }
    external_.assign(6 * static_cast<std::size_t>(m_.nbody), 0.0);
    mj_forward(&m_, d_.get());  // the start's kinematics, for body() before the first step
  }

  void setMotorTarget(int body, const vehicle::MotorTarget& target) override {
    Drive& drive = drives_.at(body);
    if (drive.dof < 0) return;
    drive.target = target;
    if (!drive.closed_form) {
      // The friction row exists only while the drive is on (frictionloss > 0).
      m_.dof_frictionloss[drive.dof] = target.active ? std::min(target.max_effort, kUncappedDriveEffort) : 0.0;
    }
  }

  void addForce(int body, const Eigen::Vector3d& force, const Eigen::Vector3d& point) override {
    const int b = built_.body.at(body);
    const Eigen::Vector3d torque = (point - vec3(d_->xipos + 3 * b)).cross(force);
    for (int i = 0; i < 3; ++i) {
      external_[6 * b + i] += force[i];
      external_[6 * b + 3 + i] += torque[i];
    }
  }

  // The free joints' and each joint's rates from the bodies' velocities
  // (consistent with the joints: startVelocities').
  void setVelocities(std::span<const sim::BodyVelocity> velocities) override {
    requireOnePerBody(velocities.size());
    for (std::size_t i = 0; i < velocities.size(); ++i) {
      const Body& body = vehicle().bodies[i];
      const int b = built_.body[i], dof = built_.dof[i];
      if (dof < 0) continue;
      const Eigen::Matrix3d r = mat3(d_->xmat + 9 * b);
      const sim::BodyVelocity& v = velocities[i];
      if (body.parent < 0) {  // free joint: linear (world), angular (local)
        for (int k = 0; k < 3; ++k) d_->qvel[dof + k] = v.linear[k];
        const Eigen::Vector3d w = r.transpose() * v.angular;
        for (int k = 0; k < 3; ++k) d_->qvel[dof + 3 + k] = w[k];
        continue;
      }
      const sim::BodyVelocity& p = velocities[body.parent];
      const int joint = m_.dof_jntid[dof];
      const Eigen::Vector3d axis = vec3(d_->xaxis + 3 * joint);
      const Eigen::Vector3d relative_spin = v.angular - p.angular;
      switch (body.joint.type) {
        case JointType::kRevolute:
          d_->qvel[dof] = relative_spin.dot(axis);
          break;
        case JointType::kPrismatic: {
          const Eigen::Vector3d x = vec3(d_->xpos + 3 * b), xp = vec3(d_->xpos + 3 * built_.body[body.parent]);
          d_->qvel[dof] = (v.linear - p.linear - p.angular.cross(x - xp)).dot(axis);
          break;
        }
        case JointType::kBall: {
          const Eigen::Vector3d w = r.transpose() * relative_spin;
          for (int k = 0; k < 3; ++k) d_->qvel[dof + k] = w[k];
          break;
        }
        case JointType::kFixed:
          break;
      }
    }
    mj_comVel(&m_, d_.get());
  }

  GroundMemory* groundMemory() const override {
    return plugin_->groundMemory().regionCount() > 0 ? &plugin_->groundMemory() : nullptr;
  }

  void setGravity(const Eigen::Vector3d& g_W) override {
    for (int i = 0; i < 3; ++i) m_.opt.gravity[i] = g_W[i];
  }

  void step() override {
    mjData& d = *d_;
    std::copy(external_.begin(), external_.end(), d.xfrc_applied);
    std::fill(d.qfrc_applied, d.qfrc_applied + m_.nv, 0.0);
    // The plugin's part (its wheels, none with the engine's own, and its
    // soil bodies) at the hooks of its mode.
    const bool solved = engineSolvesContacts(settings().mode);
    StageHooks hooks;
    hooks.after_collision = [&] {
      plugin_->dropRigidSoilContacts(m_, d);  // the soil carries the bodies on it
      field_contacts_->hold(m_, d);
      if (solved) plugin_->addContacts(m_, d);
    };
    hooks.after_velocity = [&] {
      if (!solved) plugin_->applyForces(m_, d);
      driveWheels();
      setDriveTargets();
    };
    hooks.after_solve = [&] {
      if (solved) plugin_->collectSolvedForces(m_, d);
      readDriveEfforts();
    };
    eulerStep(m_, d, hooks);
    requireRoom(d);
    plugin_->clearForces(d);
    std::fill(external_.begin(), external_.end(), 0.0);
    std::fill(d.xfrc_applied, d.xfrc_applied + 6 * m_.nbody, 0.0);
    wheels_->read(m_, d);
    // The state after the step, for body(): MuJoCo's positions and
    // velocities of bodies are those before the integration until the
    // next step's stages.
    mj_kinematics(&m_, &d);
    mj_comPos(&m_, &d);
    mj_comVel(&m_, &d);
    wheels_->stepped();
  }

  // MuJoCo drops the contacts and rows past nconmax and njmax with only a
  // warning: a body would fall through the ground unseen. The plugin
  // refuses its own contacts that do not fit; MuJoCo's own are checked here.
  void requireRoom(const mjData& d) const {
    for (const auto& [warning, what, size] : {std::tuple{mjWARN_CONTACTFULL, "contacts (nconmax", m_.nconmax},
                                              std::tuple{mjWARN_CNSTRFULL, "constraint rows (njmax", m_.njmax}}) {
      if (d.warning[warning].number > 0) {
        throw InvalidInputError("wtc::mujoco sim engine: at t = " + std::to_string(d.time) +
                                " s the model's bodies on the terrain needed more " + what + " " +
                                std::to_string(size) +
                                ") than the engine's MuJoCo model has room for "
                                "(plugins/mujoco/sim/src/mujoco_constants.hpp): MuJoCo would drop them");
      }
    }
  }

  vehicle::BodyKinematics body(int body) const override {
    const int b = built_.body.at(body);
    vehicle::BodyKinematics k;
    k.pose.translation() = vec3(d_->xpos + 3 * b);
    k.pose.linear() = mat3(d_->xmat + 9 * b);
    const PointVelocity v = velocityAt(m_, *d_, b, k.pose.translation());  // the frame is at the centre of mass
    k.angular_velocity = v.angular;
    k.linear_velocity = v.linear;
    return k;
  }

  double jointPosition(int body) const override { return oneCoordinate(body) ? d_->qpos[built_.qpos[body]] : 0.0; }
  double jointRate(int body) const override { return oneCoordinate(body) ? d_->qvel[built_.dof[body]] : 0.0; }
  double motorEffort(int body) const override { return drives_.at(body).effort; }

 private:
  // A drive: the closed form of a force-mode wheel (EngineBase::
  // solvesWheelDrive), or its joint's friction row with a velocity target.
  struct Drive {
    int dof = -1;  // -1: no drive
    bool closed_form = false;
    double spin_inertia = 0.0;  // the wheel's moment about its axle (kg m^2), closed form
    vehicle::MotorTarget target;
    double effort = 0.0;  // this step's (N m or N)
  };

  bool oneCoordinate(int body) const {
    const Body& b = vehicle().bodies.at(body);
    return b.parent >= 0 && (b.joint.type == JointType::kRevolute || b.joint.type == JointType::kPrismatic);
  }

  void buildDrive(int i) {
    const Body& b = vehicle().bodies[i];
    if (b.parent < 0 || !b.joint.actuator) return;
    Drive& drive = drives_[i];
    drive.dof = built_.dof[i];
    if (solvesWheelDrive(i)) {
      drive.closed_form = true;
      drive.spin_inertia = sim::wheelDescription(b).inertia.axial_inertia;
      return;
    }
    // The friction row: direct solref (K = 0 for friction; B = -solref[1] /
    // d = 1 / h) and a constant impedance d; off until the first command.
    const double h = settings().step_seconds, d = kDriveImpedance;
    m_.dof_frictionloss[drive.dof] = 0.0;
    m_.dof_solref[2 * drive.dof] = 0.0;
    m_.dof_solref[2 * drive.dof + 1] = -d / h;
    const std::array<mjtNum, 5> impedance = {d, d, 0.0, 0.5, 1.0};
    std::copy(impedance.begin(), impedance.end(), m_.dof_solimp + 5 * drive.dof);
  }

  // Force mode: a wheel's drive torque from the tyre's torque on it about
  // its axle (all of xfrc_applied's, at its centre on the axle) and its rate.
  void driveWheels() {
    const double h = settings().step_seconds;
    for (std::size_t i = 0; i < drives_.size(); ++i) {
      Drive& drive = drives_[i];
      if (!drive.closed_form) continue;
      const int b = built_.body[i], joint = m_.dof_jntid[drive.dof];
      const Eigen::Vector3d axis = vec3(d_->xaxis + 3 * joint);
      const double tau_axle = vec3(d_->xfrc_applied + 6 * b + 3).dot(axis);
      drive.effort = vehicle::wheelDriveTorque(drive.target, d_->qvel[drive.dof], tau_axle, drive.spin_inertia, h);
      d_->qfrc_applied[drive.dof] += drive.effort;
    }
  }

  // The drives' friction rows: a_ref = -(v - target) / h.
  void setDriveTargets() {
    const double h = settings().step_seconds;
    forEachDriveRow([&](int row, Drive& drive) { d_->efc_aref[row] += drive.target.rate / h; });
  }
  void readDriveEfforts() {
    for (Drive& drive : drives_) {
      if (!drive.closed_form) drive.effort = 0.0;
    }
    forEachDriveRow([&](int row, Drive& drive) { drive.effort = d_->efc_force[row]; });
  }
  template <class F>
  void forEachDriveRow(F&& f) {
    for (int row = d_->ne; row < d_->ne + d_->nf; ++row) {
      if (d_->efc_type[row] != mjCNSTR_FRICTION_DOF) continue;
      const int dof = d_->efc_id[row];
      for (Drive& drive : drives_) {
        if (drive.dof == dof && !drive.closed_form) f(row, drive);
      }
    }
  }

  VehicleModel built_;
  mjModel& m_;
  std::unique_ptr<mjData, DataDeleter> d_;
  std::vector<Drive> drives_;  // per vehicle body
  std::unique_ptr<Plugin> plugin_;
  std::unique_ptr<MujocoWheels> wheels_;
  std::unique_ptr<FieldContacts> field_contacts_;
  std::vector<mjtNum> external_;  // addForce's wrenches for the next step, per MuJoCo body (xfrc_applied's layout)
};

}  // namespace

std::unique_ptr<sim::Engine> makeSimEngine(const sim::EngineSettings& settings, const Terrain& terrain,
                                           const vehicle::VehicleDescription& vehicle,
                                           const Eigen::Isometry3d& placement) {
  sim::validate(settings, "wtc::mujoco::makeSimEngine");
  return std::make_unique<SimEngine>(settings, terrain, vehicle, placement);
}

}  // namespace wtc::mujoco
