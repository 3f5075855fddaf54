// The mobility settings file: the defaults, any value changed by the file,
// and every bad value refused at its file:line:col with the key.
#include "wtc/mobility/mobility_settings.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scratch_path.hpp"
#include "wtc/base/error.hpp"

namespace wtc::mobility {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

fs::path write(const std::string& text) {
  const fs::path path = wtc::test::scratchPath("wtc_mobility_settings_test.yaml");
  std::ofstream(path) << text;
  return path;
}

std::string errorOf(const std::string& text) {
  try {
    loadMobilitySettings(write(text));
  } catch (const InvalidInputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(MobilitySettingsTest, AnEmptyFileGivesTheDefaultsAndTheShippedFileIsValid) {
  const MobilitySettings d = loadMobilitySettings(write(""));
  EXPECT_EQ(d.ground.mu_max, 0.8);
  EXPECT_EQ(d.ground.rolling_resistance, 0.018);
  EXPECT_EQ(d.step.height_m.resolution, 0.01);  // the 1 cm
  EXPECT_EQ(d.coast.speed_mps, 1.0);
  EXPECT_EQ(d.braking.speed_mps, 2.0);
  EXPECT_EQ(d.events, eventNames());
  EXPECT_NO_THROW(validate(d));
  const MobilitySettings shipped =
      loadMobilitySettings(fs::path(WTC_SOURCE_DIR) / "apps" / "wtc-mobility" / "settings.yaml");
  EXPECT_NO_THROW(validate(shipped));
  EXPECT_EQ(shipped.grade.degrees.high, d.grade.degrees.high);  // it states the defaults
}

TEST(MobilitySettingsTest, TheFileChangesAnyValue) {
  const MobilitySettings s =
      loadMobilitySettings(write("ground: {mu_max: 0.6, s2: 0.3, rolling_resistance: 0.04}\n"
                                 "engines: [ode]\nmodes: [force, constraint]\ndt: 0.0002\nevents: [grade, coast]\n"
                                 "grade: {degrees: [5, 35, 0.5], min_progress: 0.2}\n"
                                 "drawbar: {slips: [0.1, 0.5], speed: 0.2}\nstep: {vehicle_controller: false}\n"));
  EXPECT_EQ(s.ground.mu_max, 0.6);
  EXPECT_EQ(s.ground.s2, 0.3);
  EXPECT_EQ(s.engines, std::vector<std::string>{"ode"});
  EXPECT_EQ(s.modes.size(), 2u);
  EXPECT_EQ(s.dt_s, 0.0002);
  EXPECT_EQ(s.events, (std::vector<std::string>{"grade", "coast"}));
  EXPECT_EQ(s.grade.degrees.low, 5.0);
  EXPECT_EQ(s.grade.degrees.high, 35.0);
  EXPECT_EQ(s.grade.degrees.resolution, 0.5);
  EXPECT_EQ(s.grade.min_progress_m, 0.2);
  EXPECT_EQ(s.drawbar.slips, (std::vector<double>{0.1, 0.5}));
  EXPECT_EQ(s.drawbar.speed_mps, 0.2);
  EXPECT_FALSE(s.step.vehicle_controller);
  EXPECT_EQ(s.coast.speed_mps, 1.0);  // untouched
}

TEST(MobilitySettingsTest, BadSettingsAreRefusedAtTheirLineAndColumn) {
  EXPECT_THAT(errorOf("grades: {}\n"), HasSubstr(":1:1: unknown key 'grades'"));
  EXPECT_THAT(errorOf("grade:\n  degree: [0, 1, 0.1]\n"), HasSubstr(":2:3: grade: unknown key 'degree'"));
  EXPECT_THAT(errorOf("grade: {degrees: [30, 10, 0.5]}\n"),
              HasSubstr(":1:18: grade.degrees: high 10 must exceed low 30"));
  EXPECT_THAT(errorOf("grade: {degrees: [0, 10, 0]}\n"), HasSubstr("grade.degrees: resolution 0 must be > 0"));
  EXPECT_THAT(errorOf("step: {height: [0, 1]}\n"), HasSubstr(":1:16: step.height ([low, high, resolution])"));
  EXPECT_THAT(errorOf("coast: {speed: -1}\n"), HasSubstr(":1:16: coast.speed: -1 must be > 0"));
  EXPECT_THAT(errorOf("coast: {speed: fast}\n"), HasSubstr("coast.speed: 'fast' is not a number"));
  EXPECT_THAT(errorOf("drawbar: {slips: [0.1, 1.0]}\n"),
              HasSubstr(":1:24: drawbar.slips: slip 1 must be in [0, 1) (the driving slip i)"));
  EXPECT_THAT(errorOf("events: [grade, climb]\n"), HasSubstr(":1:17: events: 'climb' is not an event"));
  EXPECT_THAT(errorOf("engines: [physx]\n"), HasSubstr(":1:11: engines: unknown engine 'physx'"));
  EXPECT_THAT(errorOf("modes: [rigid]\n"), HasSubstr(":1:9: modes: 'rigid'"));
  EXPECT_THAT(errorOf("ground: {mu_max: -0.8}\n"),
              HasSubstr(":1:9: wtc::Material 'ground' (ground): mu_max = -0.8 must be finite and >= 0"));
  EXPECT_THAT(errorOf("ground: {s2: 1, mu_peak: 1}\n"), HasSubstr("give either s2 or mu_peak, not both"));
  EXPECT_THAT(errorOf("dt: 0\n"), HasSubstr(":1:5: dt: must be > 0 s"));
  EXPECT_THAT(errorOf("step: {vehicle_controller: maybe}\n"), HasSubstr("step.vehicle_controller"));
  EXPECT_THAT(errorOf("turn: {wheel_rate: 1, wheel_rate: 2}\n"), HasSubstr("duplicate key 'wheel_rate'"));
  MobilitySettings s;
  s.parked.degrees.resolution = -1;
  EXPECT_THROW(validate(s), InvalidInputError);
}

// The command line's --engine and --mode reach validate, not the file's
// reader: refused there too, before any scene is written.
TEST(MobilitySettingsTest, UnknownEnginesAndModesFromTheCommandLineAreRefusedByName) {
  const auto problem = [](const MobilitySettings& s) {
    try {
      validate(s);
    } catch (const InvalidInputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  MobilitySettings s;
  s.engines = {"bullet", "physx"};
  EXPECT_THAT(problem(s), HasSubstr("unknown engine 'physx'"));
  s = MobilitySettings();
  s.modes = {"rigid"};
  EXPECT_THAT(problem(s), HasSubstr("modes: 'rigid'"));
  EXPECT_EQ(problem(MobilitySettings()), "");
}

}  // namespace
}  // namespace wtc::mobility
