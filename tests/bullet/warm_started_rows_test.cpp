// The Bullet engine's drive and joint bounds (plugins/bullet/sim/src:
// WarmStartedMotor, WarmStartedJointLimit) against Bullet's own
// btMultiBodyJointMotor and btMultiBodyJointLimitConstraint: the same rows,
// so the same motion and effort, to the solver's convergence.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <tuple>
#include <vector>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointLimitConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <btBulletDynamicsCommon.h>

#include "warm_started_joint_limit.hpp"
#include "warm_started_motor.hpp"

namespace {

constexpr double kStepS = 1e-3;

// An arm on a fixed base, turning about y, with a wheel at its tip (also
// about y) and a slider along the arm beyond the wheel: both joint types,
// each driven, in gravity. The drives are Bullet's motors or
// WarmStartedMotor; the arm and the slider have bounds, Bullet's
// btMultiBodyJointLimitConstraint or WarmStartedJointLimit, when asked.
class Pendulum {
 public:
  explicit Pendulum(bool bullets, bool limited = false)
      : world_(&dispatcher_, &broadphase_, &solver_, &configuration_) {
    world_.setGravity(btVector3(0, 0, -9.81));
    world_.getSolverInfo().m_numIterations = 2000;
    world_.getSolverInfo().m_leastSquaresResidualThreshold = 1e-30;  // converged: all sweeps
    body_ = std::make_unique<btMultiBody>(3, 0.0, btVector3(0, 0, 0), true, false);
    const btQuaternion level(0, 0, 0, 1);
    const btVector3 y(0, 1, 0), x(1, 0, 0);
    body_->setupRevolute(0, 2.0, btVector3(0.01, 0.05, 0.05), -1, level, y, btVector3(0, 0, 0), btVector3(0.25, 0, 0),
                         true);
    body_->setupRevolute(1, 1.0, btVector3(0.02, 0.04, 0.02), 0, level, y, btVector3(0.25, 0, 0), btVector3(0, 0, 0),
                         true);
    body_->setupPrismatic(2, 0.5, btVector3(0.01, 0.01, 0.01), 0, level, x, btVector3(0.35, 0, 0), btVector3(0, 0, 0),
                          true);
    body_->finalizeMultiDof();
    world_.addMultiBody(body_.get());
    // The solver takes a multibody's constraints with its island, which
    // its colliders make: a small sphere on each link, colliding with
    // nothing (one multibody, no self-collision).
    for (int link = 0; link < 3; ++link) {
      auto collider = std::make_unique<btMultiBodyLinkCollider>(body_.get(), link);
      collider->setCollisionShape(&sphere_);
      world_.addCollisionObject(collider.get(), btBroadphaseProxy::DefaultFilter, btBroadphaseProxy::AllFilter);
      body_->getLink(link).m_collider = collider.get();
      colliders_[link] = std::move(collider);
    }
    if (limited) {
      for (const auto& [link, lower, upper] : {std::tuple{0, -0.3, 0.2}, std::tuple{2, -0.05, 0.05}}) {
        if (bullets) {
          owned_limits_.push_back(std::make_unique<btMultiBodyJointLimitConstraint>(body_.get(), link, lower, upper));
        } else {
          auto limit = std::make_unique<wtc::bullet::WarmStartedJointLimit>(body_.get(), link, lower, upper);
          limits_.push_back(limit.get());
          owned_limits_.push_back(std::move(limit));
        }
        world_.addMultiBodyConstraint(owned_limits_.back().get());
      }
    }
    for (int link = 0; link < 3; ++link) {
      if (bullets) {
        auto motor = std::make_unique<btMultiBodyJointMotor>(body_.get(), link, 0.0, 0.0);
        bullet_[link] = motor.get();
        world_.addMultiBodyConstraint(motor.get());
        owned_[link] = std::move(motor);
      } else {
        auto motor = std::make_unique<wtc::bullet::WarmStartedMotor>(body_.get(), link);
        ours_[link] = motor.get();
        world_.addMultiBodyConstraint(motor.get());
        owned_[link] = std::move(motor);
      }
    }
  }
  ~Pendulum() {
    for (auto& c : owned_) world_.removeMultiBodyConstraint(c.get());
    for (auto& c : owned_limits_) world_.removeMultiBodyConstraint(c.get());
    for (auto& c : colliders_) world_.removeCollisionObject(c.get());
    world_.removeMultiBody(body_.get());
  }

  void step(const double (&rate)[3], const double (&cap)[3]) {
    for (int link = 0; link < 3; ++link) {
      if (bullet_[link] != nullptr) {
        bullet_[link]->setVelocityTarget(rate[link]);
        bullet_[link]->setMaxAppliedImpulse(cap[link] * kStepS);
      } else {
        ours_[link]->setTarget(rate[link], cap[link], true, kStepS);
      }
    }
    for (wtc::bullet::WarmStartedJointLimit* l : limits_) l->prepare(kStepS);
    world_.stepSimulation(kStepS, 0, kStepS);
    for (wtc::bullet::WarmStartedMotor* m : ours_) {
      if (m != nullptr) m->stepped();
    }
    for (wtc::bullet::WarmStartedJointLimit* l : limits_) l->stepped();
  }

