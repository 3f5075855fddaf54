// Effects: names as scenes write them, and the assembly of the tyre model.
#include "wtc/tyre/effects.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "wtc/base/error.hpp"
#include "wtc/tyre/tyre_model.hpp"

namespace wtc {
namespace {

using ::testing::HasSubstr;

TEST(EffectsTest, EveryEffectHasADistinctNameThatParsesBack) {
  for (unsigned k = 0; k < static_cast<unsigned>(Effect::kCount); ++k) {
    const Effect e = static_cast<Effect>(k);
    const EffectSet parsed = EffectSet::parse({std::string(effectName(e))}, "test");
    EXPECT_EQ(parsed, EffectSet{e}) << effectName(e);
    EXPECT_EQ(parsed.toString(), effectName(e));
  }
}

TEST(EffectsTest, FullAndMinimalPresetsAddUp) {
  EXPECT_EQ(EffectSet::parse({"minimal"}, "test"), EffectSet::minimal());
  EXPECT_EQ(EffectSet::parse({"full"}, "test"), EffectSet::full());
  EXPECT_EQ(EffectSet::minimal().toString(), "minimal");
  EXPECT_EQ(EffectSet::full().toString(),
            "normal_damping, slip_traction, rolling_resistance, multiple_contacts, tread_truncation");
  const EffectSet set = EffectSet::parse({"minimal", "rolling_resistance", "normal_damping"}, "test");
  EXPECT_TRUE(set.has(Effect::kRollingResistance));
  EXPECT_TRUE(set.has(Effect::kNormalDamping));
  EXPECT_FALSE(set.has(Effect::kSlipTraction));
  EXPECT_EQ(set.without(Effect::kNormalDamping), EffectSet{Effect::kRollingResistance});
}

TEST(EffectsTest, UnknownNameIsAnErrorThatNamesItAndWhere) {
  try {
    EffectSet::parse({"normal_damping", "traction"}, "scene.yaml:12:5");
    FAIL() << "no exception";
  } catch (const InvalidInputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("scene.yaml:12:5"));
    EXPECT_THAT(error.what(), HasSubstr("'traction'"));
    EXPECT_THAT(error.what(), HasSubstr("slip_traction"));
  }
}

TEST(EffectsTest, TyreModelRefusesTwoTractionLaws) {
  const EffectSet both{Effect::kSlipTraction, Effect::kCoulombFriction};
  try {
    TyreModel model(both);
    FAIL() << "no exception";
  } catch (const InvalidInputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("slip_traction, coulomb_friction"));
  }
}

TEST(EffectsTest, ContactLevelEffectsBecomeContactOptions) {
  const TyreModel minimal(EffectSet::minimal());
  EXPECT_FALSE(minimal.contactOptions().multiple_contacts);
  EXPECT_FALSE(minimal.contactOptions().tread_truncation);
  EXPECT_TRUE(minimal.contactOptions().seam_rule);  // not an effect: a flat ground must never double its load
  const TyreModel full(EffectSet::full());
  EXPECT_TRUE(full.contactOptions().multiple_contacts);
  EXPECT_TRUE(full.contactOptions().tread_truncation);
  EXPECT_EQ(full.effects(), EffectSet::full());
}

}  // namespace
}  // namespace wtc
