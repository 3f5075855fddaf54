// WheelDriveResponses (plugins/bullet/sim/src/wheel_drive_responses.hpp)
// against Bullet's own articulated-body solve: a wheel drive's response,
// M^-1 e_w, from the solve its parent shares with the other wheel, is
// Bullet's to rounding; a link the identity does not hold for is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>

#include "wheel_drive_responses.hpp"

namespace {

// Rounding: the two responses are one solve apart (sums in another order).
constexpr double kTolerance = 1e-12;

// A robot-like tree on a floating, tilted base: two wheels on the base
// (links 0, 1), a carrier turning about y (2), a slider along its z (3)
// and two wheels on the slider (4, 5); the right wheels' axes point along
// -y. A wheel is a disc about its axle: its centre of mass on the axle, its
// inertia (0.3, 0.5, 0.3) kg m^2 with y the axle.
struct Robot {
  static constexpr int kLinks = 6;
  explicit Robot(const btVector3& wheel_com_offset = btVector3(0, 0, 0),
                 const btVector3& wheel_inertia = btVector3(0.3, 0.5, 0.3)) {
    body = std::make_unique<btMultiBody>(kLinks, 30.0, btVector3(2.0, 3.0, 4.0), false, false);
    const btQuaternion level(0, 0, 0, 1);
    const btVector3 y(0, 1, 0), z(0, 0, 1), none(0, 0, 0);
    for (int side = 0; side < 2; ++side) {
      const double s = side == 0 ? 1.0 : -1.0;
      body->setupRevolute(side, 4.0, wheel_inertia, -1, level, s * y, btVector3(0.5, s * 0.4, -0.1), wheel_com_offset,
                          true);
    }
    body->setupRevolute(2, 6.0, btVector3(0.2, 0.3, 0.4), -1, level, y, btVector3(-0.4, 0, 0), btVector3(-0.2, 0, 0),
                        true);
    body->setupPrismatic(3, 2.0, btVector3(0.05, 0.05, 0.05), 2, level, z, btVector3(-0.2, 0, 0), none, true);
    for (int side = 0; side < 2; ++side) {
      const double s = side == 0 ? 1.0 : -1.0;
      body->setupRevolute(4 + side, 4.0, wheel_inertia, 3, level, s * y, btVector3(0, s * 0.4, -0.1), wheel_com_offset,
                          true);
    }
    body->finalizeMultiDof();
    body->setBasePos(btVector3(1.0, 2.0, 0.5));
    body->setWorldToBaseRot(btQuaternion(btVector3(1, 2, 3).normalized(), 0.4));
    body->setBaseVel(btVector3(0.5, -0.2, 0.1));
    body->setBaseOmega(btVector3(0.1, 0.3, -0.2));
    const double q[kLinks] = {0.3, -1.2, 0.25, 0.04, 2.0, -0.7};
    const double qd[kLinks] = {5.0, 4.0, -0.3, 0.1, 6.0, 5.5};
    for (int k = 0; k < kLinks; ++k) {
      body->setJointPos(k, q[k]);
      body->setJointVel(k, qd[k]);
    }
    // What btMultiBodyDynamicsWorld::solveExternalForces does before the
    // solver's setup: the link frames and the articulated-body caches.
    btAlignedObjectArray<btQuaternion> rotations;
    btAlignedObjectArray<btVector3> origins;
    body->forwardKinematics(rotations, origins);
    body->computeAccelerationsArticulatedBodyAlgorithmMultiDof(1e-3, data.scratch_r, data.scratch_v, data.scratch_m,
                                                               false, false, false);
  }
  int dofs() const { return body->getNumDofs() + 6; }
  // Bullet's M^-1 e_link.
  std::vector<btScalar> bulletsResponse(int link) {
    std::vector<btScalar> force(dofs(), 0.0), response(dofs(), 0.0);
    force[6 + body->getLink(link).m_dofOffset] = 1.0;
    body->calcAccelerationDeltasMultiDof(force.data(), response.data(), data.scratch_r, data.scratch_v);
    return response;
  }
  std::unique_ptr<btMultiBody> body;
  btMultiBodyJacobianData data;
};

double largest(const std::vector<btScalar>& v) {
  double m = 0.0;
  for (const btScalar x : v) m = std::max(m, std::abs(x));
  return m;
}

TEST(WheelDriveResponsesTest, TwoWheelsOnOneParentShareOneSolveAndGetBulletsResponse) {
  Robot robot;
  wtc::bullet::WheelDriveResponses shared;
  // Case: every wheel, in the order a solver's setup takes their drives;
  // the right wheels' axles point the other way, and a row may have sign -1.
  for (const int link : {0, 1, 4, 5}) {
    ASSERT_TRUE(wtc::bullet::WheelDriveResponses::applies(*robot.body, link)) << "link " << link;
    for (const double sign : {1.0, -1.0}) {
      std::vector<btScalar> ours(robot.dofs(), 0.0);
      shared.fill(robot.data, *robot.body, link, sign, ours.data());
      const std::vector<btScalar> bullets = robot.bulletsResponse(link);
      for (int k = 0; k < robot.dofs(); ++k) {
        EXPECT_NEAR(ours[k], sign * bullets[k], kTolerance * largest(bullets)) << "link " << link << " dof " << k;
      }
    }
  }
  // One solve for each parent (the base, the slider), the other six fills
  // from those two.
  EXPECT_EQ(shared.solvesSaved(), 6);
  // Case: the next step's pose: forget() and the first wheel of a pair
  // solves again.
  shared.forget();
  std::vector<btScalar> ours(robot.dofs(), 0.0);
  shared.fill(robot.data, *robot.body, 4, 1.0, ours.data());
  EXPECT_EQ(shared.solvesSaved(), 6);
}

TEST(WheelDriveResponsesTest, RefusesLinksTheIdentityDoesNotHoldFor) {
  Robot robot;
  // Case: the carrier (not a leaf) and the slider (not revolute).
  EXPECT_FALSE(wtc::bullet::WheelDriveResponses::applies(*robot.body, 2));
  EXPECT_FALSE(wtc::bullet::WheelDriveResponses::applies(*robot.body, 3));
  // Case: a link that does not exist.
  EXPECT_FALSE(wtc::bullet::WheelDriveResponses::applies(*robot.body, -1));
  EXPECT_FALSE(wtc::bullet::WheelDriveResponses::applies(*robot.body, Robot::kLinks));
  // Case: a wheel whose centre of mass is 1 mm off its axle.
  Robot off_axle(btVector3(0.001, 0, 0));
  EXPECT_FALSE(wtc::bullet::WheelDriveResponses::applies(*off_axle.body, 0));
  // Case: a wheel whose axle is not a principal axis (the link's frame is
  // principal; its joint axis is y): I y is along y for any diagonal I.
  // A tilted axle is: a wheel built so must be refused.
  Robot wheel(btVector3(0, 0, 0), btVector3(0.3, 0.5, 0.3));
  btMultibodyLink& l = wheel.body->getLink(0);
  l.setAxisTop(0, btVector3(0.6, 0.8, 0));  // not along a principal axis of (0.3, 0.5, 0.3)
  EXPECT_FALSE(wtc::bullet::WheelDriveResponses::applies(*wheel.body, 0));
}

}  // namespace
