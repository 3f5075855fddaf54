// Cross-engine agreement: every validation scene of the adapters, run in
// Bullet, ODE and MuJoCo, in every contact mode each serves, through one
// scene definition (engine_sim.hpp). The contact physics is the same code
// (wtc::TyreModel); what differs is how the engines integrate it:
//  - force mode: every engine steps v += h F / m, x += h v with the same
//    forces; the only differences are how each holds the wheel's rotation
//    (Bullet: angular factors, exact; ODE: an angular motor, a constraint
//    solved to roundoff by its LCP; MuJoCo: the joints) and roundoff.
//    Tolerance kForceModeRelative.
//  - constraint mode: the engines' solvers differ (Bullet: sequential
//    impulses, 10 iterations, its ERP/CFM from stiffness and damping; ODE:
//    dWorldStep's direct LCP solve with the same ERP/CFM). With one or two
//    contacts per wheel and one friction direction each, both solve the
//    same small problem to convergence: measured at most 7e-7 relative.
//    Tolerance kConstraintModeRelative; a scene with many coupled contacts
//    would need the iterative solver's own tolerance.
//  - implicit mode: constraint mode's normal row and the tread's two soft
//    friction rows per contact (Bullet: wtc::bullet::RigidContactSolver's
//    rows; ODE: dContactMotion and dContactSlip), the same soft rows in two
//    solvers: constraint mode's tolerance, no tolerance of its own
//    (measured: at most 4.8e-9 relative, the lateral drift).
//  - MuJoCo's constraint mode: the normal row is the same soft row (W/c to
//    roundoff), its friction MuJoCo's soft elliptic cone, which creeps
//    under a held force and lets a sliding contact lift; each scene says
//    its band (NamedScene::mujoco_constraint_relative). MuJoCo serves no
//    implicit mode.
// Differences beyond these are bugs. docs/cross-engine.md has the table.
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine_sim.hpp"
#include "wheel_sim.hpp"
#include "wtc/terrain/terrain_primitives.hpp"
#include "wtc/tyre/traction_law.hpp"

