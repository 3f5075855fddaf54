// Vehicle descriptions: inertias of the shapes, and the checks of validate.
#include "wtc/vehicle/vehicle_description.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "wtc/base/error.hpp"

namespace wtc::vehicle {
namespace vehicle_description_test {

using ::testing::HasSubstr;
constexpr double kTolerance = 1e-12;

// Shapes by their members (a designated initializer would leave the others
// to -Wmissing-field-initializers).
Shape boxShape(const Eigen::Vector3d& size) {
  Shape s;
  s.kind = Shape::Kind::kBox;
  s.box_size = size;
  return s;
}

// A 0.12 m wide disc about y, of `radius` (m).
Shape discShape(double radius) {
  Shape s;
  s.kind = Shape::Kind::kCylinder;
  s.radius = radius;
  s.length = 0.12;
  s.cylinder_axis = 1;
  return s;
}

TEST(VehicleDescriptionTest, SolidInertiaMatchesTextbookFormulas) {
  // Case: box a x b x c: m (b^2 + c^2) / 12, ...
  const Shape box = boxShape({0.5, 0.4, 0.2});
  const Eigen::Vector3d ib = solidInertia(box, 12.0);
  EXPECT_NEAR(ib.x(), 0.16 + 0.04, kTolerance);
  EXPECT_NEAR(ib.y(), 0.25 + 0.04, kTolerance);
  EXPECT_NEAR(ib.z(), 0.25 + 0.16, kTolerance);
  // Case: the robot's wheel as a disc about y: m r^2 / 2 = 0.0668 kg m^2.
  const Shape disc = discShape(0.19);
  const Eigen::Vector3d iw = solidInertia(disc, 3.7);
  EXPECT_NEAR(iw.y(), 0.5 * 3.7 * 0.19 * 0.19, kTolerance);
  EXPECT_NEAR(iw.x(), 3.7 * (3 * 0.19 * 0.19 + 0.12 * 0.12) / 12, kTolerance);
  // Case: sphere 2 m r^2 / 5.
  Shape ball;
  ball.kind = Shape::Kind::kSphere;
  ball.radius = 0.15;
  EXPECT_NEAR(solidInertia(ball, 10.0).z(), 0.4 * 10 * 0.0225, kTolerance);
}

VehicleDescription twoBodies() {
  VehicleDescription v;
  v.name = "test";
  Body root;
  root.name = "root";
  root.mass = 10.0;
  root.inertia = {1, 1, 1};
  Body child;
  child.name = "child";
  child.mass = 2.0;
  child.inertia = {0.1, 0.1, 0.1};
  child.parent = 0;
  Joint hinge;
  hinge.type = JointType::kRevolute;
  hinge.axis = {0, 2, 0};
  hinge.limits = JointLimits{-1, 1};
  hinge.actuator = ActuatorLimits{.max_effort = 10, .max_speed = 1};
  child.joint = hinge;
  v.bodies = {root, child};
  return v;
}

std::string errorOf(VehicleDescription v) {
  try {
    validate(v, "test.yaml");
  } catch (const InvalidInputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(VehicleDescriptionTest, ValidVehicleIsAcceptedAndAxesNormalised) {
  VehicleDescription v = twoBodies();
  validate(v, "test.yaml");
  EXPECT_NEAR(v.bodies[1].joint.axis.norm(), 1.0, kTolerance);
  EXPECT_EQ(v.totalMass(), 12.0);
  EXPECT_EQ(v.actuated(), std::vector<int>{1});
  EXPECT_EQ(v.find("child"), 1);
  EXPECT_EQ(v.find("none"), -1);
}

TEST(VehicleDescriptionTest, BadValuesAreRefusedByBodyAndField) {
  VehicleDescription v = twoBodies();
  v.bodies[1].mass = -2.0;
  EXPECT_THAT(errorOf(v), HasSubstr("test.yaml: body 'child': mass: -2 must be finite and > 0"));
  v = twoBodies();
  v.bodies[0].inertia = {1, 1, 3};
  EXPECT_THAT(errorOf(v), HasSubstr("violates the triangle inequality"));
  v = twoBodies();
  v.bodies[1].joint.axis = {0, 0, 0};
  EXPECT_THAT(errorOf(v), HasSubstr("body 'child': joint axis"));
  v = twoBodies();
  v.bodies[1].joint.limits = JointLimits{1, -1};
  EXPECT_THAT(errorOf(v), HasSubstr("lower <= upper"));
  v = twoBodies();
  v.bodies[1].joint.type = JointType::kBall;
  EXPECT_THAT(errorOf(v), HasSubstr("a ball joint has none"));
  v = twoBodies();
  v.bodies[1].joint.actuator->max_speed = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(errorOf(v), HasSubstr("actuator max_speed: nan"));
  v = twoBodies();
  v.bodies[1].name = "root";
  EXPECT_THAT(errorOf(v), HasSubstr("is used twice"));
  v = twoBodies();
  v.bodies[0].parent = 1;
  EXPECT_THAT(errorOf(v), HasSubstr("must name a body listed before it"));
  v = twoBodies();
  v.bodies[1].wheel = Wheel{};
  v.bodies[1].wheel->geometry.free_radius = -0.19;
  EXPECT_THAT(errorOf(v), HasSubstr("free_radius"));
  v = twoBodies();
  v.hitch = Hitch{.body_a = 0, .body_b = 0};
  EXPECT_THAT(errorOf(v), HasSubstr("hitch: body_a and body_b must name two different bodies"));
  v = twoBodies();
  v.hitch = Hitch{.body_a = 0, .body_b = 1, .stiffness = {1, -1, 1}};
  EXPECT_THAT(errorOf(v), HasSubstr("stiffness"));
}

// A size of 0 or 1e300 makes an inertia of 0 or inf; the size is what was
// typed, so the size is named (it used to be "inertia: (0.0044, 0, 0.0044)").
TEST(VehicleDescriptionTest, SizesAreNamedBeforeTheInertiaTheyMake) {
  for (const double radius : {0.0, 1e300}) {
    VehicleDescription v = twoBodies();
    Body& wheel = v.bodies[1];
    wheel.wheel = Wheel{};
    wheel.wheel->geometry.free_radius = radius;
    wheel.shape = discShape(radius);
    wheel.inertia = solidInertia(wheel.shape, wheel.mass);
    EXPECT_THAT(errorOf(v),
                testing::AllOf(HasSubstr("body 'child': wheel free_radius = "), testing::Not(HasSubstr("inertia"))))
        << radius;
  }
  VehicleDescription v = twoBodies();
  v.bodies[0].shape = boxShape({1e300, 1, 1});
  v.bodies[0].inertia = solidInertia(v.bodies[0].shape, v.bodies[0].mass);
  EXPECT_THAT(errorOf(v), HasSubstr("body 'root': shape box[0]: 1e+300 m is beyond the largest length a description "
                                    "may give, 1e+06 m (wtc::kMaxLengthM)"));
  v = twoBodies();
  v.bodies[0].pose.translation() = Eigen::Vector3d(0, 2e6, 0);
  EXPECT_THAT(errorOf(v), HasSubstr("body 'root': translation: (0, 2e+06, 0) m is beyond 1e+06 m of the origin"));
}

}  // namespace vehicle_description_test
}  // namespace wtc::vehicle
