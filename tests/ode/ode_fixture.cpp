#include "ode_fixture.hpp"

#include <numbers>

#include <gtest/gtest.h>

#include "wtc/terrain/terrain_primitives.hpp"

namespace wtc::testing {
namespace {

constexpr double kRadiusM = 0.19, kWidthM = 0.12;  // the robot's wheel (spec section 5)
constexpr int kMaxContacts = 16;                   // per pair, for ODE's own colliders
constexpr double kOtherPairsMu = 0.8;              // Coulomb friction of the pairs WTC leaves to ODE

// dInitODE2 once for the program, dCloseODE at its end.
class OdeEnvironment : public ::testing::Environment {
 public:
  void SetUp() override { dInitODE2(0); }
  void TearDown() override { dCloseODE(); }
};
[[maybe_unused]] const ::testing::Environment* const kOde = ::testing::AddGlobalTestEnvironment(new OdeEnvironment);

// The near callback of an ordinary ODE program, with the plugin's line first.
void nearCallback(void* data, dGeomID a, dGeomID b) {
  OdeWorld& w = *static_cast<OdeWorld*>(data);
  if (w.call_handle_pair && w.plugin->handlePair(a, b, w.contacts)) return;
  if (dGeomIsSpace(a) || dGeomIsSpace(b)) {
    dSpaceCollide2(a, b, data, &nearCallback);
    return;
  }
  const dBodyID body_a = dGeomGetBody(a), body_b = dGeomGetBody(b);
  if (body_a == nullptr && body_b == nullptr) return;
  dContact contact[kMaxContacts] = {};
  int n = dCollide(a, b, kMaxContacts, &contact[0].geom, sizeof(dContact));
  n = w.plugin->keepRigidContacts(a, b, &contact[0].geom, n, sizeof(dContact));  // bodies on soft soil
  for (int i = 0; i < n; ++i) {
    contact[i].surface.mode = dContactApprox1;
    contact[i].surface.mu = kOtherPairsMu;
    dJointAttach(dJointCreateContact(w.world, w.contacts, &contact[i]), body_a, body_b);
  }
}

void angularMotor(OdeWorld& w, dBodyID body, std::initializer_list<Eigen::Vector3d> axes) {
  const dJointID motor = dJointCreateAMotor(w.world, nullptr);
  dJointAttach(motor, body, nullptr);
  dJointSetAMotorMode(motor, dAMotorUser);
  dJointSetAMotorNumAxes(motor, static_cast<int>(axes.size()));
  const int fmax[] = {dParamFMax, dParamFMax2, dParamFMax3};
  int i = 0;
  for (const Eigen::Vector3d& a : axes) {
    dJointSetAMotorAxis(motor, i, 0, a.x(), a.y(), a.z());  // rel 0: fixed in the world
    dJointSetAMotorParam(motor, fmax[i], dInfinity);        // holds whatever it must (target speed 0)
    ++i;
  }
}

}  // namespace

OdeWorld::OdeWorld(const Terrain& terrain, ContactMode mode, Stepper s, ode::TerrainShape shape) : stepper(s) {
  world = dWorldCreate();
  dWorldSetGravity(world, 0, 0, -kGravityMps2);
  space = dHashSpaceCreate(nullptr);
  contacts = dJointGroupCreate(0);
  plugin = std::make_unique<ode::Plugin>(world, space, terrain, mode, shape);
}

OdeWorld::~OdeWorld() {
  plugin.reset();  // its terrain space lives in `space`
  dJointGroupDestroy(contacts);
  dSpaceDestroy(space);
  dWorldDestroy(world);
}

OdeWheel OdeWorld::addWheelBody(double mass, const Eigen::Vector3d& centre) {
  OdeWheel wheel;
  wheel.mass = mass;
  wheel.body = dBodyCreate(world);
  dMass m;
  dMassSetCylinderTotal(&m, mass, 3, kRadiusM, kWidthM);  // 3: along local z
  dBodySetMass(wheel.body, &m);
  dMatrix3 rotation;
  dRFromAxisAndAngle(rotation, 1, 0, 0, -std::numbers::pi / 2);  // local z -> world y
  dBodySetRotation(wheel.body, rotation);
  dBodySetPosition(wheel.body, centre.x(), centre.y(), centre.z());
  wheel.geom = dCreateCylinder(space, kRadiusM, kWidthM);
  dGeomSetBody(wheel.geom, wheel.body);
  return wheel;
}

void OdeWorld::collide() { dSpaceCollide(space, this, &nearCallback); }

void OdeWorld::step(double h) {
  plugin->beginStep(h);
  collide();
  if (stepper == Stepper::kStep) {
    dWorldStep(world, h);
  } else {
    dWorldQuickStep(world, h);
  }
  dJointGroupEmpty(contacts);
}

ode::WheelId addWheel(OdeWorld& w, const OdeWheel& wheel, EffectSet effects, const TyreParameters& tyre) {
  ode::RigidWheel spec;
  spec.body = wheel.body;
  spec.geom = wheel.geom;
  spec.description.tyre = tyre;
  spec.effects = effects;
  return w.plugin->addWheel(spec);
}

void keepUpright(OdeWorld& w, dBodyID body) {
  angularMotor(w, body, {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ()});
}

void lockRotation(OdeWorld& w, dBodyID body) {
  angularMotor(w, body, {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()});
}

Eigen::Vector3d position(dBodyID body) {
  const dReal* p = dBodyGetPosition(body);
  return {p[0], p[1], p[2]};
}

Eigen::Vector3d velocity(dBodyID body) {
  const dReal* v = dBodyGetLinearVel(body);
  return {v[0], v[1], v[2]};
}

}  // namespace wtc::testing
