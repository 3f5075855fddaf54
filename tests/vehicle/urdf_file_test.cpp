// The URDF reader: each mapped element against the hand computations of
// tests/urdf/README.md (cases 1-8), and each refusal by name.
#include "wtc/vehicle/urdf_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <numbers>

#include "wtc/base/error.hpp"
#include "wtc/geometry/convex_polyhedron.hpp"

namespace wtc::vehicle {
namespace urdf_file_test {

using ::testing::HasSubstr;
constexpr double kTolerance = 1e-12;
const std::filesystem::path kUrdf = std::filesystem::path(WTC_SOURCE_DIR) / "tests" / "urdf";

// The body's tensor about its centre in V's axes: R diag(moments) R^T.
Eigen::Matrix3d tensorInV(const Body& b) {
  return b.pose.linear() * b.inertia.asDiagonal() * b.pose.linear().transpose();
}

const Body& body(const UrdfModel& m, const std::string& name) {
  const int i = m.vehicle.find(name);
  EXPECT_GE(i, 0) << name;
  return m.vehicle.bodies.at(i);
}

TEST(UrdfFileTest, TensorOffItsAxesTurnsTheBodyToItsPrincipalAxes) {
  // Case 1: I = [[0.5, -0.1, 0], [-0.1, 0.5, 0], [0, 0, 0.7]]: 0.4, 0.6, 0.7 about Rz(45 deg)'s axes.
  const UrdfModel m = readUrdf(kUrdf / "inertia_off_axis.urdf");
  const Body& b = m.vehicle.bodies.at(0);
  Eigen::Matrix3d expected;
  expected << 0.5, -0.1, 0, -0.1, 0.5, 0, 0, 0, 0.7;
  EXPECT_TRUE(tensorInV(b).isApprox(expected, kTolerance)) << tensorInV(b);
  Eigen::Vector3d sorted = b.inertia;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_TRUE(sorted.isApprox(Eigen::Vector3d(0.4, 0.6, 0.7), kTolerance)) << sorted.transpose();
  EXPECT_NEAR(b.pose.linear().determinant(), 1.0, kTolerance);
  EXPECT_TRUE(b.pose.translation().isApprox(Eigen::Vector3d(0.1, 0.2, 0.3), kTolerance));
  // The moment 0.4 lies along (1, 1, 0)/sqrt 2.
  int smallest = 0;
  b.inertia.minCoeff(&smallest);
  const Eigen::Vector3d axis = b.pose.linear().col(smallest);
  EXPECT_NEAR(std::abs(axis.dot(Eigen::Vector3d(1, 1, 0).normalized())), 1.0, kTolerance);
  // Its box, centred on the centre of mass but not along the principal axes, is a compound part.
  ASSERT_EQ(b.compound.size(), 1u);
  EXPECT_EQ(b.compound[0].shape.kind, Shape::Kind::kBox);
  EXPECT_TRUE((b.pose * b.compound[0].pose_BS).linear().isIdentity(kTolerance));
  // What users read is the link's own frame: the root link's axes are V's (issue 57 row 3).
  EXPECT_TRUE(ownFrame(b, b.pose).linear().isIdentity(kTolerance));
  EXPECT_TRUE(ownFrame(b, b.pose).translation().isApprox(b.pose.translation(), kTolerance));
}

// Issue 57 row 3: a link's own axes, not the principal axes, wherever a
// body's rotation reaches users. A diagonal tensor in an <inertial> frame
// with rpy: the body's frame is that of the <inertial>, its own axes the
// link's. A lidar merged into the base: principal axes turned, own axes V's.
TEST(UrdfFileTest, EveryBodyKeepsItsLinksOwnAxesBesideTheFrameItIsIntegratedIn) {
  const UrdfModel rotated = readUrdf(kUrdf / "inertia_rotated_origin.urdf");
  const Body& r = rotated.vehicle.bodies.at(0);
  EXPECT_FALSE(r.pose.linear().isIdentity(1e-6));
  EXPECT_TRUE(ownFrame(r, r.pose).linear().isIdentity(kTolerance)) << ownFrame(r, r.pose).linear();
  const UrdfModel skid = readUrdf(kUrdf / "skid_lidar.urdf");
  const Body& base = body(skid, "base_link");
  EXPECT_FALSE(base.pose.linear().isIdentity(1e-3)) << base.pose.linear();
  EXPECT_TRUE(ownFrame(base, base.pose).linear().isIdentity(kTolerance)) << ownFrame(base, base.pose).linear();
  // A wheel on a joint turned by rpy (-pi/2, 0, 0): its own axes are its link's, the axle along its z.
  const Body& wheel = body(skid, "fl_wheel");
  const Eigen::Matrix3d R_VL = Eigen::AngleAxisd(-std::numbers::pi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  EXPECT_TRUE(ownFrame(wheel, wheel.pose).linear().isApprox(R_VL, kTolerance));
}

TEST(UrdfFileTest, InertialOriginRotationAppliesRollThenPitchThenYaw) {
  // Case 2: diag(0.1, 0.2, 0.25) in a frame rpy (pi/2, 0, pi/2) is diag(0.25, 0.1, 0.2) in the link's.
  const UrdfModel m = readUrdf(kUrdf / "inertia_rotated_origin.urdf");
  EXPECT_TRUE(tensorInV(m.vehicle.bodies.at(0))
                  .isApprox(Eigen::Vector3d(0.25, 0.1, 0.2).asDiagonal().toDenseMatrix(), kTolerance));
  // Case 3: the tensor of case 1 yawed by pi/2.
  const UrdfModel both = readUrdf(kUrdf / "inertia_rotated_off_axis.urdf");
  Eigen::Matrix3d expected;
  expected << 0.5, 0.1, 0, 0.1, 0.5, 0, 0, 0, 0.7;
  EXPECT_TRUE(tensorInV(both.vehicle.bodies.at(0)).isApprox(expected, kTolerance));
}

TEST(UrdfFileTest, JointOriginsWithRotationComposeIntoTheRootFrame) {
  // Case 4.
  const UrdfModel m = readUrdf(kUrdf / "joint_origin_rotated.urdf");
  const Body& arm1 = body(m, "arm1");
  const Body& arm2 = body(m, "arm2");
  EXPECT_TRUE(arm1.joint.anchor.isApprox(Eigen::Vector3d(1, 2, 3), kTolerance));
  EXPECT_TRUE(arm1.joint.axis.isApprox(Eigen::Vector3d(0, 1, 0), kTolerance)) << arm1.joint.axis.transpose();
  EXPECT_TRUE(arm2.joint.anchor.isApprox(Eigen::Vector3d(1, 3, 3), kTolerance));
  EXPECT_TRUE(arm2.joint.axis.isApprox(Eigen::Vector3d(0, 0, 1), kTolerance)) << arm2.joint.axis.transpose();
  EXPECT_TRUE((arm2.pose * Eigen::Vector3d(0, 0, 1)).isApprox(Eigen::Vector3d(2, 3, 3), kTolerance));
  EXPECT_EQ(arm2.parent, m.vehicle.find("arm1"));
  EXPECT_EQ(arm2.joint.name, "joint2");
  ASSERT_TRUE(arm2.joint.limits);
  EXPECT_EQ(arm2.joint.limits->lower, -1.0);
  EXPECT_EQ(m.drive_limits.at("joint2").effort, 10.0);
}

TEST(UrdfFileTest, FixedLinksMergeIntoTheirParentWithMassCentreAndTensor) {
  // Case 5.
  const UrdfModel m = readUrdf(kUrdf / "fixed_merge.urdf");
  ASSERT_EQ(m.vehicle.bodies.size(), 2u);
  const Body& base = body(m, "base");
  EXPECT_NEAR(base.mass, 5.0, kTolerance);
  EXPECT_TRUE(base.pose.translation().isApprox(Eigen::Vector3d(0.06, 0.04, 0.02), kTolerance));
  Eigen::Matrix3d expected;
  expected << 0.16, -0.048, -0.024, -0.048, 0.29, -0.016, -0.024, -0.016, 0.434;
  EXPECT_TRUE(tensorInV(base).isApprox(expected, kTolerance)) << tensorInV(base);
  Eigen::Vector3d sorted = base.inertia;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_TRUE(sorted.isApprox(Eigen::Vector3d(0.14155192, 0.30535874, 0.43708935), 1e-7)) << sorted.transpose();
  // Two boxes: base's own at base's origin, the bracket's at (0.3, 0, 0.1) turned by Rz(90 deg).
  ASSERT_EQ(base.compound.size(), 2u);
  const Eigen::Isometry3d bracket = base.pose * base.compound[1].pose_BS;
  EXPECT_TRUE(bracket.translation().isApprox(Eigen::Vector3d(0.3, 0, 0.1), kTolerance));
  EXPECT_TRUE((bracket.linear() * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY(), kTolerance));
  EXPECT_EQ(m.link_body.at("payload"), 0);
  EXPECT_EQ(m.link_body.at("bracket"), 0);
  const Body& arm = body(m, "arm");
  EXPECT_EQ(arm.parent, 0);
  EXPECT_TRUE(arm.joint.anchor.isApprox(Eigen::Vector3d(0.3, 0.3, 0.1), kTolerance));
  EXPECT_TRUE(arm.joint.axis.isApprox(Eigen::Vector3d(0, 1, 0), kTolerance));
  EXPECT_TRUE(arm.pose.translation().isApprox(Eigen::Vector3d(0.3, 0.35, 0.1), kTolerance));
  EXPECT_EQ(m.joint_body.count("bracket_mount"), 0u);  // a fixed joint carries no drive
}

TEST(UrdfFileTest, MimicJointsNameTheirMasterMultiplierAndOffset) {
  // Case 6: q_left = -q_bar, q_right = +q_bar.
  const UrdfModel m = readUrdf(kUrdf / "mimic_differential.urdf");
  const Body& left = body(m, "left_rocker");
  const Body& right = body(m, "right_rocker");
  ASSERT_TRUE(left.joint.mimic && right.joint.mimic);
  EXPECT_EQ(left.joint.mimic->master, m.vehicle.find("bar"));
  EXPECT_EQ(left.joint.mimic->multiplier, -1.0);
  EXPECT_EQ(right.joint.mimic->multiplier, 1.0);
  EXPECT_EQ(right.joint.mimic->offset, 0.0);
  EXPECT_FALSE(body(m, "bar").joint.mimic);
}

TEST(UrdfFileTest, PackageMeshIsItsConvexHullBesideTheBox) {
  // Case 8 (an STL holds single-precision floats: 0.1f is 0.1 + 1.5e-9).
  constexpr double kStlTolerance = 1e-7;
  // The tetrahedron (0,0,0), (0.1,0,0), (0,0.1,0), (0,0,0.1) at (0, 0, 0.2), and a box.
  const UrdfModel m = readUrdf(kUrdf / "package_mesh.urdf", {.package_path = {kUrdf / "packages"}});
  const Body& b = m.vehicle.bodies.at(0);
  ASSERT_EQ(b.compound.size(), 2u);
  const ShapePart& hull = b.compound[0];
  ASSERT_EQ(hull.shape.kind, Shape::Kind::kHull);
  ASSERT_EQ(hull.shape.hull_vertices.size(), 4u);
  std::vector<Eigen::Vector3d> in_v;
  for (const Eigen::Vector3d& p : hull.shape.hull_vertices) in_v.push_back(b.pose * hull.pose_BS * p);
  for (const Eigen::Vector3d& corner : {Eigen::Vector3d(0, 0, 0.2), Eigen::Vector3d(0.1, 0, 0.2),
                                        Eigen::Vector3d(0, 0.1, 0.2), Eigen::Vector3d(0, 0, 0.3)}) {
    EXPECT_TRUE(std::any_of(in_v.begin(), in_v.end(), [&](const auto& p) {
      return (p - corner).norm() < kStlTolerance;
    })) << corner.transpose();
  }
  EXPECT_EQ(b.compound[1].shape.kind, Shape::Kind::kBox);
}

TEST(UrdfFileTest, APackageIsFoundInAWorkspaceFolderOfAnotherNameAsRosCrawlsForIt) {
  // Issue 57 row 11: package://NAME was found only in a folder called NAME or on the path itself.
  const UrdfModel m = readUrdf(kUrdf / "workspace_mesh.urdf", {.package_path = {kUrdf / "workspace"}});
  const Body& b = m.vehicle.bodies.at(0);
  // The tetrahedron's hull, a part at its place in the body (centre-of-mass) frame.
  ASSERT_EQ(b.compound.size(), 1u);
  ASSERT_EQ(b.compound[0].shape.kind, Shape::Kind::kHull);
  EXPECT_EQ(b.compound[0].shape.hull_vertices.size(), 4u);
}

TEST(UrdfFileTest, ShippedUrdfsReadWithTheirBodyCounts) {
  const std::filesystem::path vehicles = std::filesystem::path(WTC_SOURCE_DIR) / "vehicles";
  EXPECT_EQ(readUrdf(vehicles / "six_wheel_robot.urdf").vehicle.bodies.size(), 11u);
  EXPECT_EQ(readUrdf(vehicles / "towed_system_tug.urdf").vehicle.bodies.size(), 3u);
  EXPECT_EQ(readUrdf(vehicles / "towed_system_towed.urdf").vehicle.bodies.size(), 5u);
  const UrdfModel rover = readUrdf(vehicles / "rocker_bogie_rover.urdf", {.package_path = {vehicles}});
  ASSERT_EQ(rover.vehicle.bodies.size(), 12u);
  EXPECT_NEAR(rover.vehicle.totalMass(), 30.0, 1e-9);
  // The chassis: its tensor's principal moments (docs/rocker-bogie-rover.md, from the values as written).
  Eigen::Vector3d moments = rover.vehicle.bodies.at(0).inertia;
  std::sort(moments.begin(), moments.end());
  EXPECT_TRUE(moments.isApprox(Eigen::Vector3d(0.25135, 0.48032, 0.53309), 1e-4)) << moments.transpose();
  EXPECT_EQ(rover.vehicle.bodies.at(0).name, "chassis");  // the file's order, not urdfdom's name order
}

// Refusals: the file, the link or joint, the problem.
void expectRefused(const std::string& file, const std::vector<std::string>& fragments,
                   const UrdfOptions& options = {}) {
  try {
    readUrdf(kUrdf / file, options);
    ADD_FAILURE() << file << " was accepted";
  } catch (const InvalidInputError& e) {
    EXPECT_THAT(e.what(), HasSubstr(file));
    for (const std::string& f : fragments) EXPECT_THAT(e.what(), HasSubstr(f));
  }
}

TEST(UrdfFileTest, RefusesWhatUrdfdomRefusesWithItsMessage) {
  expectRefused("malformed.urdf", {"urdfdom refuses it", "Error reading end tag"});
  expectRefused("ball_joint.urdf", {"Joint [caster_joint] has no known type [ball]"});
  expectRefused("two_roots.urdf", {"Two root links found"});
  expectRefused("closed_chain_no_root.urdf", {"No root link found"});
  expectRefused("revolute_without_limit.urdf", {"does not specify limits"});
  // urdfdom logs this one and returns a model with mass 0.
  expectRefused("inertial_without_mass.urdf", {"Inertial element must have a mass element"});
}

TEST(UrdfFileTest, RefusesFloatingAndPlanarJointsByName) {
  expectRefused("floating_joint.urdf", {"joint 'payload_joint' is floating"});
  expectRefused("planar_joint.urdf", {"joint 'payload_joint' is planar"});
}

TEST(UrdfFileTest, RefusesClosedChainsBeforeWalkingThem) {
  expectRefused("closed_chain_two_parents.urdf", {"link 'c' is the child of two joints ('a_to_c' and 'b_to_c')"});
  expectRefused("closed_chain_cycle.urdf", {"link 'b' is the child of two joints ('a_to_b' and 'c_to_b')"});
}

TEST(UrdfFileTest, RefusesMassesAndInertiasThatAreNotPositive) {
  expectRefused("massless_revolute.urdf", {"link 'flap' has no mass", "revolute joint 'flap_joint'"});
  expectRefused("zero_mass.urdf", {"link 'body' has mass 0"});
  expectRefused("negative_mass.urdf", {"link 'body' has mass -1"});
  expectRefused("zero_inertia.urdf", {"link 'body'", "inertia", "not positive"});
  expectRefused("negative_inertia.urdf", {"link 'body'", "inertia", "-0.01", "not positive"});
  expectRefused("indefinite_inertia.urdf", {"link 'body'", "principal moment -0.01 kg m^2"});
  expectRefused("inertia_triangle_inequality.urdf", {"link 'body'", "triangle inequality"});
}

TEST(UrdfFileTest, RefusesACollisionMeshThatEnclosesNoVolume) {
  // Issue 57 row 2: a zero-thickness mesh was accepted, and Bullet threw the robot from it.
  expectRefused("mesh_zero_thickness.urdf",
                {"link 'body'", "lie in one plane: a collision mesh must enclose a volume"},
                {.package_path = {kUrdf / "packages"}});
}

TEST(UrdfFileTest, RefusesAMimicOfAMissingJoint) {
  expectRefused("mimic_missing_joint.urdf",
                {"joint 'rocker_joint' mimics 'differential_joint', which is not a joint of"});
}

TEST(UrdfFileTest, RefusesAPackageFoundOnNoPackagePathNamingTheFolders) {
  expectRefused("package_missing.urdf",
                {"package://no_such_package/meshes/hull.stl", "link 'body'", (kUrdf / "packages").string()},
                {.package_path = {kUrdf / "packages"}});
  // The same mesh URI with an empty package path says so.
  expectRefused("package_mesh.urdf", {"package://wtc_test_pkg", "the package path is empty"});
}

}  // namespace urdf_file_test
}  // namespace wtc::vehicle
