// The ODE plugin's integration with ODE itself: the terrain mirrored as
// geoms for every other pair, the near callback's contract, errors that
// name the problem, diagnostics and the listener.
#include "wtc/ode/plugin.hpp"

#include <cmath>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "ode_fixture.hpp"
#include "wtc/base/error.hpp"
#include "wtc/terrain/terrain_primitives.hpp"
#include "wtc/tyre/contact_mode.hpp"

namespace wtc {
namespace ode_plugin_test {

using ::testing::HasSubstr;
using testing::kGravityMps2;
using testing::OdeWorld;
using ::testing::ThrowsMessage;
using WheelBody = testing::OdeWheel;

constexpr double kRadius = 0.19;       // r_f (m)
constexpr double kStiffness = 1e5;     // c (N/m)
constexpr double kStepSeconds = 1e-3;  // (s)
constexpr double kLedgeTop = 0.65;     // the spec's ledge (m)
constexpr ContactMode kModes[] = {ContactMode::kForce, ContactMode::kConstraint, ContactMode::kImplicit};

Terrain ledgeTerrain() {
  TerrainBuilder builder;
  addLedge(builder, {}, builder.addMaterial({}));
  return std::move(builder).build();
}

std::string shapeName(ode::TerrainShape shape) { return shape == ode::TerrainShape::kTriMesh ? "TriMesh" : "Convex"; }

class OdeTerrainShapeTest : public ::testing::TestWithParam<ode::TerrainShape> {};

// Case: the terrain's geoms are one per piece, in the plugin's space inside
// the program's, and are told apart from other geoms.
TEST_P(OdeTerrainShapeTest, EveryPieceIsAGeomOfTheTerrainSpace) {
  const Terrain ledge = ledgeTerrain();
  OdeWorld w(ledge, ContactMode::kForce, testing::Stepper::kStep, GetParam());
  const ode::TerrainGeoms& geoms = w.plugin->terrainGeoms();
  EXPECT_EQ(dSpaceGetNumGeoms(geoms.space()), static_cast<int>(ledge.pieceCount()));
  EXPECT_EQ(dGeomGetSpace(reinterpret_cast<dGeomID>(geoms.space())), w.space);
  for (PieceId id = 0; id < static_cast<PieceId>(ledge.pieceCount()); ++id) EXPECT_TRUE(geoms.contains(geoms.geom(id)));
  const WheelBody wheel = w.addWheelBody(3.7, {0, 0, 1});
  EXPECT_FALSE(geoms.contains(wheel.geom));
}

// Case: a box (a chassis, 0.6 x 0.4 x 0.2 m) dropped on the ledge's top
// collides with the terrain through ODE's own colliders: it comes to rest
// on the top, its centre 0.1 m above it, and stays level.
TEST_P(OdeTerrainShapeTest, ChassisRestsOnTheTerrainThroughOdesColliders) {
  constexpr double kRestM = 0.005;  // ODE's rigid contact sinks by its ERP/CFM, a few mm at most (m)
  const Terrain ledge = ledgeTerrain();
  OdeWorld w(ledge, ContactMode::kForce, testing::Stepper::kStep, GetParam());
  const dBodyID chassis = dBodyCreate(w.world);
  dMass m;
  dMassSetBoxTotal(&m, 10.0, 0.6, 0.4, 0.2);
  dBodySetMass(chassis, &m);
  dBodySetPosition(chassis, 1.0, 0, kLedgeTop + 0.3);
  dGeomSetBody(dCreateBox(w.space, 0.6, 0.4, 0.2), chassis);
  for (int k = 0; k < 2000; ++k) w.step(kStepSeconds);
  const Eigen::Vector3d p = testing::position(chassis);
  RecordProperty("chassis_height_error_mm", std::to_string((p.z() - kLedgeTop - 0.1) * 1e3));
  EXPECT_NEAR(p.z(), kLedgeTop + 0.1, kRestM);
  EXPECT_LT(testing::velocity(chassis).norm(), 1e-2);
  const dReal* rotation = dBodyGetRotation(chassis);
  EXPECT_GT(rotation[10], std::cos(0.01)) << "level within 10 mrad";
}

// Case: a wheel lying on its side touches the ground with a cut cap, which
// carries no tyre force (spec section 1); ODE collides the wheel's own
// cylinder there, so it rests on its side instead of sinking, in every mode
// and on both terrain shapes.
TEST_P(OdeTerrainShapeTest, WheelLyingOnItsSideRestsOnItsCap) {
  constexpr double kHalfTreadM = 0.06;  // the cylinder's half width (m)
  constexpr double kRestM = 0.005;      // ODE's rigid contact sinks a few mm at most (m)
  const Terrain ground = testing::flatGround();
  for (const ContactMode mode : kModes) {
    OdeWorld w(ground, mode, testing::Stepper::kStep, GetParam());
    const WheelBody wheel = w.addWheelBody(3.7, {0, 0, kHalfTreadM + 0.05});
    const dQuaternion upright_axis = {1, 0, 0, 0};  // the cylinder's axis (the axle, local z) vertical
    dBodySetQuaternion(wheel.body, upright_axis);
    const ode::WheelId id = testing::addWheel(w, wheel);
    for (int k = 0; k < 2000; ++k) w.step(kStepSeconds);
    EXPECT_NEAR(testing::position(wheel.body).z(), kHalfTreadM, kRestM) << contactModeName(mode);
    EXPECT_EQ(w.plugin->forces(id).contacts.size(), 0u) << "no tyre contact on a cap";
    EXPECT_FALSE(w.plugin->state(id).capContacts().empty());
  }
}

// Case: ODE gets the pieces as it expects them: faces counter-clockwise
// seen from outside and, for a convex geom, an origin inside (ODE prints a
// warning otherwise), even for a sliver whose bounding-box centre is
// outside it. A sphere pressed 1 cm into the sliver's slanted face
// x + y + 10 z = 1 is pushed out along that face's outward normal.
TEST_P(OdeTerrainShapeTest, PiecesAreGivenToOdeAsItExpects) {
  // The hull's face normals come from Qhull, to about 1e-9 (a sign error would be 2).
  constexpr double kNormalTolerance = 1e-6, kDepthToleranceM = 1e-6;
  TerrainBuilder builder;
  const MaterialId material = builder.addMaterial({});
  // Its box's centre (0.5, 0.5, 0.05) is outside it: 0.5 + 0.5 + 10 x 0.05 > 1.
  builder.addPiece(ConvexPolyhedron::fromPoints({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0.1}}), material);
  addLedge(builder, {}, material);
  const Terrain terrain = std::move(builder).build();
  ::testing::internal::CaptureStdout();  // ODE's convex warnings go to stdout
  const ode::TerrainGeoms geoms(terrain, nullptr, GetParam());
  EXPECT_THAT(::testing::internal::GetCapturedStdout(), ::testing::Not(HasSubstr("WARNING")));
  const Eigen::Vector3d normal = Eigen::Vector3d(1, 1, 10).normalized(), on_face(0.3, 0.3, 0.04);
  const double radius = 0.05, depth = 0.01;
  const Eigen::Vector3d centre = on_face + (radius - depth) * normal;
  const dGeomID sphere = dCreateSphere(nullptr, radius);
  dGeomSetPosition(sphere, centre.x(), centre.y(), centre.z());
  dContactGeom contact[4];
  const int n = dCollide(sphere, geoms.geom(0), 4, contact, sizeof(dContactGeom));
  dGeomDestroy(sphere);
  ASSERT_GE(n, 1);
  // ODE's normal points into the first geom: out of the piece.
  EXPECT_LT((Eigen::Vector3d(contact[0].normal[0], contact[0].normal[1], contact[0].normal[2]) - normal).norm(),
            kNormalTolerance);
  EXPECT_NEAR(contact[0].depth, depth, kDepthToleranceM);
}

INSTANTIATE_TEST_SUITE_P(Shapes, OdeTerrainShapeTest,
                         ::testing::Values(ode::TerrainShape::kTriMesh, ode::TerrainShape::kConvex),
                         [](const auto& info) { return shapeName(info.param); });

// Case: a wheel against a geom that is not terrain (a static block)
// collides as its own geom, a cylinder, through ODE: it rests on the block
// at its radius, with no WTC contact.
TEST(OdePluginTest, WheelAgainstAnotherGeomCollidesAsItsOwnShape) {
  const Terrain ground = testing::flatGround();
  OdeWorld w(ground, ContactMode::kConstraint);
  const dGeomID block = dCreateBox(w.space, 2.0, 2.0, 1.0);  // no body: static, top at z = 1
  dGeomSetPosition(block, 0, 0, 0.5);
  const WheelBody wheel = w.addWheelBody(3.7, {0, 0, 1.0 + kRadius + 0.01});
  testing::lockRotation(w, wheel.body);
  const ode::WheelId id = testing::addWheel(w, wheel);
  for (int k = 0; k < 2000; ++k) w.step(kStepSeconds);
  EXPECT_NEAR(testing::position(wheel.body).z(), 1.0 + kRadius, 0.005);
  EXPECT_TRUE(w.plugin->forces(id).contacts.empty()) << "the block is not terrain";
}

// Case: force mode hands ODE forces, no joints; constraint and implicit mode
// one joint per contact, whose feedback holds the weight at rest.
TEST(OdePluginTest, OnlyTheModesOdeSolvesCreateContactJoints) {
  const Terrain ground = testing::flatGround();
  for (const ContactMode mode : kModes) {
    OdeWorld w(ground, mode);
    const WheelBody wheel = w.addWheelBody(21.0, {0, 0, kRadius - 21.0 * kGravityMps2 / kStiffness});
    const ode::WheelId id = testing::addWheel(w, wheel);
    for (int k = 0; k < 1000; ++k) w.step(kStepSeconds);
    w.plugin->beginStep(kStepSeconds);
    w.collide();
    EXPECT_EQ(dBodyGetNumJoints(wheel.body), mode == ContactMode::kForce ? 0 : 1);
    dWorldStep(w.world, kStepSeconds);
    dJointGroupEmpty(w.contacts);
    if (mode == ContactMode::kForce) {
      EXPECT_TRUE(w.plugin->solvedContacts(id).empty());
    } else {
      ASSERT_EQ(w.plugin->solvedContacts(id).size(), 1u) << contactModeName(mode);
      EXPECT_NEAR(w.plugin->solvedContacts(id)[0].normalForce(), 21.0 * kGravityMps2, 1e-6 * 21.0 * kGravityMps2)
          << contactModeName(mode);
    }
    EXPECT_EQ(w.plugin->diagnostics(id).unhandled_steps, 0u);
  }
}

// Case: in constraint and implicit mode applied() is assembled from the
// contact joints' feedback once ODE has solved the step, and kept: asked between the near
// callback and the world step it counts the joints as no force and keeps
// nothing, so the same step's answer after the world step is ODE's; asked
// again, it is the same.
TEST(OdePluginTest, AppliedForcesAreTheSolvedStepsWhenEverAsked) {
  const Terrain ground = testing::flatGround();
  for (const ContactMode mode : {ContactMode::kConstraint, ContactMode::kImplicit}) {
    OdeWorld w(ground, mode);
    const double weight = 21.0 * kGravityMps2;
    const WheelBody wheel = w.addWheelBody(21.0, {0, 0, kRadius - weight / kStiffness});
    const ode::WheelId id = testing::addWheel(w, wheel);
    for (int k = 0; k < 1000; ++k) w.step(kStepSeconds);
    w.plugin->beginStep(kStepSeconds);
    w.collide();
    ASSERT_EQ(w.plugin->solvedContacts(id).size(), 1u) << contactModeName(mode);
    EXPECT_EQ(w.plugin->applied(id).contacts.size(), 1u) << contactModeName(mode);
    EXPECT_EQ(w.plugin->applied(id).force, Eigen::Vector3d::Zero()) << "before the world step: not solved yet";
    dWorldStep(w.world, kStepSeconds);
    dJointGroupEmpty(w.contacts);
    const Eigen::Vector3d solved = w.plugin->solvedContacts(id)[0].force();
    const WheelForces& after = w.plugin->applied(id);
    EXPECT_EQ(after.force, solved) << contactModeName(mode);
    EXPECT_NEAR(after.force.z(), weight, 1e-6 * weight) << contactModeName(mode);
    EXPECT_EQ(w.plugin->applied(id).force, solved) << "asked again";
    EXPECT_EQ(&w.plugin->applied(id), &after);
  }
}

// Case: force mode relies on ODE clearing the accumulated forces at the end
// of each world step (both steppers), so that beginStep's forces act on
// exactly one step: after a step the wheel carries none.
TEST(OdePluginTest, ForceModeForcesActOnExactlyOneStep) {
  const Terrain ground = testing::flatGround();
  for (const testing::Stepper stepper : {testing::Stepper::kStep, testing::Stepper::kQuickStep}) {
    OdeWorld w(ground, ContactMode::kForce, stepper);
    const WheelBody wheel = w.addWheelBody(21.0, {0, 0, kRadius - 0.001});
    testing::addWheel(w, wheel);
    w.plugin->beginStep(kStepSeconds);
    EXPECT_GT(dBodyGetForce(wheel.body)[2], 0.0) << "the tyre's force, accumulated";
    if (stepper == testing::Stepper::kStep) {
      dWorldStep(w.world, kStepSeconds);
    } else {
      dWorldQuickStep(w.world, kStepSeconds);
    }
    const dReal* force = dBodyGetForce(wheel.body);
    const dReal* torque = dBodyGetTorque(wheel.body);
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(force[i], 0.0);
      EXPECT_EQ(torque[i], 0.0);
    }
  }
}

