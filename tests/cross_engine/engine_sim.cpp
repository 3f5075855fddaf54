#include "engine_sim.hpp"

#include <sstream>

#include "bullet_fixture.hpp"
#include "mujoco_fixtures.hpp"
#include "ode_fixture.hpp"

namespace wtc::testing {
namespace {

// A btRigidBody wheel in a btDiscreteDynamicsWorld whose solver is
// wtc::bullet::RigidContactSolver (the fixture's): implicit mode's tread rows
// need it; the other modes are Bullet's own solver's.
class BulletSim : public EngineSim {
 public:
  BulletSim(ContactMode mode, const Terrain& terrain, double mass, const Eigen::Vector3d& c, Hold hold,
            const TyreParameters& tyre)
      : world_(terrain, mode), wheel_(world_.addWheelBody(mass, btVector3(c.x(), c.y(), c.z()))) {
    if (hold == Hold::kUpright) wheel_.body->setAngularFactor(btVector3(0, 1, 0));
    if (hold == Hold::kLocked) wheel_.body->setAngularFactor(btVector3(0, 0, 0));
    id_ = addWheel(world_, wheel_, EffectSet::full(), tyre);
  }
  void push(const Eigen::Vector3d& f, double torque_y) override {
    wheel_.body->applyCentralForce(btVector3(f.x(), f.y(), f.z()));
    wheel_.body->applyTorque(btVector3(0, torque_y, 0));
  }
  void setMotion(const Eigen::Vector3d& v, double spin_y) override {
    wheel_.body->setLinearVelocity(btVector3(v.x(), v.y(), v.z()));
    wheel_.body->setAngularVelocity(btVector3(0, spin_y, 0));
  }
  void step(double h) override { world_.world.stepSimulation(h, 1, h); }
  Eigen::Vector3d position() const override {
    const btVector3 p = wheel_.body->getCenterOfMassPosition();
    return {p.x(), p.y(), p.z()};
  }
  Eigen::Vector3d velocity() const override {
    const btVector3 v = wheel_.body->getLinearVelocity();
    return {v.x(), v.y(), v.z()};
  }
  const WheelForces& forces() const override { return world_.plugin->forces(id_); }
  const WheelForces& applied() const override { return world_.plugin->applied(id_); }

 private:
  BulletWorld world_;
  BulletWheel& wheel_;
  bullet::WheelId id_ = -1;
};

class OdeSim : public EngineSim {
 public:
  OdeSim(ContactMode mode, const Terrain& terrain, double mass, const Eigen::Vector3d& c, Hold hold, Stepper stepper,
         const TyreParameters& tyre)
      : world_(terrain, mode, stepper), wheel_(world_.addWheelBody(mass, c)) {
    if (hold == Hold::kUpright) keepUpright(world_, wheel_.body);
    if (hold == Hold::kLocked) lockRotation(world_, wheel_.body);
    id_ = addWheel(world_, wheel_, EffectSet::full(), tyre);
  }
  void push(const Eigen::Vector3d& f, double torque_y) override {
    dBodyAddForce(wheel_.body, f.x(), f.y(), f.z());
    dBodyAddTorque(wheel_.body, 0, torque_y, 0);
  }
  void setMotion(const Eigen::Vector3d& v, double spin_y) override {
    dBodySetLinearVel(wheel_.body, v.x(), v.y(), v.z());
    dBodySetAngularVel(wheel_.body, 0, spin_y, 0);
  }
  void step(double h) override { world_.step(h); }
  Eigen::Vector3d position() const override { return testing::position(wheel_.body); }
  Eigen::Vector3d velocity() const override { return testing::velocity(wheel_.body); }
  const WheelForces& forces() const override { return world_.plugin->forces(id_); }
  const WheelForces& applied() const override { return world_.plugin->applied(id_); }

