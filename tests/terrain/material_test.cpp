#include "wtc/terrain/material.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "wtc/base/error.hpp"

namespace wtc {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

std::string messageOf(const Material& material, const std::string& where) {
  try {
    validate(material, where);
  } catch (const InvalidInputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(MaterialTest, DefaultIsValidAsphaltConcrete) {
  const Material asphalt;
  EXPECT_NO_THROW(validate(asphalt, "test"));
  EXPECT_EQ(asphalt.mu_max, 0.8);
  EXPECT_EQ(asphalt.rolling_resistance, 0.018);
}

TEST(MaterialTest, ZeroFrictionAndZeroResistanceAreAllowed) {
  Material ice;
  ice.name = "ice";
  ice.mu_max = 0.0;
  ice.rolling_resistance = 0.0;
  EXPECT_NO_THROW(validate(ice, "test"));
}

TEST(MaterialTest, MessagesNameTheFieldTheValueAndWhere) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Case: s1 must be positive (it divides the slip).
  Material m;
  m.name = "mud";
  m.s1 = 0.0;
  EXPECT_THAT(messageOf(m, "mud.yaml:4:3"),
              AllOf(HasSubstr("'mud'"), HasSubstr("mud.yaml:4:3"), HasSubstr("s1 = 0"), HasSubstr("> 0")));
  // Case: non-finite and negative values.
  m = Material{};
  m.mu_max = nan;
  EXPECT_THAT(messageOf(m, "here"), AllOf(HasSubstr("mu_max = nan"), HasSubstr("here")));
  m = Material{};
  m.s2 = -0.1;
  EXPECT_THAT(messageOf(m, "here"), HasSubstr("s2 = -0.1"));
  m = Material{};
  m.rolling_resistance = std::numeric_limits<double>::infinity();
  EXPECT_THAT(messageOf(m, "here"), HasSubstr("rolling_resistance = inf"));
  // Case: a material needs a name (terrain files refer to it).
  m = Material{};
  m.name.clear();
  EXPECT_THAT(messageOf(m, "here"), HasSubstr("name is empty"));
}

}  // namespace
}  // namespace wtc