// Case: a near callback that never calls handlePair leaves the wheel's
// contacts out of ODE; every such step is counted (and the wheel then meets
// the terrain as an ODE cylinder).
TEST(OdePluginTest, StepsWhoseContactsNeverReachOdeAreCounted) {
  const Terrain ground = testing::flatGround();
  OdeWorld w(ground, ContactMode::kConstraint);
  w.call_handle_pair = false;
  const WheelBody wheel = w.addWheelBody(3.7, {0, 0, kRadius - 0.001});
  const ode::WheelId id = testing::addWheel(w, wheel);
  for (int k = 0; k < 10; ++k) w.step(kStepSeconds);
  EXPECT_GT(w.plugin->diagnostics(id).unhandled_steps, 0u);
  EXPECT_LE(w.plugin->diagnostics(id).unhandled_steps, 10u);
}

// Case: ODE subtracts its contact surface layer from every depth; the plugin
// adds it back, so the wheel still settles at m g / c (2 %), in both modes
// whose contacts are ODE's joints.
TEST(OdePluginTest, ContactSurfaceLayerDoesNotSoftenTheTyre) {
  const Terrain ground = testing::flatGround();
  for (const ContactMode mode : {ContactMode::kConstraint, ContactMode::kImplicit}) {
    OdeWorld w(ground, mode);
    dWorldSetContactSurfaceLayer(w.world, 0.001);  // ODE's demos' value (m)
    const WheelBody wheel = w.addWheelBody(21.0, {0, 0, kRadius + 0.01});
    testing::addWheel(w, wheel);
    for (int k = 0; k < 3000; ++k) w.step(kStepSeconds);
    const double expected = 21.0 * kGravityMps2 / kStiffness;
    EXPECT_NEAR(kRadius - testing::position(wheel.body).z(), expected, 0.02 * expected) << contactModeName(mode);
  }
}

