// The elastic hitch P = H diag(C) H^T Delta + H diag(mu) H^T dDelta/dt.
#include "wtc/vehicle/hitch_law.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "wtc/base/error.hpp"

namespace wtc::vehicle {
namespace hitch_law_test {

constexpr double kTolerance = 1e-9;

Hitch hitch() {
  Hitch h;
  h.body_a = 0;
  h.body_b = 1;
  h.point_a = {-1.0, 0.0, 0.0};
  h.point_b = {2.0, 0.0, 0.0};
  h.stiffness = {1e5, 2e5, 1e6};
  h.damping = {1e4, 2e4, 3e4};
  return h;
}

BodyKinematics at(const Eigen::Vector3d& p, double yaw = 0.0, double pitch = 0.0) {
  BodyKinematics k;
  k.pose.translation() = p;
  k.pose.linear() =
      (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()))
          .toRotationMatrix();
  return k;
}

TEST(HitchLawTest, StretchedAlongTheTugAxisPullsWithCxTimesTheStretch) {
  // Case: D1 at x = -1, D2 at x = -1.1: Delta = 0.1 m along x.
  const HitchForce f = hitchForce(hitch(), at({0, 0, 0}), at({-3.1, 0, 0}), true);
  EXPECT_NEAR(f.deflection.x(), 0.1, kTolerance);
  EXPECT_NEAR(f.force_on_b.x(), 1e5 * 0.1, 1e-6);
  EXPECT_NEAR(f.force_on_b.y(), 0.0, 1e-6);
}

TEST(HitchLawTest, AxesFollowTheTugsHeadingButStayHorizontal) {
  // Case: tug yawed 90 deg and pitched 20 deg; a lateral offset of D2 along
  // world x is the tug's -y: the force uses Cy, and no vertical part arises.
  const double yaw = std::numbers::pi / 2;
  const BodyKinematics a = at({0, 0, 0}, yaw, 20.0 * std::numbers::pi / 180.0);
  const Eigen::Vector3d d1 = a.pose * hitch().point_a;
  BodyKinematics b = at({0, 0, 0}, yaw);
  b.pose.translation() = d1 + Eigen::Vector3d(0.05, 0, 0) - b.pose.linear() * hitch().point_b;
  const HitchForce f = hitchForce(hitch(), a, b, false);
  // D2 sits 0.05 m along world x of D1, which is the tug's -y.
  EXPECT_NEAR(f.deflection.y(), 0.05, kTolerance);  // Delta = D1 - D2 = +0.05 along the tug's y
  EXPECT_NEAR(f.force_on_b.x(), -2e5 * 0.05, 1e-6);
  EXPECT_NEAR(f.force_on_b.z(), 0.0, 1e-6);
}

TEST(HitchLawTest, DampingNeverFeedsEnergyIn) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 10000; ++i) {
    BodyKinematics a = at({u(rng), u(rng), 0.1 * u(rng)}, 3 * u(rng), 0.5 * u(rng));
    BodyKinematics b = at({-3 + u(rng), u(rng), 0.1 * u(rng)}, 3 * u(rng), 0.3 * u(rng));
    a.linear_velocity = {u(rng), u(rng), u(rng)};
    a.angular_velocity = {u(rng), u(rng), u(rng)};
    b.linear_velocity = {u(rng), u(rng), u(rng)};
    b.angular_velocity = {u(rng), u(rng), u(rng)};
    const HitchForce elastic = hitchForce(hitch(), a, b, false);
    const HitchForce full = hitchForce(hitch(), a, b, true);
    const Eigen::Vector3d damping = full.force_on_b - elastic.force_on_b;
    const Eigen::Vector3d v_a = a.linear_velocity + a.angular_velocity.cross(full.point_a - a.pose.translation());
    const Eigen::Vector3d v_b = b.linear_velocity + b.angular_velocity.cross(full.point_b - b.pose.translation());
    // Power of +P on b at D2 and -P on a at D1.
    const double power = damping.dot(v_b) - damping.dot(v_a);
    EXPECT_LE(power, 1e-9) << "case " << i;
  }
}

TEST(HitchLawTest, ATugPointingStraightUpIsRefused) {
  const BodyKinematics a = at({0, 0, 0}, 0.0, -std::numbers::pi / 2);
  EXPECT_THROW(hitchForce(hitch(), a, at({-3, 0, 0}), true), InvalidInputError);
}

}  // namespace hitch_law_test
}  // namespace wtc::vehicle
