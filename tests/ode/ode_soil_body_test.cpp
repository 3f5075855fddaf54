// A user's own ODE body on soft soil through the ODE plugin
// (Plugin::addSoilBody, keepRigidContacts; wtc/tyre/body_soil.hpp):
// registered, a box dropped on sand settles at Bekker's plate sinkage, the
// near callback keeping none of its rigid contacts with the sand; not
// registered, the sand is hard ground for it. Registration refuses what it
// cannot serve.
#include <gtest/gtest.h>

#include <string>

#include "ode_fixture.hpp"
#include "expect_refused.hpp"
#include "soil_plate.hpp"
#include "wtc/base/error.hpp"

namespace wtc::testing {
namespace ode_soil_body_test {

constexpr double kMassKg = 150.0, kStepS = 4e-4;
const Eigen::Vector3d kSizeM(0.5, 0.3, 0.1);  // a belly, its edges on the 2 cm cells' edges

dBodyID addBox(OdeWorld& w) {
  const dBodyID body = dBodyCreate(w.world);
  dMass m;
  dMassSetBoxTotal(&m, kMassKg, kSizeM.x(), kSizeM.y(), kSizeM.z());
  dBodySetMass(body, &m);
  dBodySetPosition(body, 0.0, 0.0, 0.5 * kSizeM.z() + 0.01);
  dGeomSetBody(dCreateBox(w.space, kSizeM.x(), kSizeM.y(), kSizeM.z()), body);
  return body;
}

std::vector<ConvexPolyhedron> boxHull() { return {ConvexPolyhedron::box(-0.5 * kSizeM, 0.5 * kSizeM)}; }

double settledBottom(bool registered) {
  const Terrain sand = soilSlab("toyoura_sand", 4.0, 4.0);
  OdeWorld w(sand, ContactMode::kForce);
  const dBodyID box = addBox(w);
  if (registered) w.plugin->addSoilBody({.body = box, .hulls = boxHull()});
  for (int k = 0; k < 3750; ++k) w.step(kStepS);
  return position(box).z() - 0.5 * kSizeM.z();
}

TEST(OdeSoilBodyTest, ARegisteredBoxSettlesAtBekkersPlateSinkageAnOtherOnTheSurface) {
  const double bekker = bekkerPlateSinkage(*namedSoil("toyoura_sand"), kMassKg * kGravityMps2, 0.5, 0.3);
  EXPECT_NEAR(-settledBottom(true), bekker, 0.01 * bekker);
  EXPECT_NEAR(settledBottom(false), 0.0, 2e-3);  // ODE's own contact, within its slop
}

TEST(OdeSoilBodyTest, RegistrationRefusesWhatItCannotServe) {
  const Terrain sand = soilSlab("toyoura_sand", 4.0, 4.0);
  OdeWorld w(sand, ContactMode::kForce);
  const dBodyID box = addBox(w);
  const auto refused = [&](const ode::SoilBody& spec, const std::string& words) {
    expectRefused([&] { w.plugin->addSoilBody(spec); }, {words, "addSoilBody"});
  };
  refused({.body = nullptr, .hulls = boxHull()}, "null");
  refused({.body = box, .hulls = {}}, "at least one convex hull");
  const OdeWheel wheel = w.addWheelBody(10.0, {2.0, 0.0, 0.2});
  addWheel(w, wheel);
  refused({.body = wheel.body, .hulls = boxHull()}, "registered wheel");
  EXPECT_EQ(w.plugin->addSoilBody({.body = box, .hulls = boxHull()}), 0);
  refused({.body = box, .hulls = boxHull()}, "already a soil body");
  EXPECT_THROW(w.plugin->soilForces(1), InvalidInputError);
}

}  // namespace ode_soil_body_test
}  // namespace wtc::testing
