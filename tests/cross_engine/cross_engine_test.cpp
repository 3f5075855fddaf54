// Cross-engine agreement: every validation scene of the adapters, run in
// Bullet and in ODE, in both contact modes, through one scene definition
// (engine_sim.hpp). The contact physics is the same code (wtc::TyreModel);
// what differs is how the engines integrate it:
//  - force mode: both engines step v += h F / m, x += h v with the same
//    forces; the only differences are how each holds the wheel's rotation
//    (Bullet: angular factors, exact; ODE: an angular motor, a constraint
//    solved to roundoff by its LCP, whose residue adds up over 10^4 steps:
//    4.7e-6 relative on the parked creep, 2 nm) and roundoff. Tolerance
//    kForceModeRelative.
//  - constraint mode: the engines' solvers differ (Bullet: sequential
//    impulses, 10 iterations, its ERP/CFM from stiffness and damping; ODE:
//    dWorldStep's direct LCP solve with the same ERP/CFM). With one or two
//    contacts per wheel and one friction direction each, both solve the
//    same small problem to convergence: measured at most 7e-7 relative.
//    Tolerance kConstraintModeRelative; a scene with many coupled contacts
//    would need the iterative solver's own tolerance.
// Differences beyond these are bugs. docs/cross-engine.md has the table.
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "engine_sim.hpp"
#include "wheel_sim.hpp"
#include "wtc/terrain_primitives.hpp"

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

double parkedCreep(Engine engine, ContactMode mode) {
  const double slope = 15 * kDegree;
  const Terrain incline = tiltedSlab(slope);
  auto sim =
      makeEngineSim(engine, mode, incline, kMass, (kRadius - restDeflection(slope)) * slabNormal(slope), Hold::kLocked);
  run(*sim, 0.5);
  const Eigen::Vector3d start = sim->position();
  run(*sim, 10.0);
  return (sim->position() - start).dot(downhill(slope));
}

double slideAcceleration(Engine engine, ContactMode mode) {
  const double slope = 45 * kDegree;
  const Terrain incline = tiltedSlab(slope);
  auto sim =
      makeEngineSim(engine, mode, incline, kMass, (kRadius - restDeflection(slope)) * slabNormal(slope), Hold::kLocked);
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

struct NamedScene {
  const char* name;
  const char* unit;
  Scene scene;
};

class CrossEngineTest : public ::testing::TestWithParam<NamedScene> {};

// Case: the scene's quantity agrees between Bullet and ODE (both of its
// steppers) in each mode.
TEST_P(CrossEngineTest, BulletAndOdeAgree) {
  const NamedScene& s = GetParam();
  for (const ContactMode mode : {ContactMode::kForce, ContactMode::kConstraint}) {
    const bool force = mode == ContactMode::kForce;
    const double tolerance = force ? kForceModeRelative : kConstraintModeRelative;
    const double bullet = s.scene(Engine::kBullet, mode);
    for (const Engine other : {Engine::kOde, Engine::kOdeQuick}) {
      const double ode = s.scene(other, mode);
      const double scale = std::max(std::abs(bullet), std::abs(ode));
      const double difference = scale > 0 ? std::abs(bullet - ode) / scale : 0.0;
      std::printf("| %s | %s | %s | %.6g | %.6g | %.2g |\n", s.name, force ? "force" : "constraint",
                  engineName(other).c_str(), bullet, ode, difference);
      EXPECT_LE(difference, tolerance) << s.name << " (" << s.unit << ") in " << (force ? "force" : "constraint")
                                       << " mode: Bullet " << bullet << ", " << engineName(other) << " " << ode;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, CrossEngineTest,
                         ::testing::Values(NamedScene{"settle deflection", "m", settleDeflection},
                                           NamedScene{"rolling deceleration", "m/s^2", rollingDeceleration},
                                           NamedScene{"parked creep in 10 s", "m", parkedCreep},
                                           NamedScene{"slide acceleration on 45 deg", "m/s^2", slideAcceleration},
                                           NamedScene{"saturated traction acceleration", "m/s^2",
                                                      saturatedAcceleration},
                                           NamedScene{"lateral drift under a side force", "m/s", lateralDrift},
                                           NamedScene{"time to climb a 6 cm step", "s", stepClimbSeconds},
                                           NamedScene{"contacts at the ledge foot", "count", ledgeFootContacts}),
                         [](const auto& info) {
                           std::string name = info.param.name;
                           for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return name;
                         });

}  // namespace
}  // namespace wtc::testing
