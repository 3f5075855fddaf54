// Implicit mode (issue 41): the engine solves the tread's rows the tyre
// model gave (wtc::TreadRows), and the mode tends to force mode as the step
// shrinks.
//
// Each row i of a contact pushes the wheel along its direction t_i by
//   R_i = K_i (v_i - V_i+),   |R_i| <= limit_i R_z,
// V_i+ = V_P+ . t_i, V_P+ the velocity after the step of the wheel's
// material point at the contact. Whatever else acts in the step (gravity,
// a push, the normal row, the other row), a solver that solved the row
// leaves that relation between the force it applied and the velocity it
// reached, or the force on its bound. Checked every step for ODE's two
// steppers (the wheel's rotation locked: V_P = V_O), Bullet's multibody
// solver (a wheel link spinning on a base too heavy to turn:
// V_P = V_O + omega x OP), and a driven btRigidBody wheel (upright) in
// Bullet's two solvers as WTC's (wtc::bullet::RigidContactSolver, and
// wtc::bullet::ContactSolver in a multibody world). Run:
//   build/tests/cross_engine/wtc_cross_engine_tests --gtest_filter='ImplicitTreadRow*'
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <string>

#include "bullet_fixture.hpp"
#include "engine_sim.hpp"
#include "multibody_wheel_sim.hpp"
#include "wheel_sim.hpp"
#include "wtc/bullet/rigid_contact_solver.hpp"