// Case: a correcting-velocity cap below ERP Z / h cuts the tyre's spring;
// the plugin counts the contacts it cut.
TEST(OdePluginTest, CorrectingVelocityCapThatCutsTheSpringIsCounted) {
  const Terrain ground = testing::flatGround();
  OdeWorld w(ground, ContactMode::kConstraint);
  const WheelBody wheel = w.addWheelBody(21.0, {0, 0, kRadius - 21.0 * kGravityMps2 / kStiffness});
  const ode::WheelId id = testing::addWheel(w, wheel);
  w.step(kStepSeconds);
  EXPECT_EQ(w.plugin->diagnostics(id).capped_contacts, 0u) << "default cap: infinity";
  // At rest ERP Z / h = (h c / (h c + b)) (m g / c) / h = 0.21 m/s.
  dWorldSetContactMaxCorrectingVel(w.world, 0.1);  // ODE's demos' value (m/s)
  w.step(kStepSeconds);
  EXPECT_EQ(w.plugin->diagnostics(id).capped_contacts, 1u);
}

// Implicit mode is the tyre's spring solved by ODE: a cap on the rows'
// correcting velocity would cut it, so beginStep refuses a finite cap and
// says which setting (issue 41; the departure: docs/tyre-model.md).
TEST(OdePluginTest, ImplicitModeRefusesACorrectingVelocityCap) {
  const Terrain ground = testing::flatGround();
  OdeWorld w(ground, ContactMode::kImplicit);
  const WheelBody wheel = w.addWheelBody(21.0, {0, 0, kRadius - 21.0 * kGravityMps2 / kStiffness});
  testing::addWheel(w, wheel);
  EXPECT_NO_THROW(w.step(kStepSeconds)) << "default cap: infinity";
  dWorldSetContactMaxCorrectingVel(w.world, 0.1);
  EXPECT_THAT([&] { w.plugin->beginStep(kStepSeconds); },
              ::testing::ThrowsMessage<InvalidInputError>(::testing::HasSubstr("dWorldSetContactMaxCorrectingVel")));
}

