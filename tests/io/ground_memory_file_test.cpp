// The ruts of soil that remembers in a file (wtc/io/ground_memory_file.hpp):
// a memory written and read back is the same to the bit, node by node and
// where the wheels read it between nodes; a file that does not fit the
// terrain's soil regions is refused with its file, line and reason.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "temp_dir.hpp"
#include "wtc/io/ground_memory_file.hpp"
#include "wtc/io/terrain_file.hpp"

namespace wtc::io {
namespace {

using testing::errorOf;
using ::testing::HasSubstr;

constexpr double kSpacingM = 0.02;

// An 8 m slab of Toyoura sand with two soil regions, at 2 cm from
// (-1, -1) and at 5 cm from (2, -1); or with none.
const std::string kSandYaml =
    "materials: {sand: {soil: toyoura_sand}}\n"
    "pieces: [{type: slab, size: [8, 8], thickness: 0.5}]\n";
const std::string kRegionsYaml =
    "soil_regions:\n"
    "  - {corners: [-1, -1, 1, 1], spacing: 0.02}\n"
    "  - {corners: [2, -1, 4, 1], spacing: 0.05}\n";

using Nodes = std::map<std::pair<double, double>, std::tuple<double, double, bool>>;

Nodes nodesOf(const GroundMemory& memory) {
  Nodes nodes;
  memory.forEachTouchedNode([&](double x, double y, const SoilMemory& m) {
    nodes[{x, y}] = {m.plastic_sinkage, m.max_pressure, m.fresh};
  });
  return nodes;
}

class GroundMemoryFileTest : public testing::TempDirTest {
 protected:
  Terrain sand(bool regions = true) const {
    return loadTerrain(write("sand.yaml", kSandYaml + (regions ? kRegionsYaml : "")));
  }
};

TEST_F(GroundMemoryFileTest, AMemoryWrittenAndReadBackIsTheSameToTheBit) {
  const Terrain terrain = sand();
  GroundMemory memory(terrain);
  // Ruts, raised berms and pressures no float or bfloat16 holds exactly, in both regions.
  int written = 0;
  for (int k = 0; k < 400; ++k) {
    const double x = -1.0 + kSpacingM * (k % 37), y = -1.0 + kSpacingM * (k / 37 * 3);
    const double sinkage = 0.031 * std::sin(0.7 * k) - 0.004, pressure = 1234.5678 * (1 + k % 11) + 0.1 * k;
    written += memory.setNode(x, y, {.plastic_sinkage = sinkage, .max_pressure = pressure, .fresh = false});
  }
  written += memory.setNode(2.0 + 0.05 * 7, -1.0 + 0.05 * 3, {.plastic_sinkage = 0.0123, .max_pressure = 4.5e4});
  ASSERT_EQ(written, 401);
  ASSERT_EQ(memory.touchedNodes(), 401u);

  const auto path = dir() / "ruts.csv";
  writeGroundMemoryCsv(path, memory);
  GroundMemory back(terrain);
  readGroundMemoryCsv(path, back);
  EXPECT_EQ(nodesOf(back), nodesOf(memory));
  // Where a wheel reads between nodes, too.
  for (const auto& [x, y] : {std::pair{-0.987, -0.951}, {-0.5031, -0.4}, {2.361, -0.83}, {0.3, 0.9}}) {
    const SoilMemory a = memory.at(x, y), b = back.at(x, y);
    EXPECT_EQ(a.plastic_sinkage, b.plastic_sinkage) << x << ", " << y;
    EXPECT_EQ(a.max_pressure, b.max_pressure) << x << ", " << y;
  }
  // Written again, the same text: one line a node, in a set order.
  const auto again = dir() / "again.csv";
  writeGroundMemoryCsv(again, back);
  std::ifstream a(path), b(again);
  const std::string text_a{std::istreambuf_iterator<char>(a), {}}, text_b{std::istreambuf_iterator<char>(b), {}};
  EXPECT_EQ(text_a, text_b);
  EXPECT_EQ(std::count(text_a.begin(), text_a.end(), '\n'), 401 + 3);  // and three comment lines
}

TEST_F(GroundMemoryFileTest, APointOffTheGridOrOutsideTheRegionsIsNotANode) {
  GroundMemory memory(sand());
  const SoilMemory rut{.plastic_sinkage = 0.01, .max_pressure = 2e4, .fresh = false};
  EXPECT_TRUE(memory.setNode(-1.0 + 3 * kSpacingM + 1e-9, 0.0, rut));  // within 1e-6 of the spacing
  EXPECT_FALSE(memory.setNode(-1.0 + 3 * kSpacingM + 1e-6, 0.0, rut));
  EXPECT_FALSE(memory.setNode(1.5, 0.0, rut));  // between the regions
  EXPECT_FALSE(memory.setNode(std::nan(""), 0.0, rut));
  EXPECT_FALSE(memory.setNode(0.0, 0.0, {.plastic_sinkage = 1e39, .max_pressure = 1.0}));
  EXPECT_FALSE(memory.setNode(0.0, 0.0, {.plastic_sinkage = 0.0, .max_pressure = -1.0}));
  EXPECT_FALSE(memory.setNode(0.0, 0.0, {.plastic_sinkage = std::numeric_limits<double>::infinity()}));
  EXPECT_EQ(memory.touchedNodes(), 1u);
}

TEST_F(GroundMemoryFileTest, AFileThatDoesNotFitIsRefusedWithItsLineAndReason) {
  const Terrain terrain = sand();
  const auto refused = [&](const std::string& text) {
    GroundMemory memory(terrain);
    return errorOf([&] { readGroundMemoryCsv(write("bad.csv", text), memory); });
  };
  const std::string header = "# x_m,y_m,plastic_sinkage_m,max_pressure_pa\n";
  EXPECT_THAT(refused(header + "0,0,0.01,2e4\n0.013,0,0.01,2e4\n"),
              HasSubstr("bad.csv:3:1: (0.013, 0) is no node of the terrain's soil regions"));
  EXPECT_THAT(refused(header + "1.5,0,0.01,2e4\n"), HasSubstr("bad.csv:2:1: (1.5, 0) is no node"));
  EXPECT_THAT(refused(header + "0,0,0.01\n"),
              HasSubstr("bad.csv:2:1: 3 values; a node's line has 4: x_m, y_m, plastic_sinkage_m, max_pressure_pa"));
  EXPECT_THAT(refused(header + "0,0,0.01,-5\n"), HasSubstr("bad.csv:2:1: max_pressure_pa -5 must be >= 0"));
  EXPECT_THAT(refused(header + "0,0,0.01,1e40\n"), HasSubstr("bad.csv:2:1: a value beyond single precision"));
  EXPECT_THAT(refused(header + "0,0,deep,2e4\n"), HasSubstr("bad.csv:2:5: 'deep' is not a number (row 1, value 3)"));
  EXPECT_THAT(errorOf([&] {
                GroundMemory memory(terrain);
                readGroundMemoryCsv(dir() / "missing.csv", memory);
              }),
              HasSubstr("missing.csv: file not found"));
  GroundMemory forgetful(sand(false));
  EXPECT_THAT(errorOf([&] { readGroundMemoryCsv(write("ruts.csv", header), forgetful); }),
              HasSubstr("ruts.csv: ruts given, but the terrain has no soil regions to hold them"));
}

}  // namespace
}  // namespace wtc::io
