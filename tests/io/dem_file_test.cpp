// DEMs (wtc/io/dem_file.hpp): rasters written here through GDAL's own API
// (not through writeDemGeoTiff, so that the reader is checked against what
// GDAL means by a geotransform, a unit and a no-data value), .npy files
// written byte by byte after numpy.lib.format, and the bad ones of
// docs/bad-input.md.
#include "wtc/io/dem_file.hpp"

#include <gdal.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <ogr_srs_api.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "gdal_raster.hpp"
#include "temp_dir.hpp"
#include "wtc/base/error.hpp"
#include "wtc/io/file_limits.hpp"
#include "wtc/io/heightfield_file.hpp"
#include "wtc/io/terrain_file.hpp"

namespace wtc::io {
namespace {

using testing::Raster;
using testing::writeRaster;

using ::testing::AllOf;
using testing::errorOf;
using ::testing::HasSubstr;

// Float32 holds these test heights (multiples of 1/64 m below 100 m) exactly.
constexpr double kExact = 0.0;

// A 4 x 3 raster of 0.5 m pixels whose top-left corner is at (1000, 2003):
// pixel centres x = 1000.25 ... 1001.75, y = 2002.75 (top row) ... 2001.75.
Raster smallRaster() {
  Raster r;
  r.cols = 4;
  r.rows = 3;
  r.values = {10.0, 11.0, 12.0, 13.0,   // north row
              20.0, 21.0, 22.0, 23.0,   //
              30.0, 31.0, 32.0, 33.5};  // south row
  r.geotransform = std::array<double, 6>{1000.0, 0.5, 0.0, 2003.0, 0.0, -0.5};
  r.epsg = 32633;  // WGS 84 / UTM zone 33N, metres
  r.unit = std::string("m");  // not = "m": GCC 12 warns falsely (-Wrestrict) on that assignment, inlined at -O2
  return r;
}

class DemFileTest : public testing::TempDirTest {};

TEST_F(DemFileTest, AGeoTiffGivesItsSpacingItsMapPositionAndNorthUpRows) {
  const auto path = dir() / "small.tif";
  writeRaster(path, smallRaster());
  DemInfo info;
  const Heightfield f = readDem(path, {}, &info);
  EXPECT_EQ(f.cols, 4);
  EXPECT_EQ(f.rows, 3);
  EXPECT_EQ(f.spacing_x, 0.5);
  EXPECT_EQ(f.spacing_y, 0.5);
  // Grid row 0 is the south (last) file row; the local frame puts it at 0.
  EXPECT_EQ(f.height(0, 0), 30.0);
  EXPECT_EQ(f.height(0, 3), 33.5);
  EXPECT_EQ(f.height(2, 0), 10.0);
  EXPECT_EQ(f.origin, Eigen::Vector3d::Zero());
  EXPECT_TRUE(f.cell_holes.empty());
  EXPECT_TRUE(info.georeferenced);
  EXPECT_THAT(info.crs, HasSubstr("UTM zone 33N"));
  EXPECT_EQ(info.vertical_unit, "m");
  EXPECT_EQ(info.map_south_west, Eigen::Vector2d(1000.25, 2001.75));

  DemRequest request;
  request.map_frame = true;
  request.translation = Eigen::Vector3d(-1000.0, -2000.0, 0.5);
  const Heightfield placed = readDem(path, request);
  EXPECT_EQ(placed.origin, Eigen::Vector3d(0.25, 1.75, 0.5));
}

TEST_F(DemFileTest, ASouthUpOrEastToWestRasterIsTurnedToTheSameGround) {
  // The same ground, its rows stored south first and its columns east first.
  Raster r = smallRaster();
  Raster flipped = r;
  for (int i = 0; i < r.rows; ++i) {
    for (int j = 0; j < r.cols; ++j) {
      flipped.values[static_cast<std::size_t>(i) * r.cols + j] =
          r.values[static_cast<std::size_t>(r.rows - 1 - i) * r.cols + (r.cols - 1 - j)];
    }
  }
  flipped.geotransform = std::array<double, 6>{1002.0, -0.5, 0.0, 2001.5, 0.0, 0.5};
  writeRaster(dir() / "a.tif", r);
  writeRaster(dir() / "b.tif", flipped);
  DemInfo a_info, b_info;
  const Heightfield a = readDem(dir() / "a.tif", {}, &a_info);
  const Heightfield b = readDem(dir() / "b.tif", {}, &b_info);
  EXPECT_EQ(a.heights, b.heights);
  EXPECT_EQ(a_info.map_south_west, b_info.map_south_west);
}

TEST_F(DemFileTest, CropKeepsTheSamplesInsideTheWindowAndStepEveryNth) {
  Raster r;
  r.cols = 9;
  r.rows = 7;
  r.geotransform = std::array<double, 6>{0.0, 1.0, 0.0, 7.0, 0.0, -1.0};  // centres x 0.5 ... 8.5, y 6.5 ... 0.5
  for (int i = 0; i < r.rows; ++i) {
    for (int j = 0; j < r.cols; ++j) r.values.push_back(10.0 * (r.rows - 1 - i) + j);  // 10 y_index + x_index
  }
  writeRaster(dir() / "grid.tif", r);
  DemRequest request;
  request.crop = Eigen::Vector4d(1.5, 2.5, 6.5, 4.5);  // edges on sample centres keep them
  request.map_frame = true;
  Heightfield f = readDem(dir() / "grid.tif", request);
  EXPECT_EQ(f.cols, 6);  // x = 1.5 ... 6.5
  EXPECT_EQ(f.rows, 3);  // y = 2.5 ... 4.5
  EXPECT_EQ(f.origin, Eigen::Vector3d(1.5, 2.5, 0.0));
  EXPECT_EQ(f.height(0, 0), 21.0);
  EXPECT_EQ(f.height(2, 5), 46.0);

  request.step = 2;
  f = readDem(dir() / "grid.tif", request);
  EXPECT_EQ(f.cols, 3);  // x = 1.5, 3.5, 5.5
  EXPECT_EQ(f.rows, 2);  // y = 2.5, 4.5
  EXPECT_EQ(f.spacing_x, 2.0);
  EXPECT_EQ(f.height(1, 2), 45.0);

  request.crop = Eigen::Vector4d(20.0, 20.0, 30.0, 30.0);
  EXPECT_THAT(errorOf([&] { readDem(dir() / "grid.tif", request); }),
              AllOf(HasSubstr("grid.tif: "), HasSubstr("0 x 0 of the raster's 9 x 7"), HasSubstr("crop window misses")));
}

TEST_F(DemFileTest, NoDataAndNanSamplesMakeHolesOfTheCellsTheyTouch) {
  Raster r = smallRaster();
  r.no_data = -9999.0;
  r.values[1] = -9999.0;                                   // file row 0 (north), column 1
  r.values[11] = std::numeric_limits<double>::quiet_NaN();  // file row 2 (south), column 3
  writeRaster(dir() / "holes.tif", r);
  DemInfo info;
  const Heightfield f = readDem(dir() / "holes.tif", {}, &info);
  EXPECT_EQ(info.no_data_samples, 2);
  ASSERT_EQ(f.cell_holes.size(), 6u);
  // Grid row 2 column 1 is touched by cells (1, 0) and (1, 1); grid row 0
  // column 3 by cell (0, 2).
  EXPECT_EQ(f.cell_holes, (std::vector<std::uint8_t>{0, 0, 1, 1, 1, 0}));
  // The missing samples take the lowest real height: the base stays put.
  EXPECT_EQ(f.height(2, 1), 10.0);
  EXPECT_EQ(f.baseZ(), 10.0 - f.base_depth);

  r.values.assign(r.values.size(), -9999.0);
  writeRaster(dir() / "none.tif", r);
  EXPECT_THAT(errorOf([&] { readDem(dir() / "none.tif"); }),
              AllOf(HasSubstr("none.tif: "), HasSubstr("all 12 kept samples are no-data")));
  // Every cell touching a no-data sample: no ground either.
  r = smallRaster();
  r.no_data = -9999.0;
  r.values[5] = r.values[6] = -9999.0;  // the middle row's two inner samples touch all six cells
  writeRaster(dir() / "cut.tif", r);
  EXPECT_THAT(errorOf([&] { readDem(dir() / "cut.tif"); }), HasSubstr("every cell touches a missing sample"));
}

TEST_F(DemFileTest, VerticalUnitsScaleAndOffsetGiveMetres) {
  Raster r = smallRaster();
  r.unit = "cm";
  writeRaster(dir() / "cm.tif", r);
  EXPECT_DOUBLE_EQ(readDem(dir() / "cm.tif").height(0, 3), 0.335);

  r.unit = "US survey foot";
  writeRaster(dir() / "usft.tif", r);
  EXPECT_DOUBLE_EQ(readDem(dir() / "usft.tif").height(0, 0), 30.0 * 1200.0 / 3937.0);

  r.unit = "ft";
  r.scale = 0.5;
  r.offset = 100.0;
  writeRaster(dir() / "ft.tif", r);
  DemRequest twice;
  twice.height_scale = 2.0;  // multiplies the metres
  EXPECT_DOUBLE_EQ(readDem(dir() / "ft.tif", twice).height(0, 0), 2.0 * 0.3048 * (30.0 * 0.5 + 100.0));

  r.scale.reset();
  r.offset.reset();
  r.unit = "furlong";
  writeRaster(dir() / "furlong.tif", r);
  EXPECT_THAT(errorOf([&] { readDem(dir() / "furlong.tif"); }),
              AllOf(HasSubstr("furlong.tif: "), HasSubstr("vertical unit 'furlong'")));
}

TEST_F(DemFileTest, AProjectedSystemInFeetIsReadInMetres) {
  Raster r = smallRaster();
  r.epsg = 2227;  // NAD83 / California zone 3 (ftUS)
  writeRaster(dir() / "feet.tif", r);
  DemInfo info;
  const Heightfield f = readDem(dir() / "feet.tif", {}, &info);
  EXPECT_DOUBLE_EQ(f.spacing_x, 0.5 * 1200.0 / 3937.0);
  EXPECT_NEAR(info.map_south_west.x(), 1000.25 * 1200.0 / 3937.0, 1e-9);
}

TEST_F(DemFileTest, ASixteenBitPngNeedsItsSpacingAndItsScale) {
  Raster r;
  r.cols = 3;
  r.rows = 2;
  r.type = GDT_UInt16;
  r.values = {0.0, 1000.0, 65535.0, 2.0, 3.0, 4.0};
  r.driver = "PNG";
  writeRaster(dir() / "dem.png", r);
  DemRequest request;
  EXPECT_THAT(errorOf([&] { readDem(dir() / "dem.png", request); }),
              AllOf(HasSubstr("dem.png: "), HasSubstr("no georeferencing: give spacing")));
  request.spacing = Eigen::Vector2d(0.02, 0.02);
  EXPECT_THAT(errorOf([&] { readDem(dir() / "dem.png", request); }),
              AllOf(HasSubstr("integer samples with no vertical unit or scale"), HasSubstr("height_scale")));
  request.height_scale = 1e-4;
  const Heightfield f = readDem(dir() / "dem.png", request);
  EXPECT_EQ(f.cols, 3);
  EXPECT_DOUBLE_EQ(f.height(1, 2), 6.5535);  // the top row is north
  EXPECT_DOUBLE_EQ(f.height(0, 1), 3e-4);
}

// A .npy file as numpy.save writes it: version 1.0, the header padded with
// spaces to a multiple of 64 bytes and ended by '\n'.
std::string npy(const std::string& descr, bool fortran, const std::string& shape, const std::string& data) {
  std::string dict = "{'descr': '" + descr + "', 'fortran_order': " + (fortran ? "True" : "False") +
                     ", 'shape': " + shape + ", }";
  while ((10 + dict.size() + 1) % 64 != 0) dict += ' ';
  dict += '\n';
  std::string out = "\x93NUMPY";
  out += '\x01';
  out += '\x00';
  out += static_cast<char>(dict.size() & 0xff);
  out += static_cast<char>(dict.size() >> 8);
  return out + dict + data;
}

template <typename T>
std::string bytesOf(const std::vector<T>& values, bool big_endian = false) {
  std::string out(values.size() * sizeof(T), '\0');
  std::memcpy(out.data(), values.data(), out.size());
  if (big_endian) {
    for (std::size_t k = 0; k < values.size(); ++k) std::reverse(out.begin() + k * sizeof(T), out.begin() + (k + 1) * sizeof(T));
  }
  return out;
}

TEST_F(DemFileTest, NpyArraysInEitherByteOrderAndMemoryOrderAreMapsNorthRowFirst) {
  DemRequest request;
  request.spacing = Eigen::Vector2d(0.05, 0.1);
  // Row 0 of the array is the north edge, as in an image or a CSV file.
  const std::vector<double> c_order{1.0, 2.0, 3.0, 4.0, 5.0, 6.0};  // shape (2, 3)
  const Heightfield a = readDem(write("a.npy", npy("<f8", false, "(2, 3)", bytesOf(c_order))), request);
  const Heightfield b = readDem(write("b.npy", npy(">f8", false, "(2, 3)", bytesOf(c_order, true))), request);
  const std::vector<float> f_order{1.0f, 4.0f, 2.0f, 5.0f, 3.0f, 6.0f};
  const Heightfield c = readDem(write("c.npy", npy("<f4", true, "(2, 3)", bytesOf(f_order))), request);
  const Heightfield csv = readHeightfieldCsv(write("same.csv", "1,2,3\n4,5,6\n"), {0.05, 0.1});
  EXPECT_EQ(a.heights, csv.heights);
  EXPECT_EQ(b.heights, csv.heights);
  EXPECT_EQ(c.heights, csv.heights);
  EXPECT_EQ(a.spacing_y, 0.1);

  const std::vector<std::uint16_t> counts{0, 1, 65535, 7};
  request.height_scale = 1e-3;
  EXPECT_DOUBLE_EQ(readDem(write("u.npy", npy("<u2", false, "(2, 2)", bytesOf(counts))), request).height(0, 0),
                   65.535);  // the south row's first
  const std::vector<double> nan_corner{std::nan(""), 2.0, 3.0, 4.0, 5.0, 6.0};
  const Heightfield holes = readDem(write("n.npy", npy("<f8", false, "(2, 3)", bytesOf(nan_corner))), request);
  EXPECT_EQ(holes.cell_holes, (std::vector<std::uint8_t>{1, 0}));
}

TEST_F(DemFileTest, BrokenNpyFilesAreNamedWithTheirFault) {
  DemRequest request;
  request.spacing = Eigen::Vector2d(1.0, 1.0);
  const std::string six = bytesOf(std::vector<double>(6, 1.0));
  const auto error = [&](const std::string& name, const std::string& bytes) {
    return errorOf([&] { readDem(write(name, bytes), request); });
  };
  EXPECT_THAT(error("magic.npy", "PK\x03\x04 not numpy"), HasSubstr("magic.npy: not a NumPy .npy file"));
  EXPECT_THAT(error("flat.npy", npy("<f8", false, "(6,)", six)), HasSubstr("one-dimensional"));
  EXPECT_THAT(error("cube.npy", npy("<f8", false, "(1, 2, 3)", six)), HasSubstr("more than two dimensions"));
  EXPECT_THAT(error("text.npy", npy("<U8", false, "(2, 3)", six)), HasSubstr("dtype '<U8' is not numeric heights"));
  EXPECT_THAT(error("short.npy", npy("<f8", false, "(3, 3)", six)),
              HasSubstr("shape (3, 3) of 8-byte values does not match the file's 48 bytes"));
  EXPECT_THAT(error("huge.npy", npy("<f8", false, "(4294967296, 4294967296)", six)), HasSubstr("does not match"));
}

TEST_F(DemFileTest, RastersItCannotTakeAreRefusedWithTheReason) {
  Raster rotated = smallRaster();
  rotated.geotransform = std::array<double, 6>{1000.0, 0.5, 0.1, 2003.0, 0.0, -0.5};
  writeRaster(dir() / "rotated.tif", rotated);
  EXPECT_THAT(errorOf([&] { readDem(dir() / "rotated.tif"); }),
              AllOf(HasSubstr("rotated.tif: "), HasSubstr("rotated or sheared"), HasSubstr("north-up")));

  Raster degrees = smallRaster();
  degrees.epsg = 4326;
  writeRaster(dir() / "wgs84.tif", degrees);
  EXPECT_THAT(errorOf([&] { readDem(dir() / "wgs84.tif"); }),
              AllOf(HasSubstr("wgs84.tif: "), HasSubstr("'WGS 84' is geographic (degrees)"), HasSubstr("gdalwarp")));

  Raster complex = smallRaster();
  complex.type = GDT_CInt16;
  writeRaster(dir() / "complex.tif", complex);
  EXPECT_THAT(errorOf([&] { readDem(dir() / "complex.tif"); }),
              AllOf(HasSubstr("complex.tif: band 1 holds CInt16 values, not heights")));

  Raster palette = smallRaster();
  palette.type = GDT_Byte;
  palette.unit.clear();
  palette.palette = true;
  writeRaster(dir() / "palette.tif", palette);
  EXPECT_THAT(errorOf([&] { readDem(dir() / "palette.tif"); }),
              AllOf(HasSubstr("palette.tif: band 1 is a colour channel (Palette)")));

  // 40000 x 30000 samples in a file of a few kB: no block is written.
  testing::writeSparseRaster(dir() / "huge.tif", 40000, 30000, {0.0, 0.01, 0.0, 300.0, 0.0, -0.01});
  EXPECT_LT(std::filesystem::file_size(dir() / "huge.tif"), 1u << 20);
  EXPECT_THAT(errorOf([&] { readDem(dir() / "huge.tif"); }),
              AllOf(HasSubstr("huge.tif: 40000 x 30000 = 1200000000 samples, more than the 1073741824"),
                    HasSubstr("crop it or give a step")));
  DemRequest part;  // the cap counts what is kept: a window of 1e8 samples, every 50th
  part.crop = Eigen::Vector4d(0.0, 0.0, 99.99, 99.99);
  part.step = 50;
  EXPECT_EQ(readDem(dir() / "huge.tif", part).cols, 200);  // the sparse file's blocks read as zeros

  writeRaster(dir() / "small.tif", smallRaster());
  DemRequest spaced;
  spaced.spacing = Eigen::Vector2d(1.0, 1.0);
  EXPECT_THAT(errorOf([&] { readDem(dir() / "small.tif", spaced); }),
              HasSubstr("small.tif: the raster states its own spacing (0.5 x 0.5 m)"));
  DemRequest band2;
  band2.band = 2;
  EXPECT_THAT(errorOf([&] { readDem(dir() / "small.tif", band2); }),
              HasSubstr("small.tif: band 2 does not exist (the raster has 1)"));
  EXPECT_THAT(errorOf([&] { readDem(dir() / "missing.tif"); }), HasSubstr("missing.tif: file not found"));
  EXPECT_THAT(errorOf([&] { readDem(write("words.tif", "not a raster at all")); }),
              HasSubstr("words.tif: not a raster GDAL can read"));
}

TEST_F(DemFileTest, WriteDemGeoTiffRoundTripsAFieldWithItsHoles) {
  Heightfield field;
  field.rows = 4;
  field.cols = 5;
  field.spacing_x = 0.02;
  field.spacing_y = 0.03;
  for (int k = 0; k < 20; ++k) field.heights.push_back(0.125 * k - 1.0);
  field.cell_holes.assign(12, 0);
  field.cell_holes[0] = 1;  // sample (0, 0) touches only this cell: written as NaN
  DemWriteOptions options;
  options.epsg = 32633;
  options.map_south_west = Eigen::Vector2d(400000.0, 500000.0);
  writeDemGeoTiff(dir() / "out.tif", field, options);
  DemRequest request;
  request.map_frame = true;
  request.translation = Eigen::Vector3d(-400000.0, -500000.0, 0.0);
  DemInfo info;
  const Heightfield back = readDem(dir() / "out.tif", request, &info);
  EXPECT_EQ(back.rows, 4);
  EXPECT_EQ(back.cols, 5);
  EXPECT_NEAR(back.spacing_x, 0.02, 1e-12);
  EXPECT_NEAR(back.spacing_y, 0.03, 1e-12);
  EXPECT_NEAR(back.origin.x(), 0.0, 1e-9);
  EXPECT_NEAR(back.origin.y(), 0.0, 1e-9);
  EXPECT_EQ(info.no_data_samples, 1);
  EXPECT_EQ(back.cell_holes, field.cell_holes);
  for (int k = 1; k < 20; ++k) EXPECT_NEAR(back.heights[k], field.heights[k], kExact) << k;
}

TEST_F(DemFileTest, ATerrainFileTakesADemWithCropStepFrameAndCompactStorage) {
  writeRaster(dir() / "dem.tif", smallRaster());
  const auto yaml = write("t.yaml",
                          "materials: {ground: {}}\n"
                          "pieces:\n"
                          "  - type: heightfield\n"
                          "    file: dem.tif\n"
                          "    crop: [1000.0, 2001.0, 1001.6, 2003.0]\n"
                          "    frame: map\n"
                          "    translation: [-1000, -2000, 0]\n"
                          "    storage: compact\n");
  const Terrain terrain = loadTerrain(yaml);
  EXPECT_EQ(terrain.pieceCount(), 2u * 2u * 2u);  // 3 x 3 samples kept: 4 cells
  EXPECT_NEAR(terrain.bounds().min.x(), 0.25, 1e-12);

  const auto misplaced = write("c.yaml",
                               "materials: {ground: {}}\n"
                               "pieces:\n"
                               "  - type: heightfield\n"
                               "    file: h.csv\n"
                               "    spacing: 1\n"
                               "    crop: [0, 0, 1, 1]\n");
  write("h.csv", "1,2\n3,4\n");
  EXPECT_THAT(errorOf([&] { loadTerrain(misplaced); }),
              AllOf(HasSubstr("c.yaml:6:11: "), HasSubstr("crop applies to a DEM file")));
  const auto wrong = write("w.yaml",
                           "materials: {ground: {}}\n"
                           "pieces:\n"
                           "  - type: heightfield\n"
                           "    file: dem.tif\n"
                           "    spacing: 0.1\n");
  EXPECT_THAT(errorOf([&] { loadTerrain(wrong); }),
              AllOf(HasSubstr("w.yaml:4:11: "), HasSubstr("dem.tif: the raster states its own spacing")));
}

}  // namespace
}  // namespace wtc::io
