// "A step allocates nothing once warm" (tyre_model.hpp), checked: this
// executable links the counting operator new (tests/support/allocation_counter.hpp), then runs
// warmed-up wheel steps for every effect set over ground with one and two
// contacts. Its own executable, so the counter sees only these tests.
#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "wheel_sim.hpp"
#include "wtc/terrain/terrain_primitives.hpp"

namespace wtc {
namespace {

using Eigen::Vector3d;

TEST(TyreAllocationTest, WarmStepsAllocateNothingForAnyEffectSet) {
  TerrainBuilder builder;
  LedgeParams params;
  params.approach_tiles = 8;  // seams on the way to the face
  addLedge(builder, params, builder.addMaterial({}));
  const Terrain ledge = std::move(builder).build();
  const double r = WheelDescription{}.geometry.free_radius;
  std::vector<EffectSet> sets = {EffectSet::full(), EffectSet::minimal(),
                                 EffectSet::full().without(Effect::kSlipTraction).with(Effect::kCoulombFriction)};
  for (unsigned k = 0; k < static_cast<unsigned>(Effect::kCount); ++k) sets.push_back({static_cast<Effect>(k)});
  for (const EffectSet effects : sets) {
    if (effects.has(Effect::kSlipTraction) && effects.has(Effect::kCoulombFriction)) continue;
    const TyreModel model(effects);
    WheelState state;
    WheelMotion motion;
    motion.velocity = {0.5, 0.0, 0.0};
    motion.angular_velocity = {0.0, 1.05 * 0.5 / r, 0.0};
    // Approach the face over the seams, 1 mm per step, into the two-contact foot.
    auto drive = [&] {
      std::size_t contacts = 0;
      for (int mm = -1000; mm <= -188; ++mm) {
        const Vector3d centre{1e-3 * mm, 0.0, r - 0.002};
        contacts =
            model.step(ledge, WheelDescription{}, {centre, Vector3d::UnitY()}, motion, 1e-3, state).contacts.size();
      }
      return contacts;
    };
    drive();  // warm up: buffers reach their sizes
    const long before = testing::allocationCount();
    const std::size_t last = drive();
    EXPECT_EQ(testing::allocationCount() - before, 0) << effects.toString();
    EXPECT_EQ(last, effects.has(Effect::kMultipleContacts) ? 2u : 1u) << "the foot of the ledge";
    // The counter works: a fresh state must allocate.
    WheelState fresh;
    model.step(ledge, WheelDescription{}, {{-0.188, 0.0, r - 0.002}, Vector3d::UnitY()}, motion, 1e-3, fresh);
    EXPECT_GT(testing::allocationCount() - before, 0);
  }
}

}  // namespace
}  // namespace wtc
