// "A step allocates nothing once warm" (tyre_model.hpp), checked: this
// executable replaces the global operator new with a counting one, then runs
// warmed-up wheel steps for every effect set over ground with one and two
// contacts. Its own executable, so the counter sees only these tests.
#include <atomic>
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include "wheel_sim.hpp"
#include "wtc/terrain_primitives.hpp"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

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
    const long before = g_allocations.load();
    const std::size_t last = drive();
    EXPECT_EQ(g_allocations.load() - before, 0) << effects.toString();
    EXPECT_EQ(last, effects.has(Effect::kMultipleContacts) ? 2u : 1u) << "the foot of the ledge";
    // The counter works: a fresh state must allocate.
    WheelState fresh;
    model.step(ledge, WheelDescription{}, {{-0.188, 0.0, r - 0.002}, Vector3d::UnitY()}, motion, 1e-3, fresh);
    EXPECT_GT(g_allocations.load() - before, 0);
  }
}

}  // namespace
}  // namespace wtc
