// Constraint mode's normal row is the implicit Euler step of the tyre's
// spring-damper (issue 41, deliverable 1's check). A wheel with its rotation
// held, dropped onto flat ground, feels gravity and its one contact only:
//   m z'' = -m g + R_z,  R_z = c Z - b z' >= 0,  Z = r_f - z.
// Implicit Euler (the force at the end of the step, the position updated
// with the new velocity, as both engines integrate):
//   v+ = v - g h + h R_z+ / m,  R_z+ = c (Z - h v+) - b v+,  z+ = z + h v+
//   => v+ = (m (v - g h) + h c Z) / (m + h (h c + b)),  if R_z+ >= 0,
// else v+ = v - g h. This is what a row with ERP = h c / (h c + b) and
// CFM = 1 / (h c + b) solves: ODE's LCP row (1/m + CFM/h) f = (ERP Z/h - v)/h
// + g (CFM times 1/h in dxStepIsland, as ODE's manual says) and Bullet's
// (1/m + CFM/h) p = ERP Z/h - (v - g h), p = f h, both give
//   v+ = ERP Z / h - CFM f,
// the line above with f = R_z+. Each step is checked from the state the
// engine started it in, and the whole run against the recursion alone. ODE
// caps the row's target ERP Z / h at dWorldSetContactMaxCorrectingVel and
// Bullet moves its zero by m_linearSlop: those departures (both off by
// default) are measured in their own tests (docs/tyre-model.md). Run:
//   build/tests/cross_engine/wtc_cross_engine_tests --gtest_filter='ImplicitNormalRow*'
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <string>

#include "bullet_fixture.hpp"
#include "engine_sim.hpp"
#include "multibody_wheel_sim.hpp"
#include "ode_fixture.hpp"
#include "wheel_sim.hpp"