// Case: rolling resistance opposes the wheel's rolling over the ground,
// its absolute spin about the axle, whatever carries it: f_r R_z r_0
// against the spin in either direction.
TEST(OdePluginTest, RollingResistanceOpposesTheWheelsRollingOverTheGround) {
  const Terrain ground = testing::flatGround();
  OdeWorld w(ground, ContactMode::kForce);
  const WheelBody wheel = w.addWheelBody(21.0, {0, 0, kRadius - 21.0 * kGravityMps2 / kStiffness});
  ode::RigidWheel spec;
  spec.body = wheel.body;
  spec.geom = wheel.geom;
  const ode::WheelId id = w.plugin->addWheel(spec);
  for (const double spin : {5.0, -5.0}) {  // about the axle, world y (rad/s)
    dBodySetAngularVel(wheel.body, 0, spin, 0);
    w.plugin->beginStep(kStepSeconds);
    const ContactForce& c = w.plugin->forces(id).contacts[0];
    EXPECT_NEAR(c.rolling_moment.y(), -std::copysign(0.018 * c.normal_force * 0.97 * kRadius, spin),
                1e-9 * c.normal_force)
        << "spin " << spin;
  }
}

class CountingListener : public ode::WheelListener {
 public:
  void onWheelStep(ode::WheelId wheel, const WheelForces& forces, double step_seconds) override {
    ++calls[wheel];
    last_step_seconds = step_seconds;
    last_contacts = forces.contacts.size();
  }
  int calls[2] = {0, 0};
  double last_step_seconds = 0.0;
  std::size_t last_contacts = 0;
};

