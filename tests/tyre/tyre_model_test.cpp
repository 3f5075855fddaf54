// The tyre model, one step at a time, against analytic answers: the normal
// law, traction's direction and bound, its steady state (the spec's law),
// rolling resistance, the wrench split, the removal of each effect, bounded
// gain near zero velocity, finiteness, and named errors.
#include "wtc/tyre/tyre_model.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <random>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "wheel_sim.hpp"
#include "wtc/base/error.hpp"
#include "wtc/terrain/terrain_primitives.hpp"
#include "wtc/tyre/traction_law.hpp"

namespace wtc {
namespace tyre_model_test {

using Eigen::Vector3d;
using ::testing::HasSubstr;
using testing::tiltedSlab;

constexpr double kTolerance = 1e-9;     // relative, for closed-form answers
constexpr double kDeflectionM = 0.002;  // Z of the flat-ground cases (m)
constexpr double kStepSeconds = 1e-3;   // h (s)

const WheelDescription kWheel{};
const double kRadius = kWheel.geometry.free_radius;

WheelPose onFlat(double deflection = kDeflectionM) { return {{0.0, 0.0, kRadius - deflection}, Vector3d::UnitY()}; }

// A wheel in the foot of the default 0.65 m ledge (face x = 0): 2 mm into
// the face and 3 mm into the ground, so two contacts.
WheelPose inLedgeFoot() { return {{-kRadius + 0.002, 0.0, kRadius - 0.003}, Vector3d::UnitY()}; }

Terrain ledge() {
  TerrainBuilder builder;
  addLedge(builder, {}, builder.addMaterial({}));
  return std::move(builder).build();
}

WheelMotion motion(const Vector3d& velocity, const Vector3d& angular_velocity = Vector3d::Zero()) {
  WheelMotion m;
  m.velocity = velocity;
  m.angular_velocity = angular_velocity;
  return m;
}

bool finite(const WheelForces& f) {
  bool ok = f.force.allFinite() && f.torque.allFinite() && f.axial_moment.allFinite() && f.bearing_moment.allFinite();
  for (const ContactForce& c : f.contacts) {
    ok = ok && std::isfinite(c.normal_force) && std::isfinite(c.mu) && std::isfinite(c.slip_ratio) &&
         c.tangential_force.allFinite() && c.force.allFinite() && c.rolling_moment.allFinite() &&
         c.slip_velocity.allFinite();
  }
  return ok;
}

TEST(TyreModelTest, NormalForceIsStiffnessTimesDeflectionTowardTheCentre) {
  const Terrain flat = tiltedSlab(0.0);
  const TyreModel model(EffectSet::minimal());
  WheelState state;
  const WheelForces& f = model.step(flat, kWheel, onFlat(), {}, kStepSeconds, state);
  ASSERT_EQ(f.contacts.size(), 1u);
  EXPECT_NEAR(f.contacts[0].normal_force, 1e5 * kDeflectionM, kTolerance * 200);
  EXPECT_TRUE(f.force.isApprox(Vector3d(0, 0, 200), kTolerance));
  EXPECT_NEAR(f.torque.norm(), 0.0, kTolerance);
  EXPECT_TRUE(f.contacts[0].contact.point.isApprox(Vector3d(0, 0, -kDeflectionM), kTolerance));
}

TEST(TyreModelTest, DampingAddsBTimesDeflectionRateAndTheGroundNeverPulls) {
  const Terrain flat = tiltedSlab(0.0);
  WheelState state;
  // Case: moving down at 1 cm/s: v_z = +0.01, R_z = 200 + 900 x 0.01.
  const TyreModel damped(EffectSet{Effect::kNormalDamping});
  EXPECT_NEAR(damped.step(flat, kWheel, onFlat(), motion({0, 0, -0.01}), kStepSeconds, state).force.z(), 209.0,
              kTolerance * 209);
  // Case: leaving at 1 m/s: c Z + b v_z = 200 - 900 < 0, so nothing at all.
  const TyreModel full(EffectSet::full());
  const WheelForces& f = full.step(flat, kWheel, onFlat(), motion({0.5, 0, 1.0}, {0, 3, 0}), kStepSeconds, state);
  ASSERT_EQ(f.contacts.size(), 1u);
  EXPECT_EQ(f.contacts[0].normal_force, 0.0);
  EXPECT_EQ(f.force, Vector3d::Zero());
  EXPECT_EQ(f.torque, Vector3d::Zero());
}

TEST(TyreModelTest, TractionOpposesSlipAndNeverExceedsMuTimesNormalForce) {
  std::mt19937_64 random(20261121);
  std::uniform_real_distribution<double> speed(-3.0, 3.0), spin(-20.0, 20.0), depth(1e-4, 0.02);
  for (const double s2 : {0.0, 0.3, 4.44}) {
    Material ground;
    ground.s2 = s2;
    const Terrain flat = tiltedSlab(0.0, ground);
    const TyreModel model(EffectSet::full());
    WheelState carried;  // tread state carried through a random sequence
    for (int k = 0; k < 2000; ++k) {
      const WheelMotion m =
          motion({speed(random), speed(random), 0.1 * speed(random)}, {spin(random), spin(random), spin(random)});
      const WheelPose pose = onFlat(depth(random));
      // Case: the first step from rest opposes the slip velocity along each
      // tread axis (x along the ground, y along the axle; their springs
      // differ where the step caps them for the mass each moves).
      WheelState fresh;
      const ContactForce& first = model.step(flat, kWheel, pose, m, kStepSeconds, fresh).contacts[0];
      EXPECT_LE(first.tangential_force.dot(first.slip_velocity), 0.0);
      EXPECT_LE(first.tangential_force.x() * first.slip_velocity.x(), 0.0);
      EXPECT_LE(first.tangential_force.y() * first.slip_velocity.y(), 0.0);
      // Case: with history, the bound |R_xy| <= peak(mu) R_z still holds.
      const ContactForce& c = model.step(flat, kWheel, pose, m, kStepSeconds, carried).contacts[0];
      EXPECT_LE(c.tangential_force.norm(), tractionPeak(ground) * c.normal_force * (1 + 1e-12) + 1e-12);
      EXPECT_NEAR(c.mu * c.normal_force, c.tangential_force.norm(), 1e-9 * (1 + c.normal_force));
      EXPECT_NEAR(c.tangential_force.dot(c.contact.e), 0.0, 1e-9 * (1 + c.tangential_force.norm()));
    }
  }
}

// Case: a wheel driven at a constant transport speed and slip ratio reaches
// the spec's force mu(s) R_z, opposing the slip.
TEST(TyreModelTest, SteadyTractionIsTheSlipLaw) {
  for (const double s2 : {0.0, 0.3}) {
    Material ground;
    ground.s2 = s2;
    const Terrain flat = tiltedSlab(0.0, ground);
    const TyreModel model(EffectSet{Effect::kSlipTraction});
    for (const double slip : {0.02, 0.1, 0.5, 2.0}) {
      const double transport = 1.0;  // V_t (m/s), above the standstill speed: no tread damping
      // V_P = V_O + omega x OP with OP = -r z: spinning at omega_y drives the
      // contact point backward at -omega_y r... choose V_s = -slip V_t along x.
      const double omega_y = (transport + slip * transport) / kRadius;
      WheelState state;
      const ContactForce* c = nullptr;
      for (int k = 0; k < 4000; ++k) {
        c = &model.step(flat, kWheel, onFlat(), motion({transport, 0, 0}, {0, omega_y, 0}), kStepSeconds, state)
                 .contacts[0];
      }
      EXPECT_NEAR(c->slip_ratio, slip, 1e-12);
      const double expected = tractionCoefficient(ground, slip) * c->normal_force;
      EXPECT_NEAR(c->tangential_force.x(), expected, 2e-4 * expected) << "s2 = " << s2 << ", s = " << slip;
      EXPECT_NEAR(c->tangential_force.y(), 0.0, 1e-9);
    }
  }
}

TEST(TyreModelTest, RollingResistanceOpposesTheWheelsSpin) {
  const Terrain flat = tiltedSlab(0.0);
  const TyreModel model(EffectSet{Effect::kRollingResistance});
  WheelState state;
  const double full_moment = 0.018 * 200.0 * 0.97 * kRadius;  // f_r R_z r_0 (N m)
  for (const double spin : {-5.0, -0.5, 0.5, 5.0}) {
    const WheelForces& f = model.step(flat, kWheel, onFlat(), motion({0, 0, 0}, {0, spin, 0}), kStepSeconds, state);
    EXPECT_NEAR(f.axial_moment.y(), -std::copysign(full_moment, spin), kTolerance * full_moment) << spin;
    EXPECT_NEAR(f.contacts[0].rolling_moment.y(), f.axial_moment.y(), 1e-15);
  }
  // Case: at zero spin, zero moment; near zero, a ramp whose gain is at most kappa I / h.
  EXPECT_EQ(model.step(flat, kWheel, onFlat(), {}, kStepSeconds, state).axial_moment, Vector3d::Zero());
  const double gain_bound = kWheel.tyre.stability_fraction * kWheel.inertia.axial_inertia / kStepSeconds;
  double previous = 0.0;
  for (double spin = 1e-4; spin < 1.0; spin += 1e-4) {
    const double moment =
        model.step(flat, kWheel, onFlat(), motion({0, 0, 0}, {0, spin, 0}), kStepSeconds, state).axial_moment.y();
    EXPECT_LE(previous - moment, gain_bound * 1e-4 * (1 + 1e-9));
    EXPECT_LE(moment, previous + 1e-15);  // monotone
    previous = moment;
  }
}

// Issue 11, defect 5: rolling resistance is hysteresis of the tread rolling
// over the ground; it acts on the wheel, so its power M_r . omega must never
// be positive. The law took its sign from the spin relative to the hub:
// a braked wheel (turning forward at 0.1 rad/s relative to its section)
// on a section pitching nose-down at 1 rad/s (omega . a = -0.9) got
// M_r = -f_r R_z r_0 a and fed in +0.9 f_r R_z r_0 W. Random motions, on
// flat ground and in the ledge's foot (two contacts), at 1e-6 to 0.1 s.
TEST(TyreModelTest, RollingResistanceNeverFeedsEnergyIn) {
  const TyreModel model(EffectSet::full());
  WheelState state;
  const Terrain flat = tiltedSlab(0.0), steps = ledge();
  const WheelForces& braked = model.step(flat, kWheel, onFlat(), motion({0, 0, 0}, {0, -0.9, 0}), kStepSeconds, state);
  ASSERT_EQ(braked.contacts.size(), 1u);
  EXPECT_LT(braked.rolling_moment.dot(Vector3d(0, -0.9, 0)), 0.0);
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  auto any = [&](double scale) -> Vector3d {
    return Vector3d(uniform(random), uniform(random), uniform(random)) * scale;
  };
  int contacts = 0;
  for (int k = 0; k < 20000; ++k) {
    const Terrain& ground = k % 2 == 0 ? flat : steps;
    const WheelPose pose = k % 2 == 0 ? onFlat() : inLedgeFoot();
    const double scale = std::array{1e-4, 1e-2, 1.0, 10.0}[k % 4];
    const WheelMotion m = motion(any(scale), any(scale));
    const WheelForces& f = model.step(ground, kWheel, pose, m, std::array{1e-6, 1e-3, 0.1}[k % 3], state);
    for (const ContactForce& c : f.contacts) {
      ASSERT_LE(c.rolling_moment.dot(m.angular_velocity), 0.0) << "step " << k;
      ++contacts;
    }
  }
  EXPECT_GT(contacts, 20000);
}

TEST(TyreModelTest, WrenchSplitsIntoAxialAndBearingMoments) {
  const Terrain steps = ledge();
  const TyreModel model(EffectSet::full());
  WheelState state;
  const WheelForces& f =
      model.step(steps, kWheel, inLedgeFoot(), motion({0.3, 0.05, -0.02}, {0.1, 2.0, 0.2}), kStepSeconds, state);
  ASSERT_EQ(f.contacts.size(), 2u);
  Vector3d force = Vector3d::Zero(), torque = Vector3d::Zero();
  for (const ContactForce& c : f.contacts) {
    force += c.force;
    torque += (c.contact.point - inLedgeFoot().center).cross(c.force) + c.rolling_moment;
  }
  EXPECT_TRUE(f.force.isApprox(force, kTolerance));
  EXPECT_TRUE(f.torque.isApprox(torque, kTolerance));
  EXPECT_TRUE((f.axial_moment + f.bearing_moment).isApprox(f.torque, kTolerance));
  EXPECT_NEAR(f.axial_moment.cross(Vector3d::UnitY()).norm(), 0.0, kTolerance * f.torque.norm());
  EXPECT_NEAR(f.bearing_moment.y(), 0.0, kTolerance * f.torque.norm());
}

// Every force effect, removed from the full model, removes its own term and
// changes nothing it does not feed (traction and rolling resistance read
// R_z, so damping is compared on the normal force only).
TEST(TyreModelTest, EachEffectSwitchedOffRemovesExactlyItsContribution) {
  const Terrain steps = ledge();
  const WheelMotion m = motion({0.3, 0.05, -0.02}, {0.1, 2.0, 0.2});
  auto run = [&](EffectSet effects) {
    WheelState state;
    const WheelForces& f = TyreModel(effects).step(steps, kWheel, inLedgeFoot(), m, kStepSeconds, state);
    return std::vector<ContactForce>(f.contacts.begin(), f.contacts.end());
  };
  const std::vector<ContactForce> all = run(EffectSet::full());
  ASSERT_EQ(all.size(), 2u);
  // Case: damping.
  const auto undamped = run(EffectSet::full().without(Effect::kNormalDamping));
  for (std::size_t k = 0; k < all.size(); ++k) {
    EXPECT_NEAR(all[k].normal_force - undamped[k].normal_force, 900.0 * all[k].deflection_rate, 1e-9);
    EXPECT_NEAR(undamped[k].normal_force, 1e5 * all[k].contact.deflection, 1e-9);
  }
  // Case: traction.
  const auto frictionless = run(EffectSet::full().without(Effect::kSlipTraction));
  for (std::size_t k = 0; k < all.size(); ++k) {
    EXPECT_EQ(frictionless[k].normal_force, all[k].normal_force);
    EXPECT_EQ(frictionless[k].rolling_moment, all[k].rolling_moment);
    EXPECT_EQ(frictionless[k].tangential_force, Vector3d::Zero());
    EXPECT_TRUE((frictionless[k].force + all[k].tangential_force).isApprox(all[k].force, 1e-15));
  }
  // Case: rolling resistance.
  const auto free_rolling = run(EffectSet::full().without(Effect::kRollingResistance));
  for (std::size_t k = 0; k < all.size(); ++k) {
    EXPECT_EQ(free_rolling[k].force, all[k].force);
    EXPECT_EQ(free_rolling[k].rolling_moment, Vector3d::Zero());
    EXPECT_NE(all[k].rolling_moment, Vector3d::Zero());
  }
  // Case: multiple contacts: only the deepest (3 mm into the ground), unchanged.
  const auto deepest = run(EffectSet::full().without(Effect::kMultipleContacts));
  ASSERT_EQ(deepest.size(), 1u);
  const ContactForce& ground = all[0].contact.deflection > all[1].contact.deflection ? all[0] : all[1];
  EXPECT_EQ(deepest[0].contact.piece, ground.contact.piece);
  EXPECT_EQ(deepest[0].force, ground.force);
  // Case: tread truncation: a wheel lying on its side (axle vertical) touches
  // with a cap, which only the full sphere keeps.
  const Terrain flat = tiltedSlab(0.0);
  const WheelPose on_side{{0, 0, kRadius - kDeflectionM}, Vector3d::UnitZ()};
  WheelState state;
  EXPECT_EQ(TyreModel(EffectSet::full()).step(flat, kWheel, on_side, {}, kStepSeconds, state).contacts.size(), 0u);
  EXPECT_EQ(TyreModel(EffectSet::full().without(Effect::kTreadTruncation))
                .step(flat, kWheel, on_side, {}, kStepSeconds, state)
                .contacts.size(),
            1u);
}

// Case: near V_s = 0 (a locked wheel, V_P = V_O), the force from rest is
// continuous, zero at zero, and its gain is below (kappa^2 + 2 zeta kappa)
// m / h <= m / h: an explicit step cannot reverse the slip.
TEST(TyreModelTest, TractionNearZeroSlipIsContinuousWithBoundedGain) {
  const Terrain flat = tiltedSlab(0.0);
  for (const TyreModel& model :
       {TyreModel(EffectSet::full()),
        TyreModel(EffectSet::full().without(Effect::kSlipTraction).with(Effect::kCoulombFriction))}) {
    for (const double h : {1e-4, 1e-3, 2e-3}) {
      for (const double mass : {3.7, 21.0}) {
        WheelDescription wheel;
        wheel.inertia.effective_mass = mass;
        // The mass the contact moves: along the ground (x) the wheel and
        // its spin, 1 / (1/m + r^2/I); along the axle (y) the wheel.
        const double r = wheel.geometry.free_radius;
        const double rolling_mass = 1.0 / (1.0 / mass + r * r / wheel.inertia.axial_inertia);
        for (const int axis : {0, 1}) {
          const double moved = axis == 0 ? rolling_mass : mass;
          const double kappa = wheel.tyre.stability_fraction, zeta = wheel.tyre.standstill_damping_ratio;
          const double bound = (kappa * kappa + 2 * zeta * kappa) * moved / h;
          ASSERT_LE(bound, moved / h);
          const double dv = 1e-6;  // (m/s)
          double previous = 0.0;
          for (int k = -1000; k <= 1000; ++k) {
            WheelState state;
            const double v = k * dv;
            const Vector3d velocity = v * Vector3d::Unit(axis);
            const double f =
                model.step(flat, wheel, onFlat(), motion(velocity), h, state).contacts[0].tangential_force[axis];
            if (k == 0) {
              EXPECT_EQ(f, 0.0);
            }
            if (k > -1000) {
              EXPECT_LE(std::abs(f - previous), bound * dv * (1 + 1e-6))
                  << model.effects().toString() << " h = " << h << " m = " << mass << " axis " << axis << " v = " << v;
            }
            EXPECT_LE(f * v, 0.0);
            previous = f;
          }
        }
      }
    }
  }
}

// What an engine adapter reads from a wheel body: its mass, and the moment
// a^T I a about the (normalized) axle. A static body is refused by name.
TEST(TyreModelTest, BodyInertiaIsTheMassAndTheMomentAboutTheAxle) {
  const Eigen::Matrix3d inertia = Eigen::Vector3d(1.0, 2.0, 3.0).asDiagonal();
  const WheelInertia i = bodyInertia(21.0, inertia, {1.0, 1.0, 0.0}, true, "test");
  EXPECT_DOUBLE_EQ(i.effective_mass, 21.0);
  EXPECT_NEAR(i.axial_inertia, 1.5, 1e-15);
  EXPECT_TRUE(i.spin_held);
  EXPECT_THAT([&] { bodyInertia(std::numeric_limits<double>::infinity(), inertia, {0, 1, 0}, false, "wheel 3"); },
              ::testing::ThrowsMessage<InvalidInputError>(HasSubstr("wheel 3: the wheel body's mass inf")));
  EXPECT_THAT([&] { bodyInertia(21.0, Eigen::Matrix3d::Zero(), {0, 1, 0}, false, "wheel 3"); },
              ::testing::ThrowsMessage<InvalidInputError>(HasSubstr("axial_inertia = 0")));
}

TEST(TyreModelTest, CoulombSlidesAtMuMaxTimesNormalForce) {
  const Terrain flat = tiltedSlab(0.0);
  const TyreModel model(EffectSet{Effect::kCoulombFriction});
  WheelState state;
  const ContactForce* c = nullptr;
  for (int k = 0; k < 100; ++k) {
    c = &model.step(flat, kWheel, onFlat(), motion({0.5, 0, 0}), kStepSeconds, state).contacts[0];
  }
  EXPECT_NEAR(c->tangential_force.x(), -0.8 * 200.0, 1e-9);
  EXPECT_NEAR(c->mu, 0.8, 1e-12);
}

TEST(TyreModelTest, NoNanOrInfinityForAnyFiniteInput) {
  std::mt19937_64 random(7);
  std::uniform_int_distribution<int> pick(0, 5);
  const double magnitudes[] = {0.0, 1e-300, 1e-9, 1.0, 1e3, 1e6};
  auto any = [&] { return Vector3d(magnitudes[pick(random)], -magnitudes[pick(random)], magnitudes[pick(random)]); };
  Material frictionless;
  frictionless.name = "ice";
  frictionless.mu_max = 0.0;
  Material sticky;
  sticky.name = "sticky";
  sticky.s2 = 50.0;
  sticky.s1 = 1e-6;
  for (const Material& ground : {Material{}, frictionless, sticky}) {
    const Terrain flat = tiltedSlab(0.0, ground);
    for (const EffectSet effects :
         {EffectSet::full(), EffectSet::full().without(Effect::kSlipTraction).with(Effect::kCoulombFriction)}) {
      const TyreModel model(effects);
      WheelState state;
      for (int k = 0; k < 3000; ++k) {
        WheelMotion m;
        m.velocity = any();
        m.angular_velocity = any();
        // Depths from touching to the centre deep inside the slab.
        const double depth = std::array{0.0, 1e-12, 0.002, 0.19, 0.3}[k % 5];
        const WheelForces& f = model.step(flat, kWheel, onFlat(depth), m, std::array{1e-6, 1e-3, 0.1}[k % 3], state);
        ASSERT_TRUE(finite(f)) << ground.name << " " << effects.toString() << " step " << k;
      }
    }
  }
}

// Case: the springs of a wheel's contacts act in parallel; in the ledge's
// foot (face and ground, both full contacts) the explicit step sees 2c, so
// its step number is sqrt(2) times a flat-ground wheel's (issue: a V-valley
// doubles the stiffness), and the report names it with the largest stable step.
TEST(TyreModelTest, StabilityCountsTheStiffnessOfEveryContact) {
  const Terrain ground = ledge();
  const TyreModel model;
  WheelState foot_state, flat_state;
  const WheelForces& foot =
      model.step(ground, kWheel, inLedgeFoot(), motion(Vector3d::Zero()), kStepSeconds, foot_state);
  ASSERT_EQ(foot.contacts.size(), 2u);
  double shares = 0.0;
  for (const ContactForce& c : foot.contacts) shares += c.contact.load_share;
  EXPECT_GT(shares, 1.99);
  const double c = kWheel.tyre.radial_stiffness;
  EXPECT_NEAR(foot.normal_stability.stiffness, shares * c, kTolerance * c);
  const SpringStability foot_stability = foot.normal_stability;
  const WheelForces& flat =
      model.step(testing::tiltedSlab(0.0), kWheel, onFlat(), motion(Vector3d::Zero()), kStepSeconds, flat_state);
  ASSERT_EQ(flat.contacts.size(), 1u);
  EXPECT_NEAR(foot_stability.step_number, std::sqrt(shares) * flat.normal_stability.step_number, 1e-12);
  EXPECT_THAT(describe(foot_stability), HasSubstr("the largest stable step is"));
}

TEST(TyreModelTest, BadInputIsAnErrorThatNamesIt) {
  const Terrain flat = tiltedSlab(0.0);
  const TyreModel model;
  WheelState state;
  auto message = [&](const WheelDescription& wheel, const WheelMotion& m, double h) {
    try {
      model.step(flat, wheel, onFlat(), m, h, state);
    } catch (const InvalidInputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(message(kWheel, motion({std::nan(""), 0, 0}), kStepSeconds), HasSubstr("wheel motion is not finite"));
  EXPECT_THAT(message(kWheel, {}, 0.0), HasSubstr("step_seconds = 0"));
  EXPECT_THAT(message(kWheel, {}, -1e-3), HasSubstr("step_seconds = -0.001"));
  WheelDescription bad = kWheel;
  bad.tyre.radial_stiffness = -1.0;
  EXPECT_THAT(message(bad, {}, kStepSeconds), HasSubstr("radial_stiffness = -1"));
  bad = kWheel;
  bad.inertia.effective_mass = 0.0;
  EXPECT_THAT(message(bad, {}, kStepSeconds), HasSubstr("effective_mass = 0"));
  bad = kWheel;
  bad.geometry.free_radius = -0.19;
  EXPECT_THAT(message(bad, {}, kStepSeconds), HasSubstr("free_radius = -0.19"));
}

}  // namespace tyre_model_test
}  // namespace wtc
