// The six-wheel robot from URDF (vehicles/six_wheel_robot_urdf.yaml) and
// from YAML (six_wheel_robot.yaml) give the same robot_ledge series in both
// engines and both modes (issue 37, item 3), and the towed system from its
// two URDFs (towed_system_urdf.yaml) towed_path's: every CSV the run writes, every
// number to 1e-9 (they are byte-identical: the two descriptions are equal
// field by field). A 3 s run here, to the approach and the first fold; the
// full 25 s run is measured in docs/urdf.md.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "scratch_path.hpp"
#include "sim_test_support.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/scene_file.hpp"
#include "wtc/sim/scene_run.hpp"

namespace wtc::testing {
namespace urdf_equivalence_test {

namespace fs = std::filesystem;
const fs::path kRoot = fs::path(WTC_SOURCE_DIR);
constexpr double kSeriesTolerance = 1e-9;  // relative to max(1, |value|): the bound

fs::path runScene(const std::string& scene, const std::string& engine, const std::string& mode,
                  const std::string& vehicle_file) {
  const fs::path out = wtc::test::scratchPath("wtc_urdf_equivalence_" + engine + "_" + mode + "_" +
                                              fs::path(vehicle_file).stem().string());
  fs::remove_all(out);
  fs::create_directories(out);
  const sim::Scene s = sim::loadScene(
      kRoot / "scenes" / (scene + ".yaml"),
      atImplicitModeStep({{"engine", engine}, {"mode", mode}, {"duration", "3"}, {"vehicle.file", vehicle_file}}));
  const auto e = sim::makeEngine(s.engine, *s.terrain, s.vehicle, s.placement);
  sim::RunOptions options;
  options.out_dir = out;
  sim::runScene(s, *e, options);
  return out;
}

std::vector<std::string> lines(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) out.push_back(cell);
  return out;
}

// Every CSV of `a` against its namesake in `b`, cell by cell.
void expectSameSeries(const fs::path& a, const fs::path& b, const std::string& label) {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(a)) {
    if (entry.path().extension() != ".csv") continue;
    ++files;
    const std::string name = entry.path().filename().string();
    const auto la = lines(entry.path());
    const auto lb = lines(b / name);
    ASSERT_EQ(la.size(), lb.size()) << label << ", " << name;
    ASSERT_GT(la.size(), 2u) << label << ", " << name;
    EXPECT_EQ(la[0], lb[0]) << label << ", " << name << ": header";
    for (std::size_t row = 1; row < la.size(); ++row) {
      const auto ca = cells(la[row]);
      const auto cb = cells(lb[row]);
      ASSERT_EQ(ca.size(), cb.size()) << label << ", " << name << " row " << row;
      for (std::size_t c = 0; c < ca.size(); ++c) {
        if (ca[c] == cb[c]) continue;
        const double x = std::stod(ca[c]);
        const double y = std::stod(cb[c]);
        ASSERT_LE(std::abs(x - y), kSeriesTolerance * std::max(1.0, std::abs(x)))
            << label << ", " << name << " row " << row << " column " << c;
      }
    }
  }
  EXPECT_GE(files, 3) << label;
}

TEST(UrdfEquivalenceTest, RobotLedgeSeriesFromUrdfEqualTheYamlRobotsInBothEnginesAndModes) {
  for (const auto& [engine, mode] : everyEngineByName(Variants::kLeftOut)) {
    const std::string label = engine + ", " + mode;
    const fs::path yaml = runScene("robot_ledge", engine, mode, "../vehicles/six_wheel_robot.yaml");
    const fs::path urdf = runScene("robot_ledge", engine, mode, "../vehicles/six_wheel_robot_urdf.yaml");
    expectSameSeries(yaml, urdf, label);
  }
}

// The towed system from its two URDFs and two YAML casters
// (vehicles/towed_system_urdf.yaml): towed_path's series, 3 s.
TEST(UrdfEquivalenceTest, TowedPathSeriesFromUrdfEqualTheYamlSystemsInBothEnginesAndModes) {
  for (const auto& [engine, mode] : everyEngineByName(Variants::kLeftOut)) {
    const std::string label = engine + ", " + mode;
    const fs::path yaml = runScene("towed_path", engine, mode, "../vehicles/towed_system.yaml");
    const fs::path urdf = runScene("towed_path", engine, mode, "../vehicles/towed_system_urdf.yaml");
    expectSameSeries(yaml, urdf, label);
  }
}

}  // namespace urdf_equivalence_test
}  // namespace wtc::testing