// Case: the listener hears every wheel once per beginStep, with its forces
// and the step length.
TEST(OdePluginTest, ListenerHearsEveryWheelOncePerStep) {
  const Terrain ground = testing::flatGround();
  OdeWorld w(ground, ContactMode::kForce);
  testing::addWheel(w, w.addWheelBody(3.7, {0, 0, kRadius - 0.001}));
  testing::addWheel(w, w.addWheelBody(3.7, {2, 0, kRadius - 0.001}));
  CountingListener listener;
  w.plugin->setListener(&listener);
  for (int k = 0; k < 5; ++k) w.step(2e-3);
  EXPECT_EQ(listener.calls[0], 5);
  EXPECT_EQ(listener.calls[1], 5);
  EXPECT_EQ(listener.last_step_seconds, 2e-3);
  EXPECT_EQ(listener.last_contacts, 1u);
}

// Case: a wheel whose body state goes NaN: beginStep applies nothing for it
// (no force, no contact joint), counts it and tells the listener, and
// throws nothing; the other wheel keeps its tyre force. Every mode.
TEST(OdePluginTest, NonFiniteWheelIsSkippedCountedAndReportedWithoutThrowing) {
  struct Recorder : ode::WheelListener {
    void onWheelStep(ode::WheelId wheel, const WheelForces&, double) override { ++steps[wheel]; }
    void onWheelSkipped(ode::WheelId wheel, double) override { ++skipped[wheel]; }
    int steps[2] = {0, 0}, skipped[2] = {0, 0};
  };
  const Terrain ground = testing::flatGround();
  for (const ContactMode mode : kModes) {
    Recorder recorder;
    OdeWorld w(ground, mode);
    const WheelBody good = w.addWheelBody(3.7, {0, 0, kRadius - 0.001});
    const WheelBody bad = w.addWheelBody(3.7, {2, 0, kRadius - 0.001});
    testing::addWheel(w, good);
    testing::addWheel(w, bad);
    w.plugin->setListener(&recorder);
    w.step(1e-3);
    dBodySetLinearVel(bad.body, std::nan(""), 0, 0);
    // The plugin's part of the step alone: ODE itself would spread the NaN.
    for (int k = 0; k < 5; ++k) {
      EXPECT_NO_THROW(w.plugin->beginStep(1e-3));
      w.collide();
      EXPECT_EQ(dBodyGetNumJoints(bad.body), 0);
      dJointGroupEmpty(w.contacts);
    }
    EXPECT_EQ(recorder.skipped[1], 5) << contactModeName(mode);
    EXPECT_EQ(recorder.steps[1], 1) << contactModeName(mode);
    EXPECT_EQ(recorder.skipped[0], 0) << contactModeName(mode);
    EXPECT_EQ(recorder.steps[0], 6) << contactModeName(mode);
    EXPECT_EQ(w.plugin->state(1).nonFiniteSteps(), 5u);
    EXPECT_TRUE(w.plugin->forces(1).contacts.empty());
    EXPECT_FALSE(w.plugin->forces(0).contacts.empty());
    const dReal* f = dBodyGetForce(bad.body);
    EXPECT_EQ(f[0], 0.0);  // nothing added (ODE keeps what is added until its step)
    EXPECT_EQ(f[2], 0.0);
  }
}

