// Hard cases of the tyre model in both engines (issue 11), each against an
// answer derived elsewhere. The open ones are disabled: they fail today,
// and say by how much when run:
//   build/tests/cross_engine/wtc_cross_engine_tests --gtest_also_run_disabled_tests --gtest_filter='HardCases*'
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <initializer_list>
#include <iostream>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "engine_sim.hpp"
#include "multibody_wheel_sim.hpp"
#include "wheel_sim.hpp"
#include "wtc/base/constants.hpp"
#include "wtc/io/terrain_file.hpp"
#include "wtc/terrain/terrain_primitives.hpp"
#include "wtc/tyre/traction_law.hpp"

namespace wtc::testing {
namespace hard_cases_test {

constexpr double kRadius = 0.19;  // r_f of the robot's wheel (m)
// The three contact modes (contact_mode.hpp): a hard case holds in each.
constexpr ContactMode kEveryMode[] = {ContactMode::kForce, ContactMode::kConstraint, ContactMode::kImplicit};

// Issue 11, defect 1: a free wheel rolling slowly on flat ground comes to
// rest, in every engine and mode: rolling resistance alone decelerates it
// at f_r g r_0 / (r_f (1 + I / (m r_f^2))) (0.12 m/s^2 for a disc: 5 cm/s
// gone in under half a second). The tread's caps were set for the wheel's
// mass, but in the rolling direction the contact moves only
// 1 / (1/m + r_f^2/I) (m/3 for a disc): force mode chattered (at 2 ms,
// 3.7 kg: 1272 sign changes of the speed in 3 s, 1.7 mm/s left). The
// plugins read m and I from the body. A 3.7 kg wheel, a 21 kg one, and a
// 3.7 kg wheel carrying 17.3 kg on its axle; 0.4, 1 and 2 ms.
TEST(HardCasesTest, AFreeWheelRollingSlowlyComesToRest) {
  constexpr double kStartMps = 0.05, kSeconds = 3.0, kRestMps = 1e-3, kNoiseMps = 1e-5;
  struct Load {
    double mass, carried;  // (kg)
  };
  const Terrain ground = flatGround();
  for (const Engine engine : {Engine::kBullet, Engine::kOde}) {
    for (const ContactMode mode : kEveryMode) {
      for (const Load load : {Load{3.7, 0.0}, Load{21.0, 0.0}, Load{3.7, 17.3}}) {
        for (const double h : {4e-4, 1e-3, 2e-3}) {
          const double deflection = (load.mass + load.carried) * kGravityMps2 / 1e5;
          auto sim = makeEngineSim(engine, mode, ground, load.mass, {0, 0, kRadius - deflection}, Hold::kUpright);
          sim->setMotion({kStartMps, 0, 0}, kStartMps / (kRadius - deflection));
          int sign_changes = 0;
          double last = kStartMps, tail_max = 0.0;
          const long steps = std::lround(kSeconds / h);
          for (long k = 0; k < steps; ++k) {
            sim->push({0, 0, -load.carried * kGravityMps2}, 0.0);
            sim->step(h);
            const double v = sim->velocity().x();
            if (std::abs(v) > kNoiseMps) {  // a sign change of a speed that is really there
              if (v * last < 0.0) ++sign_changes;
              last = v;
            }
            if (k > steps / 2) tail_max = std::max(tail_max, std::abs(v));
          }
          const std::string label = engineName(engine) + " " + std::string(contactModeName(mode)) + ", " +
                                    std::to_string(load.mass) + " kg carrying " + std::to_string(load.carried) +
                                    " kg, h = " + std::to_string(h);
          EXPECT_LT(tail_max, kRestMps) << label;
          EXPECT_LT(sign_changes, 10) << label;
        }
      }
    }
  }
}

// Issue 11, defect 2: constraint mode exists for large steps, so a parked
// wheel must hold there as well as at 1 ms. A locked 21 kg wheel on 15 deg
// (mu_max 0.8), both engines, from where it is put down, 10 s: the creep in
// mm at 1 / 10 / 50 / 100 ms. The tread spring's explicit-stability cap
// k_t <= (kappa/h)^2 m also ran in constraint mode, where nothing
// integrates the spring explicitly, so the relaxation length grew as h^2:
// 1.07 / 2.39 / 108 / 431. Without the cap: 1.07 / 1.07 / 6.35 / 25.4; with
// the tread's sticking state (defect 6) 0.68 / 0.66 / 6.35 / 25.4, the
// first steps sliding while the empty tread state loaded up: the engine's
// friction coefficient was the state's, zero when the wheel is put down
// (g sin(15 deg) h^2 at 50 and 100 ms). With the sticking limit given to
// the engine at rest: 0 in Bullet, 55 nm in ODE, at every step.
double parkedCreep(Engine engine, ContactMode mode, const std::function<double(long)>& step_of) {
  constexpr double kSlope = 15.0 * std::numbers::pi / 180.0, kMass = 21.0, kParkedS = 10.0;
  const Terrain incline = tiltedSlab(kSlope);
  const double deflection = kMass * kGravityMps2 * std::cos(kSlope) / 1e5;
  auto sim = makeEngineSim(engine, mode, incline, kMass, (kRadius - deflection) * slabNormal(kSlope), Hold::kLocked);
  const Eigen::Vector3d start = sim->position();
  double t = 0.0;
  for (long k = 0; t < kParkedS - 1e-9; ++k) {
    const double h = step_of(k);
    sim->step(h);
    t += h;
  }
  return std::abs((sim->position() - start).dot(downhill(kSlope)));
}
double parkedCreep(Engine engine, double h) {
  return parkedCreep(engine, ContactMode::kConstraint, [h](long) { return h; });
}

constexpr double kParkedHoldM = 1e-6;  // a parked wheel holds within a micrometre

void expectHoldsAtEveryStep(std::initializer_list<double> steps) {
  for (const Engine engine : {Engine::kBullet, Engine::kOde}) {
    for (const double h : steps) {
      const double creep = parkedCreep(engine, h);
      ::testing::Test::RecordProperty(
          engineName(engine) + "_creep_mm_at_" + std::to_string(std::lround(h * 1e3)) + "ms",
          std::to_string(creep * 1e3));
      EXPECT_LT(creep, kParkedHoldM) << engineName(engine) << ", h = " << h << " s: " << creep * 1e3 << " mm";
    }
  }
}

TEST(HardCasesTest, AParkedWheelHoldsInConstraintModeAtLargeSteps) { expectHoldsAtEveryStep({1e-3, 2e-3, 5e-3, 1e-2}); }

TEST(HardCasesTest, AParkedWheelHoldsInConstraintModeAtVeryLargeSteps) { expectHoldsAtEveryStep({5e-2, 1e-1}); }

// Issue 11, defect 4: a soft tyre keeps its spring at any depth. Bullet's
// split impulse (on by default, threshold -0.04 m) turns a contact deeper
// than 4 cm into a position-only push-out that no longer acts as
// c Z + b v_z. A 21 kg wheel on a tyre of c = 5e3 N/m rests at
// Z = m g / c = 41.2 mm (statics), in every engine and mode, at 0.4 and
// 2 ms, after it was put down 2 cm too high (a hard landing crosses the
// threshold on its way).
TEST(HardCasesTest, ASoftTyreRestsAtItsStaticDeflectionInEveryEngineAndMode) {
  constexpr double kMass = 21.0, kSoftNpm = 5e3, kSettleS = 3.0;
  TyreParameters tyre;
  tyre.radial_stiffness = kSoftNpm;
  tyre.radial_damping = 2.0 * std::sqrt(kSoftNpm * kMass);  // critical: it settles within the run
  const double expected = kMass * kGravityMps2 / kSoftNpm;
  const Terrain ground = flatGround();
  for (const Engine engine : {Engine::kBullet, Engine::kOde}) {
    for (const ContactMode mode : kEveryMode) {
      for (const double h : {4e-4, 2e-3}) {
        auto sim = makeEngineSim(engine, mode, ground, kMass, {0, 0, kRadius + 0.02}, Hold::kLocked, tyre);
        for (long k = 0; k < std::lround(kSettleS / h); ++k) sim->step(h);
        const double deflection = kRadius - sim->position().z();
        RecordProperty(engineName(engine) + "_" + std::string(contactModeName(mode)) + "_" +
                           std::to_string(std::lround(h * 1e4)) + "e-4s_deflection_mm",
                       std::to_string(deflection * 1e3));
        EXPECT_NEAR(deflection, expected, 0.01 * expected)
            << engineName(engine) << ", " << contactModeName(mode) << ", h = " << h << ": " << deflection * 1e3
            << " mm, statics " << expected * 1e3 << " mm";
      }
    }
  }
}

// Issue 11, defect 7: in constraint mode the engine's solver, not the
// explicit model, decides the contact forces; the plugins report what it
// applied. Newton's second law checks it: a locked wheel (gravity and the
// contacts only) dropped 1 cm onto flat ground while sliding at 0.5 m/s has
// m (v' - v) / h - m g = the applied contact force at every step, in both
// engines; in implicit mode too (issue 41: the tread's two rows, Bullet's two
// friction directions). The explicit model's forces differ on this landing
// (recorded).
TEST(HardCasesTest, ConstraintModeReportsTheContactForcesTheSolverApplied) {
  constexpr double kMass = 21.0, kH = 1e-3;
  const Eigen::Vector3d gravity(0, 0, -kGravityMps2);
  const Terrain ground = flatGround();
  for (const Engine engine : {Engine::kBullet, Engine::kOde}) {
    for (const ContactMode mode : {ContactMode::kConstraint, ContactMode::kImplicit}) {
      const std::string label = engineName(engine) + ", " + std::string(contactModeName(mode));
      auto sim = makeEngineSim(engine, mode, ground, kMass, {0, 0, kRadius + 0.01}, Hold::kLocked);
      sim->setMotion({0.5, 0, 0}, 0.0);
      double worst = 0.0, model_gap = 0.0, peak = 0.0;
      for (int k = 0; k < 400; ++k) {
        const Eigen::Vector3d before = sim->velocity();
        sim->step(kH);
        const Eigen::Vector3d felt = kMass * ((sim->velocity() - before) / kH - gravity);
        const WheelForces& applied = sim->applied();
        worst = std::max(worst, (applied.force - felt).norm());
        model_gap = std::max(model_gap, (sim->forces().force - felt).norm());
        peak = std::max(peak, felt.norm());
        double sum = 0.0;
        for (const ContactForce& c : applied.contacts) sum += c.normal_force;
        if (!applied.contacts.empty()) {
          EXPECT_NEAR(sum, -applied.force.dot(applied.contacts[0].contact.e), 1e-9 * peak);
        }
      }
      RecordProperty(label + "_explicit_model_error_N", std::to_string(model_gap));
      EXPECT_GT(peak, kMass * kGravityMps2) << label << ": the wheel never landed";
      EXPECT_LT(worst, 1e-6 * peak) << label << ": applied force off Newton's law by " << worst << " N (peak " << peak
                                    << " N; the explicit model's off by " << model_gap << " N)";
    }
  }
}

// Issue 11: the step switched between 0.5 and 3 ms every 7 steps. A locked
// 21 kg wheel parked on 15 deg creeps no more than at the larger of the two
// steps held fixed (within 5 %, or a micrometre), in both engines and modes.
// Measured: force mode 0.7204 / 0.7741 mm at a fixed 0.5 / 3 ms (0.7202 at
// 0.4 ms: the slide while the tread spring loads up as the wheel is put
// down, with the overshoot its elastic unloading keeps), 0.7748 mm
// switching; constraint mode 0 (Bullet) and 55 nm (ODE) either way.
TEST(HardCasesTest, AParkedWheelHoldsWhenTheStepChangesEveryFewSteps) {
  for (const Engine engine : {Engine::kBullet, Engine::kOde}) {
    for (const ContactMode mode : kEveryMode) {
      const std::string label = engineName(engine) + "_" + std::string(contactModeName(mode));
      double fixed = 0.0;
      for (const double h : {5e-4, 3e-3}) {
        const double creep = parkedCreep(engine, mode, [h](long) { return h; });
        RecordProperty(label + "_fixed_creep_mm_at_" + std::to_string(h), std::to_string(creep * 1e3));
        fixed = std::max(fixed, creep);
      }
      const double switching = parkedCreep(engine, mode, [](long k) { return (k / 7) % 2 == 0 ? 5e-4 : 3e-3; });
      RecordProperty(label + "_switching_creep_mm", std::to_string(switching * 1e3));
      EXPECT_LT(switching, std::max(1.05 * fixed, kParkedHoldM))
          << label << ": " << switching * 1e3 << " mm against " << fixed * 1e3 << " mm at a fixed step";
    }
  }
}

// Issue 11: a large step drops the wheel's centre into a thin plate (2 cm,
// nothing under it), nearer its bottom face than its top: the nearest face
// pushed it on through (it fell 40-60 m in 2 s, both engines, both modes).
// It must come out on the side it entered, never go below the plate's top
// again, and (the engine-solved modes) rest on it. h = 20 ms, 10.25 m/s down from
// 5 mm above the plate.
TEST(HardCasesTest, AWheelDroppedIntoAThinPlateComesOutWhereItEntered) {
  constexpr double kMass = 21.0, kH = 0.02, kThick = 0.02;
  TerrainBuilder builder;
  BoxParams plate;
  plate.size = {4.0, 4.0, kThick};
  plate.pose_WL.translation() = Eigen::Vector3d(0, 0, -0.5 * kThick);
  addBox(builder, plate, builder.addMaterial({}));
  const Terrain deck = std::move(builder).build();
  for (const Engine engine : {Engine::kBullet, Engine::kOde}) {
    for (const ContactMode mode : kEveryMode) {
      auto sim = makeEngineSim(engine, mode, deck, kMass, {0, 0, kRadius + 0.005}, Hold::kLocked);
      sim->setMotion({0, 0, -10.25}, 0.0);
      sim->step(kH);
      const double entered = sim->position().z();
      double lowest = 1e9;
      for (int k = 0; k < 150; ++k) {
        sim->step(kH);
        if (k > 0) lowest = std::min(lowest, sim->position().z());
      }
      const std::string label = engineName(engine) + ", " + std::string(contactModeName(mode));
      EXPECT_LT(entered, -0.5 * kThick) << label << ": the centre did not reach the plate's lower half";
      EXPECT_GT(lowest, 0.0) << label << ": after entering at z = " << entered;
      // The engine-solved modes rest on the top; force mode's explicit
      // spring, compressed 0.2 m in one 20 ms step, throws the wheel up (its
      // accuracy at such a step, not its side) and it lands on the top.
      if (mode != ContactMode::kForce) {
        EXPECT_NEAR(sim->position().z(), kRadius - kMass * kGravityMps2 / 1e5, 0.01) << label;
      }
    }
  }
}

// A locked wheel put down sliding at 3.5 m/s on flat ground: where it
// passes 2 m/s (by then its tread has settled to steady sliding: the
// transient from the unloaded tread decays over its relaxation length, 90 mm
// here, and it has slid six of them), where it stops (the farthest point it
// reaches) and how far back from there it is 1 s later.
struct Braking {
  double from = -1.0;   // m, where it passed 2 m/s
  double stop = 0.0;    // m
  double spring = 0.0;  // m, back from the stop at the end
};
constexpr double kBrakingFromMps = 2.0;
Braking brake(Engine engine, ContactMode mode, const Terrain& ground, double h) {
  constexpr double kMass = 21.0, kSpeed = 3.5;
  auto sim = makeEngineSim(engine, mode, ground, kMass, {0, 0, kRadius - kMass * kGravityMps2 / 1e5}, Hold::kLocked);
  sim->setMotion({kSpeed, 0, 0}, 0.0);
  Braking b;
  for (long k = 0; k < std::lround(1.5 / h); ++k) {
    const double before = sim->velocity().x();
    sim->step(h);
    const double v = sim->velocity().x();
    if (b.from < 0.0 && v <= kBrakingFromMps) {  // interpolated within the step
      b.from = sim->position().x() - 0.5 * (kBrakingFromMps - v) * (kBrakingFromMps + v) / ((before - v) / h);
    }
    b.stop = std::max(b.stop, sim->position().x());
  }
  b.spring = b.stop - sim->position().x();
  return b;
}

// A material whose mu(s) falls past its peak (s2 = 4.44: about 2.3 mu_max
// near s = 0.16, falling to mu(1) at the locked wheel's s = 1).
Terrain fallingGround() {
  Material falling;
  falling.name = "falling";
  falling.s2 = 4.44;
  return flatGround(1, falling);
}

// Issue 11: locked-wheel braking on the falling branch of mu(s). From
// 2 m/s, sliding steadily, the wheel stops after v^2 / (2 g mu(1)) within
// 2 %, in both engines and modes, at 1 and 2 ms.
TEST(HardCasesTest, ALockedWheelBrakesOnTheFallingBranch) {
  const Terrain ground = fallingGround();
  const double expected =
      kBrakingFromMps * kBrakingFromMps / (2.0 * kGravityMps2 * tractionCoefficient(ground.materials()[0], 1.0));
  for (const Engine engine : {Engine::kBullet, Engine::kOde}) {
    for (const ContactMode mode : kEveryMode) {
      for (const double h : {1e-3, 2e-3}) {
        const Braking b = brake(engine, mode, ground, h);
        EXPECT_NEAR(b.stop - b.from, expected, 0.02 * expected)
            << engineName(engine) << ", " << contactModeName(mode) << ", h = " << h;
      }
    }
  }
}

// Issue 11: once stopped, a braked wheel springs back no farther than its
// tread's elastic deflection: the sliding force at the stop over k_t,
// mu(1) m g / k_t (1.65 mm on asphalt), what a brush tyre's bristles give
// back. Constraint mode holds it (the engine's friction). Force mode sprang
// back 14 mm on the default asphalt and 82 mm with s2 = 4.44: its tread state
// held the slip's memory sigma s (16 mm at s = 1 for this wheel), and its
// force mu(u / sigma) R_z stayed on after the stop until the wheel had moved
// that far back. The tread now keeps its elastic deflection apart from that
// memory (tyre_kernels.cpp). Measured (both engines, 1 ms): 1.02 mm on
// asphalt, 1.04 mm with s2 = 4.44.
TEST(HardCasesTest, ABrakedWheelSpringsBackNoFartherThanItsTreadsElasticDeflection) {
  constexpr double kMass = 21.0;
  const TyreParameters tyre;
  for (const Terrain& ground : {flatGround(), fallingGround()}) {
    const double elastic =
        tractionCoefficient(ground.materials()[0], 1.0) * kMass * kGravityMps2 / tyre.tangential_stiffness;
    for (const Engine engine : {Engine::kBullet, Engine::kOde}) {
      for (const ContactMode mode : kEveryMode) {
        const double spring = brake(engine, mode, ground, 1e-3).spring;
        const std::string label =
            ground.materials()[0].name + ", " + engineName(engine) + ", " + std::string(contactModeName(mode));
        RecordProperty(label, std::to_string(spring * 1e3) + " mm");
        EXPECT_LT(spring, elastic) << label;
      }
    }
  }
}

// Issue 11: a wheel driven at full torque (100 N m, the robot's drive) up
// an 8 deg incline of mu_max = 0.21 from standstill. It spins, its slip
// saturates the law at mu_max R_z, and it climbs at g (mu_max cos - sin) =
// 0.675 m/s^2 (statics of the sliding contact), never sliding back: the
// mean acceleration over 1 s within 5 %, in both engines and modes, at 0.4
// and 2 ms.
TEST(HardCasesTest, AWheelDrivenAtFullTorqueUpALowFrictionInclineClimbs) {
  constexpr double kSlope = 8.0 * std::numbers::pi / 180.0, kMass = 21.0, kTorque = 100.0, kSeconds = 1.0;
  Material icy;
  icy.name = "icy";
  icy.mu_max = 0.21;
  const Terrain incline = tiltedSlab(kSlope, icy);
  const double expected = kGravityMps2 * (icy.mu_max * std::cos(kSlope) - std::sin(kSlope));
  const double deflection = kMass * kGravityMps2 * std::cos(kSlope) / 1e5;
  for (const Engine engine : {Engine::kBullet, Engine::kOde}) {
    for (const ContactMode mode : kEveryMode) {
      for (const double h : {4e-4, 2e-3}) {
        auto sim =
            makeEngineSim(engine, mode, incline, kMass, (kRadius - deflection) * slabNormal(kSlope), Hold::kUpright);
        const Eigen::Vector3d start = sim->position();
        double lowest = 0.0;
        for (long k = 0; k < std::lround(kSeconds / h); ++k) {
          sim->push(Eigen::Vector3d::Zero(), kTorque);  // +y turns the wheel toward +x: uphill
          sim->step(h);
          lowest = std::min(lowest, -(sim->position() - start).dot(downhill(kSlope)));
        }
        const double travelled = -(sim->position() - start).dot(downhill(kSlope));
        const double mean = 2.0 * travelled / (kSeconds * kSeconds);
        const std::string label =
            engineName(engine) + ", " + std::string(contactModeName(mode)) + ", h = " + std::to_string(h);
        EXPECT_NEAR(mean, expected, 0.05 * expected) << label;
        EXPECT_GT(lowest, -1e-3) << label << ": slid back";
      }
    }
  }
}

// Issue 11: a wheel on a side slope steeper than the tread's limit
// asin(w / 2 r_f) = 18.4 deg touches the ground with a cut cap: the tyre
// gives no force there and the engine collides the cap. Crossing the limit
// must change the support by no more than the tyre's own deflection. Before
// the fix the engine collided the wheel's cylinder of radius r_f, whose rim
// reaches r_f cos + w/2 sin (9 mm past the tread at the limit), and the
// cap contacts came and went with it: a locked 21 kg wheel put down on
// 18.5-21 deg was thrown off (0.36-0.42 m above the slope and 1.2-1.4 m
// away after 2 s). Now the centre rests where the geometry puts it (the
// tread less its static deflection of 2 mm, or the cap's rim), within
// 1.5 mm, and moves less than 5 mm along the slope, in both engines and
// modes, from 18 to 30 deg.
TEST(HardCasesTest, AWheelOnASideSlopePastTheTreadsLimitRestsOnItsCap) {
  constexpr double kMass = 21.0;
  for (const double degrees : {18.0, 18.5, 19.0, 21.0, 30.0}) {
    const double phi = degrees * std::numbers::pi / 180.0;
    TerrainBuilder builder;
    SlabParams slab;
    slab.size_x = slab.size_y = 20.0;
    slab.pose_WL = Eigen::Isometry3d(Eigen::AngleAxisd(phi, Eigen::Vector3d::UnitX()));
    addSlab(builder, slab, builder.addMaterial({}));
    const Terrain side = std::move(builder).build();
    const Eigen::Vector3d n = Eigen::AngleAxisd(phi, Eigen::Vector3d::UnitX()) * Eigen::Vector3d::UnitZ();
    // The centre's height over the slope: on the tread, r_f less the
    // tyre's static deflection; past the limit, on the cap's rim (radius
    // sqrt(r_f^2 - (w/2)^2) at w/2 from the centre), rigid.
    const double half_width = 0.06, rim = std::sqrt(kRadius * kRadius - half_width * half_width);
    const double support = std::sin(phi) * kRadius <= half_width ? kRadius - kMass * kGravityMps2 * std::cos(phi) / 1e5
                                                                 : rim * std::cos(phi) + half_width * std::sin(phi);
    for (const Engine engine : {Engine::kBullet, Engine::kOde}) {
      for (const ContactMode mode : kEveryMode) {
        auto sim = makeEngineSim(engine, mode, side, kMass, (kRadius + 0.002) * n, Hold::kLocked);
        const Eigen::Vector3d start = sim->position();
        for (int k = 0; k < 2000; ++k) sim->step(1e-3);
        const Eigen::Vector3d moved = sim->position() - start;
        const std::string label =
            std::to_string(degrees) + " deg, " + engineName(engine) + ", " + std::string(contactModeName(mode));
        EXPECT_NEAR(sim->position().dot(n), support, 1.5e-3) << label;
        EXPECT_LT((moved - moved.dot(n) * n).norm(), 5e-3) << label;
      }
    }
  }
}

// Time for a driven wheel (21 kg, 10 N m and a 0.3 m g push, as its
// vehicle would) to climb a 6 cm step: from the face's first touch until
// the centre stands r_f past the edge on the top (s), or -1.
// Flat ground with a step of `height` (m) along x = 0.
Terrain groundWithAStep(double height) {
  TerrainBuilder builder;
  LedgeParams step;
  step.height = height;
  addLedge(builder, step, builder.addMaterial({}));
  return std::move(builder).build();
}

double stepClimbTime(Engine engine, ContactMode mode) {
  constexpr double kMass = 21.0, kH = 1e-3, kStep = 0.06;
  const Terrain ground = groundWithAStep(kStep);
  auto sim =
      makeEngineSim(engine, mode, ground, kMass, {-1.0, 0, kRadius - kMass * kGravityMps2 / 1e5}, Hold::kUpright);
  double touch = -1.0;
  for (int k = 0; k < 6000; ++k) {
    sim->push({0.3 * kMass * kGravityMps2, 0, 0}, 10.0);
    sim->step(kH);
    const double t = (k + 1) * kH;
    if (touch < 0.0 && sim->position().x() > -kRadius) touch = t;  // the tread reaches the face (x = 0)
    if (sim->position().x() > kRadius && sim->position().z() > kStep + 0.5 * kRadius) return t - touch;
  }
  return -1.0;
}

// Issue 11, defect 3, in the engines: a 21 kg wheel pushed at its axle at a
// creeping 0.1 m/s (a tug's hitch, held with a 50 ms time constant) climbs a
// kerb, force mode, 1 ms. The largest change of its load (the sum of its
// contacts' R_z) from one step to the next, from the tread's first touch of
// the kerb until the centre is r_f past its edge (N).
constexpr double kCreepMps = 0.1;
double largestLoadStepOnAKerb(Engine engine, double rise) {
  constexpr double kMass = 21.0, kH = 1e-3, kHoldS = 0.05;
  const Terrain ground = groundWithAStep(rise);
  auto sim = makeEngineSim(engine, ContactMode::kForce, ground, kMass, {-0.25, 0, kRadius - kMass * kGravityMps2 / 1e5},
                           Hold::kUpright);
  sim->setMotion({kCreepMps, 0, 0}, kCreepMps / kRadius);
  double previous = -1.0, largest = 0.0;
  for (int k = 0; k < 20000 && sim->position().x() < kRadius; ++k) {
    const double push = std::clamp(kMass * (kCreepMps - sim->velocity().x()) / kHoldS, 0.0, 2 * kMass * kGravityMps2);
    sim->push({push, 0, 0}, 0.0);
    sim->step(kH);
    double load = 0.0;
    for (const ContactForce& c : sim->forces().contacts) load += c.normal_force;
    if (sim->position().x() > -kRadius && previous >= 0.0) largest = std::max(largest, std::abs(load - previous));
    previous = load;
  }
  return largest;
}

// Issue 11, defect 3: the seam rule gave a kerb's edge H / L of its load
// until the edge became the nearer contact, and then all of it: a jump in
// the middle of the climb. Now the largest change in a step is the
// natural one: the damper's b v sin(theta) as the tread first meets the
// edge at theta from the vertical (the centre r_f - Z above the ground),
// and the spring's c v h. Measured, both engines: 22.3 / 30.0 / 41.3 N on
// 5 / 10 / 20 mm kerbs, against 150 / 91 / 41 N before. Issue 40, item 6:
// kerbs lower than the 2 mm deflection (0.5 / 1 / 1.5 mm): once the edge
// became the nearer contact the crease rule cut the ground's patch, 41 N on
// the 0.5 mm kerb; now 14.6 / 15.1 / 16.2 N.
TEST(HardCasesTest, AWheelClimbsKerbsWithoutALoadJump) {
  const TyreParameters tyre;
  const double deflection = 21.0 * kGravityMps2 / tyre.radial_stiffness;
  for (const Engine engine : {Engine::kBullet, Engine::kOde}) {
    for (const double rise : {0.0005, 0.001, 0.0015, 0.005, 0.01, 0.02}) {
      const double below = kRadius - deflection - rise;  // the edge below the centre at first touch (m)
      const double sin_theta = std::sqrt(kRadius * kRadius - below * below) / kRadius;
      const double natural =
          tyre.radial_damping * kCreepMps * sin_theta + tyre.radial_stiffness * kCreepMps * sin_theta * 1e-3;
      const double largest = largestLoadStepOnAKerb(engine, rise);
      RecordProperty(engineName(engine) + "_" + std::to_string(rise), std::to_string(largest) + " N");
      std::printf("%s, %.1f mm kerb: largest load change in a step %.1f N, natural %.1f N\n",
                  engineName(engine).c_str(), rise * 1e3, largest, natural);
      EXPECT_LT(largest, 1.15 * natural) << engineName(engine) << ", " << rise * 1e3 << " mm kerb (N)";
    }
  }
}

// Issue 11: force mode against constraint mode on one transient, a driven
// wheel climbing a 6 cm step (a third of its radius), in both engines. The
// two modes are two models of the same tyre (constraint mode: the engine's
// implicit spring and Coulomb friction within the step); the difference is
// stated, and bounded at 10 %. Measured, both engines: 0.215 s in force
// mode, 0.225 s in constraint mode (+4.7 %).
TEST(HardCasesTest, ForceAndConstraintModeClimbASmallStepInAboutTheSameTime) {
  for (const Engine engine : {Engine::kBullet, Engine::kOde}) {
    const double force = stepClimbTime(engine, ContactMode::kForce);
    const double constraint = stepClimbTime(engine, ContactMode::kConstraint);
    RecordProperty(engineName(engine) + "_force_s", std::to_string(force));
    RecordProperty(engineName(engine) + "_constraint_s", std::to_string(constraint));
    ASSERT_GT(force, 0.0) << engineName(engine) << ": force mode did not climb";
    ASSERT_GT(constraint, 0.0) << engineName(engine) << ": constraint mode did not climb";
    EXPECT_NEAR(constraint, force, 0.10 * force) << engineName(engine);
  }
}

// Issue 11, defect 6: a robot parked for an hour on a slope must stay
// within 1 mm. The spec's law has no force at zero slip, and its
// regularization max(V_t, eps) made the tread relax at eps / sigma even at
// rest: 0.41 mm in 10 s on 15 deg, 0.15 m per hour (0.46 m on 30 deg).
// The tread state now relaxes only as the ground moves under it (rate
// V_t / sigma): at rest it is a spring that holds while the load is below
// the peak of mu(s) R_z (a sticking state). A locked 21 kg wheel on 15 and
// 30 deg, both engines and modes, at 0.4 and 2 ms, after settling for 1 s:
// - held for kHoldS, its creep is below the hour's 1 mm prorated
//   (1 mm x kHoldS / 1 h = 33 um): a creep at a rate, as the old defect's,
//   is a rate from the first minutes on (the old law moved 0.41 mm in 10 s,
//   twelve times this bound), and a creep that slows (a settling's tail)
//   moves less in the hour than the prorated bound assumes;
// - one case, the one that creeps most in kHoldS, is held the whole hour
//   (kHourCase): the hour's 1 mm itself, measured.
// The whole hour in every case (24 of them, 9e6 steps each at 0.4 ms) took
// 7.8 min of the suite and was its longest test by ten times, for no defect
// the prorated bound would miss.
TEST(HardCasesTest, AParkedWheelHoldsForAnHourOn15And30Degrees) {
  constexpr double kMass = 21.0, kHourS = 3600.0, kHoldS = 120.0, kHourCreepM = 1e-3;
  struct Case {
    double degrees;
    Engine engine;
    ContactMode mode;
    double h;
  };
  // The largest creep of the 24 in kHoldS (1.3 um on 30 deg, the same at
  // both steps; Bullet's are 0, ODE's force and implicit modes' 0.05 um: the
  // test prints them), at the larger step (a fifth of the steps). Its hour
  // measured 38.4 um: the 120 s creep times 30, a rate, as the bound assumes.
  const Case kHourCase{30.0, Engine::kOde, ContactMode::kConstraint, 2e-3};
  const auto creepOf = [&](const Case& c, double hold_s) {
    const double slope = c.degrees * std::numbers::pi / 180.0;
    const Terrain incline = tiltedSlab(slope);
    const double deflection = kMass * kGravityMps2 * std::cos(slope) / 1e5;
    auto sim = makeEngineSim(c.engine, c.mode, incline, kMass, (kRadius - deflection) * slabNormal(slope), Hold::kLocked);
    for (long k = 0; k < std::lround(1.0 / c.h); ++k) sim->step(c.h);
    const Eigen::Vector3d start = sim->position();
    for (long k = 0; k < std::lround(hold_s / c.h); ++k) sim->step(c.h);
    return std::abs((sim->position() - start).dot(downhill(slope)));
  };
  for (const double degrees : {15.0, 30.0}) {
    for (const Engine engine : {Engine::kBullet, Engine::kOde}) {
      for (const ContactMode mode : kEveryMode) {
        for (const double h : {4e-4, 2e-3}) {
          const double creep = creepOf({degrees, engine, mode, h}, kHoldS);
          const std::string label = std::to_string(degrees) + " deg, " + engineName(engine) + ", " +
                                    std::string(contactModeName(mode)) + ", h = " + std::to_string(h);
          RecordProperty(label, std::to_string(creep * 1e3) + " mm");
          std::printf("%s: %.3g um in %g s\n", label.c_str(), creep * 1e6, kHoldS);
          EXPECT_LT(creep, kHourCreepM * kHoldS / kHourS) << label << ": " << creep * 1e3 << " mm in " << kHoldS << " s";
        }
      }
    }
  }
  const double hour = creepOf(kHourCase, kHourS);
  RecordProperty("the hour's case", std::to_string(hour * 1e3) + " mm");
  std::printf("30 deg, ODE dWorldStep, constraint, h = 0.002: %.3g um in an hour\n", hour * 1e6);
  EXPECT_LT(hour, kHourCreepM) << hour * 1e3 << " mm in an hour";
}

// Issue 11, defect 9: the modes on a driven scene. wtc_bench_bullet and
// wtc_bench_ode drive wheels across the rough ground of scenario 3 (21 kg,
// 3 N m, dropped from above the highest bumps): after 12 s force mode is at
// 2.42 m/s and constraint mode at 2.07 (Bullet) / 2.10 m/s (ODE), 14 %
// apart. Both are converged in the step (force 2.419 / 2.4205 m/s at 1 /
// 0.1 ms, constraint 2.074 / 2.084), and on flat soil the modes agree to
// four digits (2.967 m/s, the rolling acceleration 0.247 m/s^2). Compared
// where the wheel is, not when, they agree along the path: the 14 % is a
// lag of 1.6 s gathered in the first half metre after the drop, where the
// wheel crawls uphill at 0.1-0.2 m/s near its stall and constraint mode is
// up to 30 % slower (explained below: the tread's compliance at the
// landing; hard-cases.md). From x = -11.4 m on, the speeds
// at the same position agree within 2 % of the final speed (measured: 22
// mm/s at most, at 0.25-0.6 m/s; under 0.9 % above 1 m/s); the lag is recorded.
struct PathSample {
  double t, x, v;  // (s), (m), (m/s)
};
std::vector<PathSample> drivenAcrossRoughGround(Engine engine, ContactMode mode, const TyreParameters& tyre = {},
                                                double kH = 1e-3) {
  constexpr double kSeconds = 12.0, kTorqueNm = 3.0, kSampleS = 0.05;
  static const Terrain ground = io::loadTerrain(WTC_SOURCE_DIR "/terrains/rough_ground.yaml");
  auto sim = makeEngineSim(engine, mode, ground, 21.0, {-12.0, -3.75, 0.15 + kRadius + 0.05}, Hold::kUpright, tyre);
  std::vector<PathSample> path;
  const long steps = std::lround(kSeconds / kH), every = std::lround(kSampleS / kH);
  for (long k = 1; k <= steps; ++k) {
    sim->push(Eigen::Vector3d::Zero(), kTorqueNm);
    sim->step(kH);
    if (k % every == 0) path.push_back({static_cast<double>(k) * kH, sim->position().x(), sim->velocity().x()});
  }
  return path;
}
double speedAt(const std::vector<PathSample>& path, double x) {  // linear between samples; the path moves on
  for (std::size_t i = 1; i < path.size(); ++i) {
    if (path[i].x >= x) {
      const double w = (x - path[i - 1].x) / (path[i].x - path[i - 1].x);
      return path[i - 1].v + w * (path[i].v - path[i - 1].v);
    }
  }
  return path.back().v;
}
double timeTo(const std::vector<PathSample>& path, double x) {
  for (const PathSample& sample : path) {
    if (sample.x >= x) return sample.t;
  }
  return std::numeric_limits<double>::infinity();
}

TEST(HardCasesTest, ForceAndConstraintModeAgreeAlongADrivenRoughGroundPath) {
  // From where the crawl is over to the end both reach; a speed difference
  // a fiftieth of the run's final speed (the 2 %).
  constexpr double kFromX = -11.4, kAgreementMps = 0.02 * 2.42;
  for (const Engine engine : {Engine::kBullet, Engine::kOde}) {
    const std::vector<PathSample> force = drivenAcrossRoughGround(engine, ContactMode::kForce);
    const std::vector<PathSample> constraint = drivenAcrossRoughGround(engine, ContactMode::kConstraint);
    const double to_x = std::min(force.back().x, constraint.back().x);
    ASSERT_GT(to_x, -5.0) << engineName(engine);
    double worst = 0.0, worst_fast = 0.0;  // (m/s); relative where faster than 1 m/s
    for (double x = kFromX; x <= to_x; x += 0.05) {
      const double vf = speedAt(force, x), vc = speedAt(constraint, x);
      worst = std::max(worst, std::abs(vc - vf));
      if (vf > 1.0) worst_fast = std::max(worst_fast, std::abs(vc - vf) / vf);
      EXPECT_NEAR(vc, vf, kAgreementMps) << engineName(engine) << " at x = " << x << " m";
    }
    RecordProperty(engineName(engine) + "_worst_speed_difference_mps", std::to_string(worst));
    RecordProperty(engineName(engine) + "_worst_relative_above_1mps", std::to_string(worst_fast));
    RecordProperty(engineName(engine) + "_lag_to_x_-10_s",
                   std::to_string(timeTo(constraint, -10.0) - timeTo(force, -10.0)));
  }
}

// A wheel resting in a shallow concave crease (a V of two prisms whose
// flanks rise 1 deg) has two contacts 6.6 mm apart, the second with the
// crease's share (r - Z) sin(1 deg) / L = 0.12 (wheel_contact.hpp): their
// springs act in parallel, so the wheel rests at m g / (c (1 + 0.12)).
// Bullet merges contacts that close into one manifold point, keeping the
// later one's; the plugin makes that point hold both springs. Before, the
// point kept the second contact's 0.12 share alone, and Bullet's wheel sank
// past the test's 5 % (it fails with mergedContact left out). Measured
// with it: 1.832-1.837 mm in every engine and mode, 1.832 mm expected.
TEST(HardCasesTest, AWheelInAShallowCreaseRestsOnBothItsContactsInEveryEngine) {
  constexpr double kSlope = std::numbers::pi / 180.0, kMass = 21.0, kSettleS = 1.0, kH = 4e-4;
  const Terrain ground = valley(kSlope);
  const TyreParameters tyre;
  // The force-mode equilibrium: c Z (1 + share) = m g, share at that Z.
  double z = kMass * kGravityMps2 / tyre.radial_stiffness;
  for (int i = 0; i < 50; ++i) {
    const double share = (kRadius - z) * std::sin(kSlope) / std::sqrt(2.0 * kRadius * z);
    z = kMass * kGravityMps2 / (tyre.radial_stiffness * (1.0 + std::min(share, 1.0)));
  }
  const auto expectRests = [&](const std::string& what, double centre_height) {
    const double deflection = kRadius - centre_height * std::cos(kSlope);  // to each flank
    RecordProperty(what + "_deflection_mm", std::to_string(deflection * 1e3));
    EXPECT_NEAR(deflection, z, 0.05 * z) << what << ": expected " << z * 1e3 << " mm";
  };
  for (const Engine engine : {Engine::kBullet, Engine::kOde}) {
    for (const ContactMode mode : {ContactMode::kConstraint, ContactMode::kImplicit}) {
      auto sim = makeEngineSim(engine, mode, ground, kMass, {0, 0, kRadius}, Hold::kLocked);
      for (long k = 0; k < std::lround(kSettleS / kH); ++k) sim->step(kH);
      expectRests(engineName(engine) + ", " + std::string(contactModeName(mode)), sim->position().z());
    }
  }
  for (const ContactMode mode : {ContactMode::kConstraint, ContactMode::kImplicit}) {
    MultiBodyWheelSim sim(ground, kRadius, tyre, mode);
    for (long k = 0; k < std::lround(kSettleS / kH); ++k) sim.world.stepSimulation(kH, 1, kH);
    expectRests("Bullet multibody, " + std::string(contactModeName(mode)), sim.multibody->getBasePos().z());
  }
}

// Three contacts in one manifold point: a wheel resting in a shallow trough
// (a 4 mm floor between two flanks rising 1 deg) touches the floor and both
// flanks within 3.3 mm, and Bullet merges all three into one point. The
// point must hold the three springs, as the model's forces do: the wheel
// rests where force mode's does, in each engine and engine-solved mode.
// Before, a third contact was merged with the first contact alone, and the
// second's spring was dropped.
TEST(HardCasesTest, AWheelOnThreeContactsInOneManifoldPointRestsOnAllThree) {
  constexpr double kMass = 21.0, kSettleS = 1.0, kH = 4e-4, kFloorWidth = 0.004;
  constexpr double kSlope = std::numbers::pi / 180.0;
  constexpr double kTolerance = 0.01;  // of the deflection: the V's test agrees to 0.3 %
  const Terrain ground = trough(kSlope, kFloorWidth);
  const auto restingDeflection = [&](Engine engine, ContactMode mode) {
    auto sim = makeEngineSim(engine, mode, ground, kMass, {0, 0, kRadius}, Hold::kLocked);
    for (long k = 0; k < std::lround(kSettleS / kH); ++k) sim->step(kH);
    EXPECT_EQ(sim->forces().contacts.size(), 3u) << engineName(engine) << ", " << contactModeName(mode);
    return kRadius - sim->position().z();
  };
  const double expected = restingDeflection(Engine::kOde, ContactMode::kForce);
  for (const Engine engine : {Engine::kBullet, Engine::kOde}) {
    for (const ContactMode mode : {ContactMode::kConstraint, ContactMode::kImplicit}) {
      const std::string what = engineName(engine) + ", " + std::string(contactModeName(mode));
      const double deflection = restingDeflection(engine, mode);
      RecordProperty(what + "_deflection_mm", std::to_string(deflection * 1e3));
      EXPECT_NEAR(deflection, expected, kTolerance * expected)
          << what << ": force mode rests at " << expected * 1e3 << " mm";
    }
  }
}

// Issue 41: implicit mode is the tyre model, tread included, solved by the
// engine: on the same run at the source's 0.4 ms it ends within 1 % of force
// mode's final speed (constraint mode: 14 % below), and agrees along the
// whole path, the crawl after the landing included. In ODE's two steppers
// and Bullet's rigid-body solver (wtc::bullet::RigidContactSolver).
TEST(HardCasesTest, ImplicitModeEndsTheDrivenRoughGroundRunWithForceMode) {
  constexpr double kH = 4e-4;
  for (const Engine engine : {Engine::kBullet, Engine::kOde, Engine::kOdeQuick}) {
    const std::vector<PathSample> force = drivenAcrossRoughGround(engine, ContactMode::kForce, {}, kH);
    const std::vector<PathSample> implicit = drivenAcrossRoughGround(engine, ContactMode::kImplicit, {}, kH);
    const double final_gap = std::abs(implicit.back().v - force.back().v) / force.back().v;
    double worst = 0.0;  // m/s, at the same time
    for (std::size_t i = 0; i < std::min(force.size(), implicit.size()); ++i) {
      worst = std::max(worst, std::abs(implicit[i].v - force[i].v));
    }
    RecordProperty(engineName(engine) + "_final_speed_force_mps", std::to_string(force.back().v));
    RecordProperty(engineName(engine) + "_final_speed_implicit_mps", std::to_string(implicit.back().v));
    RecordProperty(engineName(engine) + "_worst_speed_difference_mps", std::to_string(worst));
    std::cout << engineName(engine) << ": final speed force " << force.back().v << " m/s, implicit "
              << implicit.back().v << " m/s (" << final_gap * 100 << " %); worst difference at one time " << worst
              << " m/s\n";
    EXPECT_LT(final_gap, 0.01) << engineName(engine);
  }
}

// Issue 11, defect 9: where the lag comes from. The spinning wheel lands
// slipping, and for the 40 ms of its first bounce the tread pushes it
// forward: in force mode through the tread's tangential spring k_t, which
// gives the force back at k_t per metre of slip once the slip has turned
// (about 2 mm for the landing's 230 N); in constraint mode through the
// engine's friction, a rigid constraint that gives it back at once. Force
// mode leaves the bounce at +0.065 m/s, constraint mode at -0.015 m/s, and
// near its stall the wheel keeps that start. A stiffer tread brings force
// mode to constraint mode: the lag to x = -10 m, in Bullet, is 1.55 / 1.19 /
// 0.45 s with k_t = 1e5 / 3e5 / 1e6 N/m (sampled every 50 ms). The modes
// differ by the tread's compliance, which constraint mode's friction does
// not have.
TEST(HardCasesTest, TheModesLagOnTheRoughGroundShrinksAsTheTreadStiffens) {
  std::vector<double> lags;
  for (const double stiffness : {1e5, 1e6}) {
    TyreParameters tyre;
    tyre.tangential_stiffness = stiffness;
    const double lag = timeTo(drivenAcrossRoughGround(Engine::kBullet, ContactMode::kConstraint, tyre), -10.0) -
                       timeTo(drivenAcrossRoughGround(Engine::kBullet, ContactMode::kForce, tyre), -10.0);
    RecordProperty("lag_s_at_k_t_" + std::to_string(stiffness), std::to_string(lag));
    lags.push_back(lag);
  }
  EXPECT_GT(lags[0], 1.0);
  EXPECT_LT(lags[1], 0.35 * lags[0]);
}

}  // namespace hard_cases_test
}  // namespace wtc::testing