namespace wtc::testing {
namespace implicit_normal_row_test {

constexpr double kRadius = 0.19, kWidth = 0.12;  // the robot's wheel: r_f, tread width (m)
constexpr double kMass = 21.0;                   // kg on the contact: a sixth of the robot
constexpr double kRunSeconds = 1.0;
// Per step, the engine's velocity against the recursion's from the same
// start, over g h (the velocity a step of gravity gives): round-off only.
constexpr double kStepVelocityRelative = 1e-9;
constexpr double kNoCap = std::numeric_limits<double>::infinity();

// A vertical state: the wheel centre's height z (m) and velocity v (m/s, up).
struct Vertical {
  double z = 0.0, v = 0.0;
};

// What an engine setting does to the row: ODE's cap on its target velocity
// (m/s), Bullet's linear slop (m), which it adds to the contact's distance
// (btSequentialImpulseConstraintSolver::setupContactConstraintInternal:
// penetration = distance + m_linearSlop; a penetration below zero asks
// ERP (-penetration) / h, one above zero lets the bodies approach by
// penetration / h, with no ERP).
struct Row {
  double cap = kNoCap, slop = 0.0;
};

// One implicit Euler step of the spring-damper (c, b) under gravity: the
// row's target velocity, ERP Z / h = c Z / (h c + b) with the defaults,
// then v+ = target - CFM f, f = (target - v+) (h c + b) >= 0.
Vertical implicitStep(Vertical s, double c, double b, double h, Row row = {}) {
  const double depth = kRadius - s.z, free = s.v - kGravityMps2 * h;
  if (depth <= 0.0) return {s.z + h * free, free};
  const double inverse_cfm = h * c + b, error = depth - row.slop;
  const double target = std::min(error > 0.0 ? c * error / inverse_cfm : error / h, row.cap);
  double v = (kMass * free + h * inverse_cfm * target) / (kMass + h * inverse_cfm);
  if (target - v < 0.0) v = free;  // the row never pulls
  return {s.z + h * v, v};
}

// What a drop is compared by: the largest per-step gap in velocity (m/s)
// and height (m), the largest gap of the whole run against the recursion
// alone (m), and the deepest deflection reached (m).
struct Gaps {
  double step_velocity = 0.0, step_height = 0.0, run_height = 0.0, deepest = 0.0;
};

struct Tyre {
  const char* name;
  double stiffness, damping, drop;  // c (N/m), b (N s/m), tread's height above the ground at the start (m)
};
// Shallow: the robot's tyre, 2.1 mm static deflection (4-7 mm at the
// bounce's bottom). Deep: a soft tyre, 41 mm static deflection, 66-78 mm at
// the bounce's bottom: past Bullet's split-impulse threshold (40 mm), which
// the plugin steers around (wheel_terrain_algorithm.cpp, setSpring).
constexpr Tyre kShallow{"shallow", 1e5, 900.0, 0.01}, kDeep{"deep", 5e3, 100.0, 0.02};
constexpr double kSteps[] = {4e-4, 1e-2, 2e-2};

// Steps `step` (one engine step of h) and reads the wheel's vertical state
// through `read`, from a drop of `tyre`, against implicitStep. Only while
// the deflection is below half the radius: past it the wheel has gone
// through the ground (a capped row) and the contact is no longer the
// tread's lowest point; it still runs on, and `deepest` says how far.
template <class Step, class Read>
Gaps compare(const Tyre& tyre, double h, Step step, Read read, Row row = {}) {
  constexpr double kThroughM = 0.5 * kRadius;
  Gaps gaps;
  Vertical alone = read();
  const long steps = std::lround(kRunSeconds / h);
  for (long k = 0; k < steps; ++k) {
    const Vertical before = read();
    step();
    if (kRadius - before.z > kThroughM || kRadius - alone.z > kThroughM) {
      gaps.deepest = std::max(gaps.deepest, kRadius - read().z);
      continue;
    }
    const Vertical after = read(), expected = implicitStep(before, tyre.stiffness, tyre.damping, h, row);
    alone = implicitStep(alone, tyre.stiffness, tyre.damping, h, row);
    gaps.step_velocity = std::max(gaps.step_velocity, std::abs(after.v - expected.v));
    gaps.step_height = std::max(gaps.step_height, std::abs(after.z - expected.z));
    gaps.run_height = std::max(gaps.run_height, std::abs(after.z - alone.z));
    gaps.deepest = std::max(gaps.deepest, kRadius - after.z);
  }
  return gaps;
}

TyreParameters tyreOf(const Tyre& tyre) {
  TyreParameters p;
  p.radial_stiffness = tyre.stiffness;
  p.radial_damping = tyre.damping;
  return p;
}

std::string label(const std::string& engine, const Tyre& tyre, double h) {
  return engine + ", " + tyre.name + ", h = " + std::to_string(h * 1e3) + " ms";
}

void report(const std::string& what, const Gaps& g, double h) {
  std::cout << what << ": per step |dv| " << g.step_velocity << " m/s (" << g.step_velocity / (kGravityMps2 * h)
            << " g h), |dz| " << g.step_height << " m; whole run |dz| " << g.run_height << " m; deepest "
            << g.deepest * 1e3 << " mm\n";
  ::testing::Test::RecordProperty(what + " step_dv_over_gh", std::to_string(g.step_velocity / (kGravityMps2 * h)));
  ::testing::Test::RecordProperty(what + " run_dz_m", std::to_string(g.run_height));
}

void expectImplicit(const std::string& what, const Gaps& g, double h, const Tyre& tyre) {
  report(what, g, h);
  EXPECT_LT(g.step_velocity, kStepVelocityRelative * kGravityMps2 * h) << what;
  EXPECT_LT(g.step_height, kStepVelocityRelative * kGravityMps2 * h * h) << what;
  // The deep drop must really cross Bullet's split threshold (0.04 m).
  if (&tyre == &kDeep) {
    EXPECT_GT(g.deepest, 0.05) << what;
  }
}

// Bullet's rigid-body solver (with the plugin's way around the split
// impulse for the deep drop) and ODE's two steppers, with their defaults:
// each step is the implicit Euler step of (c, b) to round-off.
TEST(ImplicitNormalRowTest, EachStepIsTheImplicitEulerStepOfTheSpringDamper) {
  const Terrain ground = flatGround();
  for (const Engine engine : {Engine::kBullet, Engine::kOde, Engine::kOdeQuick}) {
    for (const Tyre* tyre : {&kShallow, &kDeep}) {
      for (const double h : kSteps) {
        auto sim = makeEngineSim(engine, ContactMode::kConstraint, ground, kMass, {0, 0, kRadius + tyre->drop},
                                 Hold::kLocked, tyreOf(*tyre));
        const Gaps g = compare(
            *tyre, h, [&] { sim->step(h); },
            [&] {
              return Vertical{sim->position().z(), sim->velocity().z()};
            });
        expectImplicit(label(engineName(engine), *tyre, h), g, h, *tyre);
      }
    }
  }
}

// The same in Bullet's multibody solver (a wheel link of a btMultiBody).
TEST(ImplicitNormalRowTest, EachStepIsTheImplicitEulerStepInBulletsMultiBodySolver) {
  const Terrain ground = flatGround();
  for (const Tyre* tyre : {&kShallow, &kDeep}) {
    for (const double h : kSteps) {
      MultiBodyWheelSim sim(ground, kRadius + tyre->drop, tyreOf(*tyre));
      const Gaps g = compare(
          *tyre, h, [&] { sim.world.stepSimulation(h, 1, h); },
          [&] {
            return Vertical{sim.multibody->getBasePos().z(), sim.multibody->getBaseVel().z()};
          });
      expectImplicit(label("Bullet multibody", *tyre, h), g, h, *tyre);
    }
  }
}

// One ODE world with the wheel dropped, its world settings set by `setUp`,
// compared by `compare` against the recursion capped at `cap`.
template <class SetUp>
Gaps odeDrop(Stepper stepper, const Tyre& tyre, double h, SetUp setUp, Row row = {}) {
  const Terrain ground = flatGround();
  OdeWorld w(ground, ContactMode::kConstraint, stepper);
  setUp(w.world);
  const OdeWheel wheel = w.addWheelBody(kMass, {0, 0, kRadius + tyre.drop});
  lockRotation(w, wheel.body);
  addWheel(w, wheel, EffectSet::full(), tyreOf(tyre));
  return compare(
      tyre, h, [&] { w.step(h); },
      [&] {
        return Vertical{position(wheel.body).z(), velocity(wheel.body).z()};
      },
      row);
}

std::string stepperName(Stepper stepper) {
  return stepper == Stepper::kStep ? "ODE dWorldStep" : "ODE dWorldQuickStep";
}

// ODE subtracts its contact surface layer from every depth
// (dxJointContact::getInfo2: depth - min_depth); the plugin adds it back
// (contact_joint.cpp), so with ODE's demos' layer (1 mm) the row is still
// the implicit Euler step.
TEST(ImplicitNormalRowTest, OdesContactSurfaceLayerLeavesTheStepImplicit) {
  constexpr double kDemoLayerM = 0.001;
  for (const Stepper stepper : {Stepper::kStep, Stepper::kQuickStep}) {
    for (const Tyre* tyre : {&kShallow, &kDeep}) {
      for (const double h : kSteps) {
        const Gaps g = odeDrop(stepper, *tyre, h, [&](dWorldID w) { dWorldSetContactSurfaceLayer(w, kDemoLayerM); });
        expectImplicit(label(stepperName(stepper) + " with a 1 mm surface layer", *tyre, h), g, h, *tyre);
      }
    }
  }
}

// ODE caps the row's target velocity ERP Z / h at the world's contact max
// correcting velocity (dxJointContact::getInfo2: c[0] = min(ERP Z / h,
// max_vel)); infinite by default, 0.1 m/s in ODE's demos. With the demos'
// cap the row is the capped recursion to round-off and departs from the
// implicit Euler step: where m g / (h c + b) exceeds the cap the force
// cannot hold the weight at any depth and the wheel sinks at
// m g / (h c + b) - cap (recorded: deepest after 1 s).
TEST(ImplicitNormalRowTest, OdesMaxCorrectingVelocityCapsTheSpringAndDeparts) {
  constexpr double kDemoCapMps = 0.1;
  const auto setCap = [&](dWorldID w) { dWorldSetContactMaxCorrectingVel(w, kDemoCapMps); };
  for (const Stepper stepper : {Stepper::kStep, Stepper::kQuickStep}) {
    for (const Tyre* tyre : {&kShallow, &kDeep}) {
      for (const double h : kSteps) {
        const std::string what = label(stepperName(stepper) + " capped at 0.1 m/s", *tyre, h);
        const Gaps capped = odeDrop(stepper, *tyre, h, setCap, Row{kDemoCapMps});
        report(what + " (against the capped row)", capped, h);
        EXPECT_LT(capped.step_velocity, kStepVelocityRelative * kGravityMps2 * h) << what;
        const Gaps departure = odeDrop(stepper, *tyre, h, setCap);
        report(what + " (against the implicit step)", departure, h);
        EXPECT_GT(departure.step_velocity, 1e3 * kStepVelocityRelative * kGravityMps2 * h) << what;
      }
    }
  }
}

// Bullet adds its linear slop (0 by default) to every contact's distance,
// in the rigid-body solver (setupContactConstraintInternal) and in the
// plugin's way around the split impulse (setSpring keeps (Z - slop) ERP / h):
// the spring's zero moves down by the slop, and below it the row is a
// plain velocity limit (no ERP, no spring). With 1 mm the row is that
// recursion to round-off, and departs from the implicit step of c Z.
TEST(ImplicitNormalRowTest, BulletsLinearSlopMovesTheSpringsZeroAndDeparts) {
  constexpr double kSlopM = 0.001;
  const Terrain ground = flatGround();
  for (const Tyre* tyre : {&kShallow, &kDeep}) {
    for (const double h : kSteps) {
      const auto drop = [&](Row row) {
        BulletWorld w(ground, ContactMode::kConstraint);
        w.world.getSolverInfo().m_linearSlop = kSlopM;
        BulletWheel& wheel = w.addWheelBody(kMass, btVector3(0, 0, kRadius + tyre->drop));
        wheel.body->setAngularFactor(btVector3(0, 0, 0));
        addWheel(w, wheel, EffectSet::full(), tyreOf(*tyre));
        return compare(
            *tyre, h, [&] { w.world.stepSimulation(h, 1, h); },
            [&] {
              return Vertical{wheel.body->getCenterOfMassPosition().z(), wheel.body->getLinearVelocity().z()};
            },
            row);
      };
      const std::string what = label("Bullet with a 1 mm linear slop", *tyre, h);
      const Gaps slop = drop(Row{kNoCap, kSlopM});
      report(what + " (against the slop's row)", slop, h);
      EXPECT_LT(slop.step_velocity, kStepVelocityRelative * kGravityMps2 * h) << what;
      const Gaps departure = drop(Row{});
      report(what + " (against the implicit step)", departure, h);
      EXPECT_GT(departure.step_velocity, 1e3 * kStepVelocityRelative * kGravityMps2 * h) << what;
    }
  }
}

// Implicit mode hands Bullet Z + m_linearSlop (wheel_terrain_algorithm.cpp),
// so that with a slop the row is the implicit step of c Z again: the
// multibody wheel and the rigid one (its deep drop past the split impulse's
// threshold too) with a 1 mm slop against the recursion without one.
TEST(ImplicitNormalRowTest, ImplicitModeTakesBulletsLinearSlopBackOut) {
  constexpr double kSlopM = 0.001;
  const Terrain ground = flatGround();
  for (const Tyre* tyre : {&kShallow, &kDeep}) {
    for (const double h : kSteps) {
      BulletWorld w(ground, ContactMode::kImplicit);
      w.world.getSolverInfo().m_linearSlop = kSlopM;
      BulletWheel& wheel = w.addWheelBody(kMass, btVector3(0, 0, kRadius + tyre->drop));
      wheel.body->setAngularFactor(btVector3(0, 0, 0));
      addWheel(w, wheel, EffectSet::full(), tyreOf(*tyre));
      const Gaps rigid = compare(
          *tyre, h, [&] { w.world.stepSimulation(h, 1, h); },
          [&] {
            return Vertical{wheel.body->getCenterOfMassPosition().z(), wheel.body->getLinearVelocity().z()};
          });
      expectImplicit(label("Bullet rigid body, implicit mode, 1 mm linear slop", *tyre, h), rigid, h, *tyre);
    }
  }
  for (const Tyre* tyre : {&kShallow, &kDeep}) {
    for (const double h : kSteps) {
      MultiBodyWheelSim sim(ground, kRadius + tyre->drop, tyreOf(*tyre), ContactMode::kImplicit);
      sim.world.getSolverInfo().m_linearSlop = kSlopM;
      const Gaps g = compare(
          *tyre, h, [&] { sim.world.stepSimulation(h, 1, h); },
          [&] {
            return Vertical{sim.multibody->getBasePos().z(), sim.multibody->getBaseVel().z()};
          });
      expectImplicit(label("Bullet multibody, implicit mode, 1 mm linear slop", *tyre, h), g, h, *tyre);
    }
  }
}

}  // namespace implicit_normal_row_test
}  // namespace wtc::testing