  double position(int link) const { return body_->getJointPos(link); }
  double rate(int link) const { return body_->getJointVel(link); }
  double effort(int link) const {
    return bullet_[link] != nullptr ? bullet_[link]->getAppliedImpulse(0) / kStepS : ours_[link]->effort();
  }

 private:
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_{&configuration_};
  btDbvtBroadphase broadphase_;
  btMultiBodyConstraintSolver solver_;
  btMultiBodyDynamicsWorld world_;
  btSphereShape sphere_{0.01};
  std::unique_ptr<btMultiBody> body_;
  std::unique_ptr<btMultiBodyLinkCollider> colliders_[3];
  std::unique_ptr<btMultiBodyConstraint> owned_[3];
  btMultiBodyJointMotor* bullet_[3] = {};
  wtc::bullet::WarmStartedMotor* ours_[3] = {};
  std::vector<std::unique_ptr<btMultiBodyConstraint>> owned_limits_;
  std::vector<wtc::bullet::WarmStartedJointLimit*> limits_;
};

// Each joint's position (to 1e-9), rate (1e-7) and drive effort (1e-6 of
// its cap) the same in both.
::testing::AssertionResult sameMotion(const Pendulum& ours, const Pendulum& bullet, const double (&cap)[3]) {
  for (int link = 0; link < 3; ++link) {
    const double dq = std::abs(ours.position(link) - bullet.position(link));
    const double dv = std::abs(ours.rate(link) - bullet.rate(link));
    const double de = std::abs(ours.effort(link) - bullet.effort(link));
    if (dq > 1e-9 || dv > 1e-7 || de > 1e-6 * (1.0 + cap[link])) {
      return ::testing::AssertionFailure()
             << "link " << link << ": position, rate, effort off by " << dq << ", " << dv << ", " << de;
    }
  }
  return ::testing::AssertionSuccess();
}

// Drives both for 2 s, joint i at a_i sin(w_i t + phi_i) (rad/s or m/s)
// within the caps below, each step checked with sameMotion; returns the
// steps at which `counted(bullet)` holds.
constexpr double kCap[3] = {6.0, 0.5, 40.0};  // arm, wheel (N m), slider (N)
template <class Counted>
int driveBoth(Pendulum& bullet, Pendulum& ours, const double (&a)[3], const double (&w)[3], Counted counted) {
  constexpr double kPhase[3] = {0.0, std::numbers::pi / 2, 0.0};
  int n = 0;
  for (int k = 0; k < 2000; ++k) {
    double rate[3];
    for (int i = 0; i < 3; ++i) rate[i] = a[i] * std::sin(w[i] * k * kStepS + kPhase[i]);
    bullet.step(rate, kCap);
    ours.step(rate, kCap);
    if (counted(bullet)) ++n;
    const ::testing::AssertionResult same = sameMotion(ours, bullet, kCap);
    if (!same) {
      ADD_FAILURE() << same.message() << " at step " << k;
      return n;
    }
  }
  return n;
}

// Driven through free, tracking and saturated phases (the arm's cap is
// below gravity's torque on it at times), the drive moves the joints as
// Bullet's motor does and reports the same effort.
TEST(WarmStartedMotorTest, MovesTheJointsAsBulletsOwnJointMotorDoes) {
  Pendulum bullet(true), ours(false);
  const int saturated = driveBoth(bullet, ours, {0.8, 20.0, 0.1}, {3.0, 2.0, 5.0},
                                  [](const Pendulum& p) { return std::abs(std::abs(p.effort(0)) - kCap[0]) < 1e-9; });
  EXPECT_GT(saturated, 100);  // the limit was exercised
  EXPECT_LT(saturated, 1900);
}

// Driven into its bounds and held there by gravity and the drives (the
// arm's drive is too weak to lift it off its lower stop at times), the
// bounded joints move as they do under Bullet's own limits, with the same
// drive efforts.
TEST(WarmStartedJointLimitTest, HoldsTheJointsAtTheirStopsAsBulletsOwnLimitDoes) {
  Pendulum bullet(true, true), ours(false, true);
  const int at_stop = driveBoth(bullet, ours, {1.5, 20.0, 0.4}, {4.0, 2.0, 7.0}, [](const Pendulum& p) {
    return p.position(0) < -0.3 + 1e-4 || p.position(0) > 0.2 - 1e-4;
  });
  EXPECT_GT(at_stop, 200);  // the stops were reached and held
  EXPECT_LT(at_stop, 1800);
}

}  // namespace