namespace wtc::testing {
namespace {

constexpr double kForceModeRelative = 1e-5;       // same integrator, same forces
constexpr double kConstraintModeRelative = 1e-4;  // two solvers of the same soft contacts
constexpr double kStepSeconds = 1e-3;             // h (s)
constexpr double kRadius = 0.19, kStiffness = 1e5;
constexpr double kMass = 21.0;  // a sixth of the robot (kg)
constexpr double kDegree = 0.017453292519943295;

double restDeflection(double slope = 0.0) { return kMass * kGravityMps2 * std::cos(slope) / kStiffness; }

void run(EngineSim& sim, double seconds, const std::function<void()>& each = {}) {
  for (long k = 0; k < std::lround(seconds / kStepSeconds); ++k) {
    if (each) each();
    sim.step(kStepSeconds);
  }
}

// Each scene returns one number, the quantity its validation test checks.
using Scene = std::function<double(Engine, ContactMode)>;

double settleDeflection(Engine engine, ContactMode mode) {
  const Terrain ground = flatGround();
  auto sim = makeEngineSim(engine, mode, ground, kMass, {0, 0, kRadius + 0.01}, Hold::kUpright);
  run(*sim, 3.0);
  return kRadius - sim->position().z();
}

double rollingDeceleration(Engine engine, ContactMode mode) {
  const Terrain ground = flatGround();
  auto sim = makeEngineSim(engine, mode, ground, kMass, {-5, 0, kRadius - restDeflection()}, Hold::kUpright);
  sim->setMotion({1.0, 0, 0}, 1.0 / kRadius);
  run(*sim, 0.5);
  const double v0 = sim->velocity().x();
  run(*sim, 2.0);
  return (v0 - sim->velocity().x()) / 2.0;
}

// A locked wheel (a parked vehicle's brake) at rest on `incline`, tilted by
// `slope`, at its static deflection.
std::unique_ptr<EngineSim> lockedOnSlope(Engine engine, ContactMode mode, const Terrain& incline, double slope) {
  return makeEngineSim(engine, mode, incline, kMass, (kRadius - restDeflection(slope)) * slabNormal(slope),
                       Hold::kLocked);
}

double parkedCreep(Engine engine, ContactMode mode) {
  const double slope = 15 * kDegree;
  const Terrain incline = tiltedSlab(slope);
  auto sim = lockedOnSlope(engine, mode, incline, slope);
  run(*sim, 0.5);
  const Eigen::Vector3d start = sim->position();
  run(*sim, 10.0);
  return (sim->position() - start).dot(downhill(slope));
}

double slideAcceleration(Engine engine, ContactMode mode) {
  const double slope = 45 * kDegree;
  const Terrain incline = tiltedSlab(slope);
  auto sim = lockedOnSlope(engine, mode, incline, slope);
  run(*sim, 0.3);
  const double v0 = sim->velocity().dot(downhill(slope));
  run(*sim, 1.0);
  return sim->velocity().dot(downhill(slope)) - v0;
}

double saturatedAcceleration(Engine engine, ContactMode mode) {
  const Terrain ground = flatGround();
  auto sim = makeEngineSim(engine, mode, ground, kMass, {-5, 0, kRadius - restDeflection()}, Hold::kUpright);
  run(*sim, 0.2);
  const double v0 = sim->velocity().x();
  run(*sim, 1.0, [&] { sim->push(Eigen::Vector3d::Zero(), 100.0); });
  return sim->velocity().x() - v0;
}

double lateralDrift(Engine engine, ContactMode mode) {
  const Terrain ground = flatGround();
  auto sim = makeEngineSim(engine, mode, ground, kMass, {-8, 0, kRadius - restDeflection()}, Hold::kUpright);
  sim->setMotion({1.0, 0, 0}, 1.0 / kRadius);
  const double rolling_torque = 0.018 * kMass * kGravityMps2 * 0.97 * kRadius;  // holds the speed (N m)
  auto push = [&] { sim->push({0, 0.3 * kMass * kGravityMps2, 0}, rolling_torque); };
  run(*sim, 2.0, push);
  double drift = 0.0;
  run(*sim, 1.0, [&] {
    push();
    drift += sim->velocity().y() * kStepSeconds;  // mean over 1 s
  });
  return drift;
}

double stepClimbSeconds(Engine engine, ContactMode mode) {
  TerrainBuilder builder;
  LedgeParams step;
  step.height = 0.06;
  addLedge(builder, step, builder.addMaterial({}));
  const Terrain ground = std::move(builder).build();
  auto sim = makeEngineSim(engine, mode, ground, kMass, {-1.0, 0, kRadius - restDeflection()}, Hold::kUpright);
  double t = 0.0;
  while (sim->position().x() < 0.5 && t < 5.0) {
    sim->push({0.3 * kMass * kGravityMps2, 0, 0}, 10.0);
    sim->step(kStepSeconds);
    t += kStepSeconds;
  }
  return t;
}

double ledgeFootContacts(Engine engine, ContactMode mode) {
  TerrainBuilder builder;
  addLedge(builder, {}, builder.addMaterial({}));
  const Terrain ledge = std::move(builder).build();
  auto sim =
      makeEngineSim(engine, mode, ledge, kMass, {-kRadius - 0.01, 0, kRadius - restDeflection()}, Hold::kUpright);
  run(*sim, 2.0, [&] { sim->push({100.0, 0, 0}, 0.0); });
  return static_cast<double>(sim->forces().contacts.size());
}

// A disc put down sliding at 1 m/s without spin (issue 39's "sliding disc"): the ground's force acts at
// the contact, so L = m v + I omega / r_f changes only by the rolling-resistance moment, -f_r m g r_0 / r_f
// per second, while it slides and after (whatever the slip law); once it rolls (omega r_f = v),
// v = L / (m + I / r_f^2). Measured after 1 s: 2/3 (v0 - f_r g (r_0/r_f) t) for a disc.
double slidingDiscSpeed(Engine engine, ContactMode mode) {
  const Terrain ground = flatGround();
  auto sim = makeEngineSim(engine, mode, ground, kMass, {-5, 0, kRadius - restDeflection()}, Hold::kUpright);
  sim->setMotion({1.0, 0, 0}, 0.0);
  run(*sim, 1.0);
  return sim->velocity().x();
}

// A free wheel at the foot of a 6 cm step, pushed at its axle by a force growing slowly: it lifts off the
// ground when the edge's force, along the line to the centre at alpha from the vertical
// (cos alpha = (r - h) / r), carries the weight: P = m g tan alpha (a free wheel takes no tangential
// force at the edge but its rolling resistance's). The push when the ground's contact (its normal
// vertical) carries nothing.
double stepPushAtLiftOff(Engine engine, ContactMode mode) {
  TerrainBuilder builder;
  LedgeParams step;
  step.height = 0.06;
  addLedge(builder, step, builder.addMaterial({}));
  const Terrain ground = std::move(builder).build();
  const double x = -std::sqrt(kRadius * kRadius - (kRadius - step.height) * (kRadius - step.height));
  auto sim = makeEngineSim(engine, mode, ground, kMass, {x - 0.002, 0, kRadius - restDeflection()}, Hold::kUpright);
  run(*sim, 0.5);
  const auto groundLoad = [&] {
    double load = 0.0;
    for (const ContactForce& c : sim->forces().contacts) {
      if (std::abs(c.contact.e.z()) > 0.99) load += c.normal_force;  // the ground's (the edge's is at alpha)
    }
    return load;
  };
  constexpr double kRampNps = 50.0;  // slow against the wheel's bounce on its tyre (~20 Hz)
  double push = 0.0;
  while (groundLoad() > 0.0 && push < 1000.0) {
    push += kRampNps * kStepSeconds;
    sim->push({push, 0, 0}, 0.0);
    sim->step(kStepSeconds);
  }
  return push;
}

double settleDeflectionLight(Engine engine, ContactMode mode) {
  const Terrain ground = flatGround();
  const double light = 3.7;  // the robot's wheel alone (kg)
  auto sim = makeEngineSim(engine, mode, ground, light, {0, 0, kRadius + 0.01}, Hold::kUpright);
  run(*sim, 3.0);
  return kRadius - sim->position().z();
}

// A scene, its analytic value (the spec's law, worked out in each test's
// comment) and the tolerance its validation test allows; `expected` is NaN
// for a scene with no closed form (then only the agreement is checked).
struct NamedScene {
  const char* name;
  const char* unit;
  Scene scene;
  double expected;
  double tolerance;  // absolute, in `unit`
  // Values this close (absolute, in `unit`) agree whatever their ratio:
  // the sticking tread holds a parked wheel to nanometres, where the
  // engines' own holds of its rotation and their solvers differ by
  // roundoff (measured: 2 nm in force mode, 55 nm in constraint mode).
  double agreement_floor = 0.0;
  // MuJoCo's constraint mode, its friction MuJoCo's soft cone
  // (docs/mujoco-plugin.md, "Friction"): the relative band in which it
  // agrees with Bullet and meets `expected` (where wider than `tolerance`),
  // and its own closed form where the soft cone has one (NaN: `expected`).
  double mujoco_constraint_relative = kConstraintModeRelative;
  double mujoco_constraint_expected = std::numeric_limits<double>::quiet_NaN();
};

constexpr double kNoClosedForm = std::numeric_limits<double>::quiet_NaN();

std::vector<NamedScene> scenes() {
  const Material asphalt;
  const double slope = 45 * kDegree;
  // Rolling without slip against f_r R_z r_0: a = f_r g r_0 r / (I/m + r^2), I = m r^2 / 2.
  const double rolling = 0.018 * kGravityMps2 * 0.97 * kRadius * kRadius / (1.5 * kRadius * kRadius);
  // Sliding without rolling has s = 1: a = g (sin - mu(1) cos).
  const double slide = kGravityMps2 * (std::sin(slope) - tractionCoefficient(asphalt, 1.0) * std::cos(slope));
  // A side force of 0.3 m g held by mu(s) R_z at 1 m/s: V_y = s with mu(s) = 0.3.
  const double drift = -asphalt.s1 * std::log(1.0 - 0.3 / asphalt.mu_max);
  const double light = 3.7 * kGravityMps2 / kStiffness;
  // The sliding disc: 2/3 of v0 = 1 m/s less what rolling resistance took in 1 s (slidingDiscSpeed).
  const double disc = 2.0 / 3.0 * (1.0 - 0.018 * kGravityMps2 * 0.97 * 1.0);
  // A free wheel pushed over a 6 cm step: P = m g tan alpha, cos alpha = (r - h) / r (stepPushAtLiftOff).
  const double alpha = std::acos((kRadius - 0.06) / kRadius);
  const double stepPush = kMass * kGravityMps2 * std::tan(alpha);
  // MuJoCo's soft cone holds a tangential force F only while the contact slides at h R F / impratio,
  // R = 1 / (h (h c + b)) the normal row's compliance (docs/mujoco-plugin.md): the parked wheel's
  // F = m g sin 15 deg creeps 10 s of that.
  const double compliance = 1.0 / (kStepSeconds * (kStepSeconds * kStiffness + TyreParameters{}.radial_damping));
  const double softConeCreep =
      10.0 * kStepSeconds * compliance * kMass * kGravityMps2 * std::sin(15 * kDegree) / kMujocoImpratio;
  // In MuJoCo's constraint mode a sliding tread's friction is its elliptic cone's at mu(s), which lets a
  // sliding contact lift (docs/mujoco-plugin.md, "Sliding contacts lift"); the bands below are the
  // measured differences, rounded up: 5.8 %, 3.5 %, 1.7 %, 0.8 %, 0.5 %.
  return {
      {"settle deflection", "m", settleDeflection, restDeflection(), 0.02 * restDeflection()},
      {"settle deflection of the light wheel", "m", settleDeflectionLight, light, 0.02 * light},
      {"rolling deceleration", "m/s^2", rollingDeceleration, rolling, 0.05 * rolling},
      {"parked creep in 10 s", "m", parkedCreep, 0.0, 1e-6, 1e-6, 1e-3, softConeCreep},
      {"slide acceleration on 45 deg", "m/s^2", slideAcceleration, slide, 0.02 * slide, 0.0, 0.07},
      {"saturated traction acceleration", "m/s^2", saturatedAcceleration, 0.8 * kGravityMps2, 0.02 * 0.8 * kGravityMps2,
       0.0, 0.05},
      {"lateral drift under a side force", "m/s", lateralDrift, drift, 0.05 * drift, 0.0, 0.025},
      {"sliding disc speed after 1 s", "m/s", slidingDiscSpeed, disc, 0.01 * disc, 0.0, 0.01},
      // In constraint mode the ground contact's last load is the solver's impulse, and Bullet's sequential
      // impulses and ODE's LCP bring it to zero a dozen steps of the ramp apart (measured: 0.7 N, 0.3 %).
      {"push at lift-off over a 6 cm step", "N", stepPushAtLiftOff, stepPush, 0.02 * stepPush, 1.0, 0.01},
      {"time to climb a 6 cm step", "s", stepClimbSeconds, kNoClosedForm, 0.0},
      {"contacts at the ledge foot", "count", ledgeFootContacts, 2.0, 0.0},
  };
}

class CrossEngineTest : public ::testing::TestWithParam<NamedScene> {};

// The test name of a scene: its name with every non-alphanumeric as '_'.
std::string sceneName(const ::testing::TestParamInfo<NamedScene>& info) {
  std::string name = info.param.name;
  for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

// Case: the scene's quantity agrees between Bullet and ODE (both of its
// steppers) and MuJoCo in each mode each serves.
TEST_P(CrossEngineTest, EveryEngineAgreesWithBullet) {
  const NamedScene& s = GetParam();
  for (const ContactMode mode : {ContactMode::kForce, ContactMode::kConstraint, ContactMode::kImplicit}) {
    const bool force = mode == ContactMode::kForce;
    const double bullet = s.scene(Engine::kBullet, mode);
    for (const Engine other : {Engine::kOde, Engine::kOdeQuick, Engine::kMujoco}) {
      if (!serves(other, mode)) continue;
      const bool soft_cone = other == Engine::kMujoco && mode == ContactMode::kConstraint;
      const double tolerance = force       ? kForceModeRelative
                               : soft_cone ? s.mujoco_constraint_relative
                                           : kConstraintModeRelative;
      const double value = s.scene(other, mode);
      const double scale = std::max(std::abs(bullet), std::abs(value));
      const bool within_floor = std::abs(bullet - value) <= s.agreement_floor;
      const double difference = !within_floor && scale > 0 ? std::abs(bullet - value) / scale : 0.0;
      std::printf("| %s | %s | %s | %.6g | %.6g | %.2g |\n", s.name, std::string(contactModeName(mode)).c_str(),
                  engineName(other).c_str(), bullet, value, difference);
      // Where the soft cone has its own closed form, that is its check (EveryEngineMeetsTheAnalyticValue).
      if (soft_cone && !std::isnan(s.mujoco_constraint_expected)) continue;
      EXPECT_LE(difference, tolerance) << s.name << " (" << s.unit << ") in " << contactModeName(mode)
                                       << " mode: Bullet " << bullet << ", " << engineName(other) << " " << value;
    }
  }
}

// The scenes with a closed form.
std::vector<NamedScene> analyticScenes() {
  std::vector<NamedScene> out;
  for (const NamedScene& s : scenes()) {
    if (!std::isnan(s.expected)) out.push_back(s);
  }
  return out;
}

class CrossEngineAnalyticTest : public CrossEngineTest {};

// Case: in every engine and mode the scene meets its analytic value (the
// validation scenes of the adapter issues, checked once for all engines);
// MuJoCo's constraint mode within its band, or its soft cone's own value.
TEST_P(CrossEngineAnalyticTest, EveryEngineMeetsTheAnalyticValue) {
  const NamedScene& s = GetParam();
  for (const Engine engine : {Engine::kBullet, Engine::kOde, Engine::kOdeQuick, Engine::kMujoco}) {
    for (const ContactMode mode : {ContactMode::kForce, ContactMode::kConstraint, ContactMode::kImplicit}) {
      if (!serves(engine, mode)) continue;
      const bool soft_cone = engine == Engine::kMujoco && mode == ContactMode::kConstraint;
      double expected = s.expected, tolerance = s.tolerance;
      if (soft_cone && !std::isnan(s.mujoco_constraint_expected)) {
        expected = s.mujoco_constraint_expected;
        tolerance = s.mujoco_constraint_relative * std::abs(expected);
      } else if (soft_cone) {
        tolerance = std::max(tolerance, s.mujoco_constraint_relative * std::abs(expected));
      }
      const double value = s.scene(engine, mode);
      std::printf("| %s | %s | %s | %.6g | %.6g |\n", s.name, std::string(contactModeName(mode)).c_str(),
                  engineName(engine).c_str(), value, expected);
      EXPECT_NEAR(value, expected, tolerance)
          << s.name << " (" << s.unit << "), " << engineName(engine) << ", " << contactModeName(mode) << " mode";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, CrossEngineTest, ::testing::ValuesIn(scenes()), sceneName);
INSTANTIATE_TEST_SUITE_P(Scenes, CrossEngineAnalyticTest, ::testing::ValuesIn(analyticScenes()), sceneName);

}  // namespace
}  // namespace wtc::testing
