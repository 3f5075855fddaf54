// wtc_bench_ode: what WTC costs inside an ODE step, against ODE's own wheel
// contact, in the same run.
//
//   build/bench/wtc_bench_ode --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
//
// The scene of wtc_bench_bullet (bench/engine_step_scene.hpp), its pieces
// mirrored into ODE as one triangle mesh each, the wheels held upright by an
// angular motor. One item = one world step of 1 ms (dWorldQuickStep) for the
// whole scene, collision
// included. Runs:
//   OdeStep/native          no WTC: ODE's cylinder-against-trimesh contacts
//                           (up to 8 per pair, mu 0.8)
//   OdeStep/wtc_force       WTC in force mode (full tyre model)
//   OdeStep/wtc_constraint  WTC in constraint mode
// Counters: contacts per step over all wheels (WTC contacts, or ODE
// contact joints).
#include <benchmark/benchmark.h>

#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <ode/ode.h>
#include <wtc/io/terrain_file.hpp>
#include <wtc/ode/plugin.hpp>

#include "engine_step_scene.hpp"

namespace {

using namespace wtc::bench;

constexpr int kMaxNativeContacts = 8;  // per pair, ODE's own collider
constexpr double kNativeMu = 0.8;      // ODE's Coulomb friction for its own contacts

class Scene {
 public:
  Scene(const std::string& kind, int wheels) : native_(kind == "native") {
    world_ = dWorldCreate();
    dWorldSetGravity(world_, 0, 0, -9.81);
    space_ = dHashSpaceCreate(nullptr);
    contacts_ = dJointGroupCreate(0);
    if (native_) {
      native_terrain_ =
          std::make_unique<wtc::ode::TerrainGeoms>(roughGround(), space_, wtc::ode::TerrainShape::kTriMesh);
    } else {
      plugin_ = std::make_unique<wtc::ode::Plugin>(
          world_, space_, roughGround(),
          kind == "wtc_force" ? wtc::ContactMode::kForce : wtc::ContactMode::kConstraint);
    }
    // ODE's cylinder axis is local z: turn it to the world's y.
    const dQuaternion turn = {std::numbers::sqrt2 / 2, -std::numbers::sqrt2 / 2, 0, 0};
    for (int i = 0; i < wheels; ++i) {
      const dBodyID body = dBodyCreate(world_);
      dMass mass;
      dMassSetCylinderTotal(&mass, kMass, 3, kRadius, kWidth);
      dBodySetMass(body, &mass);
      dBodySetQuaternion(body, turn);
      dBodySetPosition(body, startX(i), laneY(i, wheels), kStartZ);
      dBodySetAutoDisableFlag(body, 0);
      const dGeomID geom = dCreateCylinder(space_, kRadius, kWidth);
      dGeomSetBody(geom, body);
      // Upright: no rotation about world x and z.
      const dJointID motor = dJointCreateAMotor(world_, nullptr);
      dJointAttach(motor, body, nullptr);
      dJointSetAMotorMode(motor, dAMotorUser);
      dJointSetAMotorNumAxes(motor, 2);
      dJointSetAMotorAxis(motor, 0, 0, 1, 0, 0);
      dJointSetAMotorAxis(motor, 1, 0, 0, 0, 1);
      dJointSetAMotorParam(motor, dParamFMax, dInfinity);
      dJointSetAMotorParam(motor, dParamFMax2, dInfinity);
      bodies_.push_back(body);
      if (plugin_) {
        wtc::ode::RigidWheel spec;
        spec.body = body;
        spec.geom = geom;
        spec.description.geometry = {kRadius, kWidth};
        plugin_->addWheel(spec);
      }
    }
  }
  ~Scene() {
    plugin_.reset();
    native_terrain_.reset();
    dJointGroupDestroy(contacts_);
    dSpaceDestroy(space_);
    dWorldDestroy(world_);
  }
  void step() {
    for (const dBodyID body : bodies_) dBodyAddTorque(body, 0, kDriveTorque, 0);
    if (plugin_) plugin_->beginStep(kStepSeconds);
    joints_ = 0;
    dSpaceCollide(space_, this, &Scene::nearCallback);
    dWorldQuickStep(world_, kStepSeconds);
    dJointGroupEmpty(contacts_);
  }
  int contacts() const {
    if (!plugin_) return joints_;
    int n = 0;
    for (int i = 0; i < plugin_->wheelCount(); ++i) n += static_cast<int>(plugin_->forces(i).contacts.size());
    return n;
  }
  double speed() const { return dBodyGetLinearVel(bodies_.front())[0]; }

 private:
  static void nearCallback(void* data, dGeomID a, dGeomID b) {
    Scene& s = *static_cast<Scene*>(data);
    if (s.plugin_ && s.plugin_->handlePair(a, b, s.contacts_)) return;
    if (dGeomIsSpace(a) || dGeomIsSpace(b)) {
      dSpaceCollide2(a, b, data, &Scene::nearCallback);
      return;
    }
    const dBodyID body_a = dGeomGetBody(a), body_b = dGeomGetBody(b);
    if (body_a == nullptr && body_b == nullptr) return;
    dContact contact[kMaxNativeContacts] = {};
    const int n = dCollide(a, b, kMaxNativeContacts, &contact[0].geom, sizeof(dContact));
    for (int i = 0; i < n; ++i) {
      contact[i].surface.mode = dContactApprox1;
      contact[i].surface.mu = kNativeMu;
      dJointAttach(dJointCreateContact(s.world_, s.contacts_, &contact[i]), body_a, body_b);
    }
    s.joints_ += n;
  }

  bool native_;
  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;
  dJointGroupID contacts_ = nullptr;
  std::unique_ptr<wtc::ode::TerrainGeoms> native_terrain_;
  std::unique_ptr<wtc::ode::Plugin> plugin_;
  std::vector<dBodyID> bodies_;
  int joints_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  dInitODE2(0);
  registerScenes<Scene>("Ode");
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  dCloseODE();
}