// Case: bad registrations and steps are errors that name the problem.
// The tyre's stability bounds use the mass the wheel's contacts move
// (issue 11, defect 1): the plugin reads it from the body unless told to
// take the description's. A 21 kg body with the description's default
// 3.7 kg: the stability report's mass says which was used.
TEST(OdePluginTest, TheTyreTakesTheWheelBodysMassAndInertiaUnlessToldOtherwise) {
  const Terrain ground = testing::flatGround();
  OdeWorld w(ground, ContactMode::kForce);
  const WheelBody heavy = w.addWheelBody(21.0, {0, 0, kRadius - 0.002});
  const WheelBody told = w.addWheelBody(21.0, {2, 0, kRadius - 0.002});
  ode::RigidWheel spec;
  spec.body = heavy.body;
  spec.geom = heavy.geom;
  const ode::WheelId from_body = w.plugin->addWheel(spec);
  spec.body = told.body;
  spec.geom = told.geom;
  spec.inertia_source = InertiaSource::kDescription;
  const ode::WheelId from_description = w.plugin->addWheel(spec);
  w.step(1e-3);
  EXPECT_DOUBLE_EQ(w.plugin->forces(from_body).normal_stability.mass, 21.0);
  EXPECT_DOUBLE_EQ(w.plugin->forces(from_description).normal_stability.mass, spec.description.inertia.effective_mass);
}

TEST(OdePluginTest, BadRegistrationIsAnErrorThatNamesIt) {
  const Terrain ground = testing::flatGround();
  OdeWorld w(ground, ContactMode::kConstraint);
  const WheelBody wheel = w.addWheelBody(3.7, {0, 0, 1});
  const WheelBody other = w.addWheelBody(3.7, {2, 0, 1});
  ode::RigidWheel spec;
  auto refused = [&](const char* message) {
    EXPECT_THAT([&] { w.plugin->addWheel(spec); }, ThrowsMessage<InvalidInputError>(HasSubstr(message))) << message;
  };
  refused("body is null");
  spec.body = wheel.body;
  refused("geom is null");
  spec.geom = other.geom;
  refused("geom is not attached to body");
  spec.geom = wheel.geom;
  spec.axle_local = Eigen::Vector3d::Zero();
  refused("axle_local = (0, 0, 0)");
  spec.axle_local = Eigen::Vector3d::UnitZ();
  spec.description.tyre.radial_stiffness = -5;
  refused("radial_stiffness = -5");
  spec.description.tyre.radial_stiffness = kStiffness;
  spec.description.geometry.free_radius = 0.25;  // larger than the 0.19 m cylinder
  refused("does not hold the tread");
  spec.description.geometry.free_radius = kRadius;
  w.plugin->addWheel(spec);
  refused("already a registered wheel");
  EXPECT_THAT([&] { w.plugin->beginStep(0.0); }, ThrowsMessage<InvalidInputError>(HasSubstr("step_seconds = 0")));
  EXPECT_THROW(w.plugin->forces(7), std::out_of_range);
}

}  // namespace ode_plugin_test
}  // namespace wtc
