// wtc_bench_ode: what WTC costs inside an ODE step, against ODE's own wheel
// contact, in the same run.
//
//   build/bench/wtc_bench_ode --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
//
// The scene of wtc_bench_bullet: the rough ground of scenario 3
// (terrains/rough_ground.yaml, 7200 heightfield prisms and rocks, mirrored
// into ODE as one triangle mesh per piece) and six 21 kg wheels (cylinders
// r = 0.19 m, w = 0.12 m, held upright by an angular motor), each on its own
// line, driven by 3 N m for 2 s of warm-up and 10 s of timed steps. One item
// = one world step of 1 ms (dWorldQuickStep) for the whole scene, collision
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

namespace {

constexpr int kWheels = 6;
constexpr double kRadius = 0.19, kWidth = 0.12;   // (m)
constexpr double kMass = 21.0;                    // a sixth of the robot (kg)
constexpr double kStepSeconds = 1e-3;             // (s)
constexpr double kDriveTorque = 3.0;              // per wheel (N m): twice the soil's rolling resistance
constexpr double kLaneSpacingM = 1.5;             // between the wheels' lines (m)
constexpr double kStartX = -12.0, kDropM = 0.05;  // start (m) and height above the ground (m)
constexpr int kWarmupSteps = 2000;                // settle and spin up
constexpr int kTimedSteps = 10000;                // 10 s: every wheel stays on the 30 m ground
constexpr int kMaxNativeContacts = 8;             // per pair, ODE's own collider
constexpr double kNativeMu = 0.8;                 // ODE's Coulomb friction for its own contacts

const wtc::Terrain& roughGround() {
  static const wtc::Terrain terrain = wtc::io::loadTerrain(WTC_SOURCE_DIR "/terrains/rough_ground.yaml");
  return terrain;
}

class Scene {
 public:
  explicit Scene(const std::string& kind) : native_(kind == "native") {
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
    for (int i = 0; i < kWheels; ++i) {
      const dBodyID body = dBodyCreate(world_);
      dMass mass;
      dMassSetCylinderTotal(&mass, kMass, 3, kRadius, kWidth);
      dBodySetMass(body, &mass);
      dBodySetQuaternion(body, turn);
      dBodySetPosition(body, kStartX, (i - 0.5 * (kWheels - 1)) * kLaneSpacingM, 0.15 + kRadius + kDropM);
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
        spec.description.inertia = {kMass, 0.5 * kMass * kRadius * kRadius};
        plugin_->addWheel(spec);
      }
    }
    for (int k = 0; k < kWarmupSteps; ++k) step();
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

void odeStep(benchmark::State& state, const std::string& kind) {
  Scene scene(kind);
  long contacts = 0, steps = 0;
  for (auto _ : state) {
    scene.step();
    contacts += scene.contacts();
    ++steps;
  }
  state.SetItemsProcessed(steps);
  state.counters["wheels"] = kWheels;
  state.counters["contacts"] = steps > 0 ? static_cast<double>(contacts) / steps : 0.0;
  state.counters["speed_mps"] = scene.speed();
}

// dInitODE2 before the first scene, for the whole program.
const bool kOdeReady = [] {
  dInitODE2(0);
  return true;
}();

}  // namespace

BENCHMARK_CAPTURE(odeStep, native, std::string("native"))
    ->Name("OdeStep/native")
    ->Iterations(kTimedSteps)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(odeStep, wtc_force, std::string("wtc_force"))
    ->Name("OdeStep/wtc_force")
    ->Iterations(kTimedSteps)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(odeStep, wtc_constraint, std::string("wtc_constraint"))
    ->Name("OdeStep/wtc_constraint")
    ->Iterations(kTimedSteps)
    ->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