namespace wtc::testing {
namespace implicit_tread_row_test {

constexpr double kRadius = MultiBodyWheelSim::kRadius;
constexpr double kMass = MultiBodyWheelSim::kMass;
constexpr double kSettleSeconds = 0.3, kRunSeconds = 0.6;
// A row off its bound by less than this fraction of the bound is on it.
constexpr double kOnBoundRelative = 1e-6;

// What a run gives: the largest |R_i - K_i (v_i - V_i+)| over the rows off
// their bounds, relative to the load R_z (dimensionless), and how many row
// steps were off and on their bounds.
struct RowGaps {
  double worst = 0.0;
  long free = 0, bounded = 0;
};

// One step's check of every row of every contact: `model` the tyre model's
// contacts (rows, P, e), `applied` what the solver applied, `point_velocity`
// V_P+ at a point.
void checkRows(const WheelForces& model, const WheelForces& applied,
               const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& point_velocity, RowGaps& gaps) {
  ASSERT_EQ(model.contacts.size(), applied.contacts.size());
  for (std::size_t k = 0; k < model.contacts.size(); ++k) {
    const ContactForce& c = model.contacts[k];
    const TreadRows& rows = c.tread_rows;
    // Every solver bounds a row by the solved normal force (Bullet's
    // multibody rows through wtc::bullet::ContactSolver); a row at the
    // smaller of that and the model's is counted as on its bound.
    const double load = applied.contacts[k].normal_force;
    if (!(load > 0.0)) continue;
    const double bounding_load = std::min(load, c.normal_force);
    const Eigen::Vector3d directions[2] = {rows.direction, rows.direction.cross(c.contact.e)};
    const Eigen::Vector3d v = point_velocity(c.contact.point);
    for (int i = 0; i < 2; ++i) {
      if (!(rows.damping[i] > 0.0)) continue;
      const double force = applied.contacts[k].tangential_force.dot(directions[i]);
      const double bound = rows.limit[i] * bounding_load;
      if (std::abs(force) >= (1.0 - kOnBoundRelative) * bound) {
        ++gaps.bounded;
        continue;
      }
      ++gaps.free;
      const double expected = rows.damping[i] * (rows.velocity[i] - v.dot(directions[i]));
      gaps.worst = std::max(gaps.worst, std::abs(force - expected) / load);
    }
  }
}

// Prints and records a run's gaps, and expects rows off their bounds, each
// within `tolerance` of R_z.
void expectRowsHeld(const std::string& what, const RowGaps& g, double tolerance) {
  std::cout << what << ": worst |R - K (v - V+)| / R_z " << g.worst << " over " << g.free << " free row steps ("
            << g.bounded << " on their bound)\n";
  ::testing::Test::RecordProperty(what + " worst_over_load", std::to_string(g.worst));
  EXPECT_GT(g.free, 0) << what;
  EXPECT_LT(g.worst, tolerance) << what;
}

// A rigid body's velocity at a point p (Bullet's vectors): v + w x (p - c).
std::function<Eigen::Vector3d(const Eigen::Vector3d&)> rigidVelocityAt(const btVector3& velocity, const btVector3& spin,
                                                                       const btVector3& centre) {
  return [=](const Eigen::Vector3d& p) {
    const btVector3 v = velocity + spin.cross(btVector3(p.x(), p.y(), p.z()) - centre);
    return Eigen::Vector3d(v.x(), v.y(), v.z());
  };
}

// The wheel settles on flat ground, then slides off at (0.05, 0.03) m/s
// under a push of (60, -40) N: the rows load, stick, and (at large steps)
// slide, in every combination.
const Eigen::Vector3d kPush{60.0, -40.0, 0.0};

TEST(ImplicitTreadRowTest, OdeSolvesTheRowsTheModelGave) {
  const Terrain ground = flatGround();
  for (const Engine engine : {Engine::kOde, Engine::kOdeQuick}) {
    for (const double h : {4e-4, 2e-3, 1e-2}) {
      auto sim = makeEngineSim(engine, ContactMode::kImplicit, ground, kMass, {0, 0, kRadius}, Hold::kLocked);
      for (long k = 0; k < std::lround(kSettleSeconds / h); ++k) sim->step(h);
      sim->setMotion({0.05, 0.03, sim->velocity().z()}, 0.0);
      RowGaps gaps;
      for (long k = 0; k < std::lround(kRunSeconds / h); ++k) {
        sim->push(kPush, 0.0);
        sim->step(h);
        const Eigen::Vector3d v = sim->velocity();
        checkRows(
            sim->forces(), sim->applied(), [&](const Eigen::Vector3d&) { return v; }, gaps);
      }
      // dWorldStep's Dantzig LCP solves to round-off, but the joint that
      // locks the rotation has ODE's world CFM (1e-10): the wheel turns by
      // what that lets through. QuickStep's 20 iterations leave a residual.
      expectRowsHeld(engineName(engine) + ", h = " + std::to_string(h * 1e3) + " ms", gaps,
                     engine == Engine::kOde ? 1e-7 : 1e-4);
    }
  }
}

TEST(ImplicitTreadRowTest, BulletsMultiBodySolverSolvesTheRowsTheModelGave) {
  const Terrain ground = flatGround();
  for (const double h : {4e-4, 2e-3, 1e-2}) {
    MultiBodyWheelSim sim(ground, kRadius, TyreParameters{}, ContactMode::kImplicit, 1e9);
    // Gauss-Seidel to convergence: the row's fixed point is what is checked.
    sim.world.getSolverInfo().m_numIterations = 2000;
    sim.world.getSolverInfo().m_leastSquaresResidualThreshold = 0.0;
    btMultiBody& body = *sim.multibody;
    const auto step = [&] { sim.world.stepSimulation(h, 1, h); };
    for (long k = 0; k < std::lround(kSettleSeconds / h); ++k) step();
    body.setBaseVel(btVector3(0.05, 0.03, body.getBaseVel().z()));
    RowGaps gaps;
    for (long k = 0; k < std::lround(kRunSeconds / h); ++k) {
      body.addBaseForce(btVector3(kPush.x(), kPush.y(), kPush.z()));
      const btVector3 centre = body.getBasePos();
      step();
      const btVector3 velocity = body.getBaseVel(), spin = body.getBaseOmega() + btVector3(0, body.getJointVel(0), 0);
      checkRows(sim.plugin->forces(0), sim.plugin->applied(0), rigidVelocityAt(velocity, spin, centre), gaps);
    }
    expectRowsHeld("Bullet multibody, h = " + std::to_string(h * 1e3) + " ms", gaps, 1e-6);
  }
}

// A btRigidBody wheel, upright (it spins about its axle, y, only), in a World whose
// solver is Solver; the plugin in implicit mode. The body added to the world
// first is the manifold's body 0 (Bullet orders a pair by its proxies'
// ids): `wheel_first` puts the wheel there, else the terrain. Members in
// construction order: the plugin goes first, then the wheel, then the world.
template <class Solver, class World>
struct RigidWheelWorld {
  RigidWheelWorld(const Terrain& ground, bool wheel_first) {
    world.setGravity(btVector3(0, 0, -kGravityMps2));
    if (wheel_first) wheel = std::make_unique<BulletWheel>(world, kMass, btVector3(0, 0, kRadius));
    plugin = std::make_unique<bullet::Plugin>(world, ground, ContactMode::kImplicit);
    if (!wheel_first) wheel = std::make_unique<BulletWheel>(world, kMass, btVector3(0, 0, kRadius));
    wheel->body->setAngularFactor(btVector3(0, 1, 0));
    bullet::RigidWheel spec;
    spec.body = wheel->body.get();
    plugin->addWheel(spec);
  }
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  Solver solver;
  World world{&dispatcher, &broadphase, &solver, &config};
  std::unique_ptr<BulletWheel> wheel;
  std::unique_ptr<bullet::Plugin> plugin;
};

// The rigid wheel is driven too: Bullet measures a friction row's velocity
// without the torque's impulse (rigid_tread_rows.cpp), which the rows must
// take in (N m).
constexpr double kRigidDriveTorqueNm = 20.0;

template <class Solver, class World>
void expectBulletSolvesTheRigidWheelsRows(const std::string& name) {
  const Terrain ground = flatGround();
  for (const bool wheel_first : {false, true}) {
    for (const double h : {4e-4, 2e-3, 1e-2}) {
      RigidWheelWorld<Solver, World> sim(ground, wheel_first);
      // Gauss-Seidel to convergence: the row's fixed point is what is checked.
      sim.world.getSolverInfo().m_numIterations = 2000;
      sim.world.getSolverInfo().m_leastSquaresResidualThreshold = 0.0;
      btRigidBody& body = *sim.wheel->body;
      const auto step = [&] { sim.world.stepSimulation(h, 1, h); };
      for (long k = 0; k < std::lround(kSettleSeconds / h); ++k) step();
      body.setLinearVelocity(btVector3(0.05, 0.03, body.getLinearVelocity().z()));
      RowGaps gaps;
      for (long k = 0; k < std::lround(kRunSeconds / h); ++k) {
        body.applyCentralForce(btVector3(kPush.x(), kPush.y(), kPush.z()));
        body.applyTorque(btVector3(0, kRigidDriveTorqueNm, 0));
        const btVector3 centre = body.getCenterOfMassPosition();
        step();
        const btVector3 velocity = body.getLinearVelocity(), spin = body.getAngularVelocity();
        checkRows(sim.plugin->forces(0), sim.plugin->applied(0), rigidVelocityAt(velocity, spin, centre), gaps);
      }
      expectRowsHeld(
          name + (wheel_first ? ", wheel as body 0" : ", wheel as body 1") + ", h = " + std::to_string(h * 1e3) + " ms",
          gaps, 1e-6);
    }
  }
}

TEST(ImplicitTreadRowTest, BulletsRigidBodySolverSolvesTheRowsTheModelGave) {
  expectBulletSolvesTheRigidWheelsRows<bullet::RigidContactSolver, btDiscreteDynamicsWorld>(
      "Bullet rigid body (RigidContactSolver)");
}

TEST(ImplicitTreadRowTest, BulletsMultiBodySolverSolvesARigidWheelsRows) {
  expectBulletSolvesTheRigidWheelsRows<bullet::ContactSolver, btMultiBodyDynamicsWorld>(
      "Bullet rigid body in a multibody world (ContactSolver)");
}

// A driven wheel: 21 kg on one contact, its spin free about its axle,
// driven from rest by 25 N m for 1 s (131 N at the tread, 0.64 of its
// load: on the slip law's rising part, where the law's curvature matters). Implicit mode's travel against
// force mode's at 0.05 ms (the reference): the gap shrinks with the step,
// and at 0.4 ms it is within 1 % of the travel (force mode's own gap at
// 0.4 ms is the scale of what the step costs both).
struct Drive {
  double travel = 0.0;  // m
};

template <class Run>
void expectTendsToForceMode(const std::string& engine, Run run) {
  constexpr double kReferenceStep = 5e-5;
  const Drive reference = run(ContactMode::kForce, kReferenceStep);
  double last_gap = std::numeric_limits<double>::infinity();
  for (const double h : {1e-2, 2e-3, 4e-4, 1e-4}) {
    const Drive implicit = run(ContactMode::kImplicit, h), force = run(ContactMode::kForce, h);
    const double gap = std::abs(implicit.travel - reference.travel) / reference.travel;
    const double force_gap = std::abs(force.travel - reference.travel) / reference.travel;
    const std::string what = engine + ", h = " + std::to_string(h * 1e3) + " ms";
    std::cout << what << ": travel " << implicit.travel << " m (force mode " << force.travel << ", reference "
              << reference.travel << "); gap to the reference " << gap * 100 << " % (force mode " << force_gap * 100
              << " %)\n";
    ::testing::Test::RecordProperty(what + " travel_gap_percent", std::to_string(gap * 100));
    EXPECT_TRUE(std::isfinite(implicit.travel)) << what;
    if (h <= 2e-3) {
      EXPECT_LT(gap, last_gap) << what << ": the gap grows as the step shrinks";
    }
    if (h <= 4e-4) {
      EXPECT_LT(gap, 0.01) << what;
    }
    last_gap = gap;
  }
}

constexpr double kDriveTorqueNm = 25.0, kDriveSeconds = 1.0;

TEST(ImplicitModeTest, ADrivenWheelTendsToForceModeAsTheStepShrinks) {
  const Terrain ground = flatGround();
  for (const Engine engine : {Engine::kOde, Engine::kOdeQuick}) {
    expectTendsToForceMode(engineName(engine), [&](ContactMode mode, double h) {
      auto sim = makeEngineSim(engine, mode, ground, kMass, {0, 0, kRadius - 0.002}, Hold::kUpright);
      const double x0 = sim->position().x();
      for (long k = 0; k < std::lround(kDriveSeconds / h); ++k) {
        sim->push(Eigen::Vector3d::Zero(), kDriveTorqueNm);
        sim->step(h);
      }
      return Drive{sim->position().x() - x0};
    });
  }
  expectTendsToForceMode("Bullet multibody", [&](ContactMode mode, double h) {
    MultiBodyWheelSim sim(ground, kRadius - 0.002, TyreParameters{}, mode);
    const double x0 = sim.multibody->getBasePos().x();
    for (long k = 0; k < std::lround(kDriveSeconds / h); ++k) {
      sim.multibody->addJointTorque(0, kDriveTorqueNm);
      sim.world.stepSimulation(h, 1, h);
    }
    return Drive{sim.multibody->getBasePos().x() - x0};
  });
}

}  // namespace implicit_tread_row_test
}  // namespace wtc::testing
