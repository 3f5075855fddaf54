#include "engine_sim.hpp"

#include "bullet_fixture.hpp"
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

}  // namespace

std::string engineName(Engine engine) {
  switch (engine) {
    case Engine::kBullet:
      return "Bullet";
    case Engine::kOde:
      return "ODE dWorldStep";
    case Engine::kOdeQuick:
      return "ODE dWorldQuickStep";
  }
  return "?";
}

std::unique_ptr<EngineSim> makeEngineSim(Engine engine, ContactMode mode, const Terrain& terrain, double mass,
                                         const Eigen::Vector3d& centre, Hold hold, const TyreParameters& tyre) {
  if (engine == Engine::kBullet) return std::make_unique<BulletSim>(mode, terrain, mass, centre, hold, tyre);
  return std::make_unique<OdeSim>(mode, terrain, mass, centre, hold,
                                  engine == Engine::kOde ? Stepper::kStep : Stepper::kQuickStep, tyre);
}

}  // namespace wtc::testing