 private:
  OdeWorld world_;
  OdeWheel wheel_;
  ode::WheelId id_ = -1;
};

// The wheel as a body of an MJCF model: on slides along x, y, z and a hinge
// about y (upright), on the slides alone (locked), or on a free joint, with
// the fixtures' inertia, stepped by wtc::mujoco::Plugin; the cone elliptic
// at kMujocoImpratio. The world's one geom, far below and colliding with
// nothing, is what constraint mode's contacts are made against.
class MujocoSim : public EngineSim {
 public:
  MujocoSim(ContactMode mode, const Terrain& terrain, double mass, const Eigen::Vector3d& c, Hold hold,
            const TyreParameters& tyre)
      : model_(mjcf(mass, c, hold)), start_(c), hold_(hold), plugin_(*model_.m, terrain, mode) {
    body_ = model_.body("wheel");
    mujoco::Wheel wheel = mujocoWheel(body_, kRadiusM, kWidthM);
    wheel.description.tyre = tyre;
    wheel.effects = EffectSet::full();
    id_ = plugin_.addWheel(wheel);
  }
  void push(const Eigen::Vector3d& f, double torque_y) override {
    mjtNum* wrench = model_.d->xfrc_applied + 6 * body_;
    for (int i = 0; i < 3; ++i) wrench[i] += f[i];
    wrench[4] += torque_y;
  }
  void setMotion(const Eigen::Vector3d& v, double spin_y) override {
    for (int i = 0; i < 3; ++i) model_.d->qvel[i] = v[i];
    // A free joint's angular velocity is in the body's frame, which is the
    // world's until the wheel turns: setMotion comes before the first step.
    if (hold_ == Hold::kUpright) model_.d->qvel[3] = spin_y;
    if (hold_ == Hold::kFree) model_.d->qvel[4] = spin_y;
  }
  void step(double h) override {
    model_.m->opt.timestep = h;  // the plugin reads it each step
    plugin_.step(*model_.m, *model_.d);
    mju_zero(model_.d->xfrc_applied + 6 * body_, 6);
  }
  // From qpos, not xpos: mj_Euler moves qpos after the step's kinematics,
  // so xpos is the position the step started from. The slides along x, y,
  // z move the centre from where it started; a free joint's first three
  // coordinates are the centre itself, its first three velocities the
  // centre's (world frame).
  Eigen::Vector3d position() const override {
    const Eigen::Vector3d q(model_.d->qpos[0], model_.d->qpos[1], model_.d->qpos[2]);
    return hold_ == Hold::kFree ? q : Eigen::Vector3d(start_ + q);
  }
  Eigen::Vector3d velocity() const override { return {model_.d->qvel[0], model_.d->qvel[1], model_.d->qvel[2]}; }
  const WheelForces& forces() const override { return plugin_.forces(id_); }
  const WheelForces& applied() const override { return plugin_.applied(id_); }

 private:
  static constexpr double kRadiusM = 0.19, kWidthM = 0.12;

  static std::string mjcf(double mass, const Eigen::Vector3d& c, Hold hold) {
    const double r = kRadiusM, w = kWidthM;
    const double spin = 0.5 * mass * r * r, across = 0.25 * mass * r * r + mass * w * w / 12;  // the fixtures' disc
    std::ostringstream xml;
    xml.precision(17);
    xml << "<mujoco model=\"cross_engine_wheel\">\n"
        << "  <option integrator=\"Euler\" cone=\"elliptic\" impratio=\"" << kMujocoImpratio << "\""
        << " gravity=\"0 0 " << -kGravityMps2 << "\"/>\n"
        << "  <worldbody>\n"
        << "    <geom name=\"anchor\" type=\"box\" size=\"0.01 0.01 0.01\" pos=\"0 0 -100\" contype=\"0\""
        << " conaffinity=\"0\"/>\n"
        << "    <body name=\"wheel\" pos=\"" << c.x() << ' ' << c.y() << ' ' << c.z() << "\">\n";
    if (hold == Hold::kFree) {
      xml << "      <freejoint/>\n";
    } else {
      for (const char* axis : {"1 0 0", "0 1 0", "0 0 1"})
        xml << "      <joint type=\"slide\" axis=\"" << axis << "\"/>\n";
      if (hold == Hold::kUpright) xml << "      <joint type=\"hinge\" axis=\"0 1 0\"/>\n";
    }
    xml << "      <inertial pos=\"0 0 0\" mass=\"" << mass << "\" diaginertia=\"" << across << ' ' << spin << ' '
        << across << "\"/>\n"
        << "      <geom name=\"tyre\" type=\"cylinder\" size=\"" << r << ' ' << 0.5 * w
        << "\" euler=\"90 0 0\" contype=\"0\" conaffinity=\"0\"/>\n"
        << "    </body>\n  </worldbody>\n</mujoco>\n";
    return xml.str();
  }

  MjcfModel model_;
  Eigen::Vector3d start_;
  Hold hold_;
  mujoco::Plugin plugin_;
  int body_ = -1;
  mujoco::WheelId id_ = -1;
};

}  // namespace

std::string engineName(Engine engine) {
  switch (engine) {
    case Engine::kBullet:
      return "Bullet";
    case Engine::kOde:
      return "ODE dWorldStep";
    case Engine::kOdeQuick:
      return "ODE dWorldQuickStep";
    case Engine::kMujoco:
      return "MuJoCo";
  }
  return "?";
}

bool serves(Engine engine, ContactMode mode) { return engine != Engine::kMujoco || mode != ContactMode::kImplicit; }

std::unique_ptr<EngineSim> makeEngineSim(Engine engine, ContactMode mode, const Terrain& terrain, double mass,
                                         const Eigen::Vector3d& centre, Hold hold, const TyreParameters& tyre) {
  if (engine == Engine::kBullet) return std::make_unique<BulletSim>(mode, terrain, mass, centre, hold, tyre);
  if (engine == Engine::kMujoco) return std::make_unique<MujocoSim>(mode, terrain, mass, centre, hold, tyre);
  return std::make_unique<OdeSim>(mode, terrain, mass, centre, hold,
                                  engine == Engine::kOde ? Stepper::kStep : Stepper::kQuickStep, tyre);
}

}  // namespace wtc::testing
