#include "wtc/io/heightfield_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "temp_dir.hpp"
#include "wtc/base/error.hpp"

namespace wtc::io {
namespace {

using ::testing::AllOf;
using testing::errorOf;
using ::testing::HasSubstr;
using testing::samplesDir;

// Heights are decimal numbers read exactly as the nearest double; scaling
// multiplies once. 1e-15 m is a few ulps of the values used.
constexpr double kTolerance = 1e-15;

class HeightfieldFileTest : public testing::TempDirTest {};

TEST_F(HeightfieldFileTest, CsvIsAMapWithTheNorthRowFirst) {
  HeightfieldLayout layout;
  layout.spacing_x = 0.25;
  layout.spacing_y = 0.5;
  layout.origin = {1.0, 2.0, 3.0};
  layout.base_depth = 0.2;
  const Heightfield f = readHeightfieldCsv(samplesDir() / "bumps.csv", layout);
  EXPECT_EQ(f.rows, 4);
  EXPECT_EQ(f.cols, 5);
  EXPECT_EQ(f.spacing_x, 0.25);
  EXPECT_EQ(f.spacing_y, 0.5);
  EXPECT_EQ(f.origin, Eigen::Vector3d(1.0, 2.0, 3.0));
  EXPECT_EQ(f.base_depth, 0.2);
  // The 0.20 peak is on the file's third row, the grid's second (row 1).
  EXPECT_EQ(f.height(1, 2), 0.20);
  EXPECT_EQ(f.height(2, 2), 0.10);
  EXPECT_EQ(f.height(3, 2), 0.0);
}

TEST_F(HeightfieldFileTest, CsvAcceptsSpacesCommentsCrlfAndAByteOrderMark) {
  const auto path = write("spaces.csv", "\xEF\xBB\xBF# comment\r\n1 2\t+3\r\n\r\n  4 5 6e-1\r\n");
  const Heightfield f = readHeightfieldCsv(path, {.height_scale = 0.5});
  ASSERT_EQ(f.rows, 2);
  ASSERT_EQ(f.cols, 3);
  EXPECT_NEAR(f.height(1, 2), 1.5, kTolerance);  // north row: "1 2 +3"
  EXPECT_NEAR(f.height(0, 2), 0.3, kTolerance);
}

TEST_F(HeightfieldFileTest, CsvErrorsNameFileLineAndColumn) {
  // Case: a word among numbers.
  auto path = write("word.csv", "0, 1, 2\n3, abc, 5\n");
  EXPECT_THAT(errorOf([&] { readHeightfieldCsv(path); }),
              AllOf(HasSubstr(path.string() + ":2:4: 'abc' is not a number"), HasSubstr("row 2, value 2")));
  // Case: an empty field.
  path = write("empty_field.csv", "0,1,2\n0,,2\n");
  EXPECT_THAT(errorOf([&] { readHeightfieldCsv(path); }), HasSubstr(path.string() + ":2:3: empty value"));
  // Case: rows of different lengths.
  path = write("ragged.csv", "# header\n0,1,2\n0,1\n");
  EXPECT_THAT(errorOf([&] { readHeightfieldCsv(path); }),
              HasSubstr(path.string() + ":3:1: 2 values, but the first row (line 2) has 3"));
  // Case: non-finite values.
  path = write("nan.csv", "0,1\n0,nan\n");
  EXPECT_THAT(errorOf([&] { readHeightfieldCsv(path); }), HasSubstr(path.string() + ":2:3: 'nan' is not finite"));
  // Case: no data, one row only, a missing file.
  path = write("comments.csv", "# nothing\n\n");
  EXPECT_THAT(errorOf([&] { readHeightfieldCsv(path); }), HasSubstr(path.string() + ": no rows of heights"));
  path = write("one_row.csv", "1,2,3\n");
  EXPECT_THAT(errorOf([&] { readHeightfieldCsv(path); }), HasSubstr(path.string() + ": wtc::Heightfield: rows = 1"));
  EXPECT_THAT(errorOf([&] { readHeightfieldCsv(dir() / "missing.csv"); }),
              HasSubstr((dir() / "missing.csv").string() + ": file not found"));
  EXPECT_THAT(errorOf([&] { readHeightfieldFile(write("x.dem", "1")); }),
              HasSubstr("unknown heightfield format '.dem'"));
}

TEST_F(HeightfieldFileTest, TextPgmUsesGrayLevelsTimesScale) {
  const Heightfield f = readHeightfieldFile(samplesDir() / "crater.pgm", {.height_scale = 0.01});
  EXPECT_EQ(f.rows, 6);
  EXPECT_EQ(f.cols, 8);
  // Image row 2 (from the top) is grid row 3; its column 3 is the pit (level 1).
  EXPECT_NEAR(f.height(3, 3), 0.01, kTolerance);
  EXPECT_NEAR(f.height(4, 2), 0.09, kTolerance);  // image row 1: the rim
  EXPECT_EQ(f.height(5, 0), 0.0);
}

TEST_F(HeightfieldFileTest, BinaryPgmIn8And16Bits) {
  // 3 x 2 image, 8 bit: top row 0 1 2, bottom row 3 4 255.
  auto path = write("eight.pgm", std::string("P5\n# c\n3 2\n255\n") + std::string("\x00\x01\x02\x03\x04\xff", 6));
  Heightfield f = readHeightfieldPgm(path);
  EXPECT_EQ(f.height(1, 1), 1.0);
  EXPECT_EQ(f.height(0, 2), 255.0);
  // 2 x 2, 16 bit big-endian: 0x0102 = 258 first.
  path = write("sixteen.pgm", std::string("P5 2 2 65535\n") + std::string("\x01\x02\x00\x00\x00\x00\xff\xff", 8));
  f = readHeightfieldPgm(path, {.height_scale = 1e-4});
  EXPECT_NEAR(f.height(1, 0), 0.0258, kTolerance);
  EXPECT_NEAR(f.height(0, 1), 6.5535, 1e-12);
}

TEST_F(HeightfieldFileTest, BrokenPgmFilesAreNamed) {
  auto path = write("truncated.pgm", std::string("P5\n4 4\n255\n") + std::string(10, '\x10'));
  EXPECT_THAT(errorOf([&] { readHeightfieldPgm(path); }),
              HasSubstr(path.string() + ": truncated: the 4 x 4 image needs 16 bytes of pixel data, the file has 10"));
  path = write("color.pgm", "P6\n1 1\n255\nabc");
  EXPECT_THAT(errorOf([&] { readHeightfieldPgm(path); }),
              HasSubstr(path.string() + ":1:1: not a grayscale PGM file (magic number 'P6'"));
  path = write("over.pgm", "P2\n2 2\n9\n0 1\n2 12\n");
  EXPECT_THAT(errorOf([&] { readHeightfieldPgm(path); }),
              HasSubstr(path.string() + ":5:3: gray level 12 exceeds maxval 9"));
  path = write("short.pgm", "P2\n2 2\n9\n0 1\n2\n");
  EXPECT_THAT(errorOf([&] { readHeightfieldPgm(path); }), HasSubstr("file ends where gray level was expected"));
  path = write("garbage.pgm", "P2\n2 x2\n9\n");
  EXPECT_THAT(errorOf([&] { readHeightfieldPgm(path); }),
              HasSubstr(path.string() + ":2:3: 'x2' is not a valid height"));
  path = write("empty.pgm", "");
  EXPECT_THAT(errorOf([&] { readHeightfieldPgm(path); }), HasSubstr(path.string() + ": too short for a PGM file"));
}

}  // namespace
}  // namespace wtc::io
