// Writes the DEM files of docs/bad-input.md's cases into a folder
// (tests/bad_input): rasters WTC refuses, each a few hundred bytes.
//   build/tests/io/wtc_make_bad_dems tests/bad_input
#include <cstdio>
#include <limits>

#include "gdal_raster.hpp"

namespace {

using wtc::io::testing::Raster;

// 3 x 2 samples of 1 m, north-up, EPSG:32633, heights in m.
Raster plain() {
  Raster r;
  r.cols = 3;
  r.rows = 2;
  r.values = {1.0, 2.0, 3.0, 4.0, 5.0, 6.0};
  r.geotransform = std::array<double, 6>{500000.0, 1.0, 0.0, 800002.0, 0.0, -1.0};
  r.epsg = 32633;
  r.unit = "m";
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: wtc_make_bad_dems DIR\n");
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  using wtc::io::testing::writeRaster;
  Raster rotated = plain();
  rotated.geotransform = std::array<double, 6>{500000.0, 0.866, 0.5, 800002.0, 0.5, -0.866};  // turned 30 degrees
  writeRaster(dir / "dem_rotated.tif", rotated);
  Raster degrees = plain();
  degrees.epsg = 4326;
  degrees.geotransform = std::array<double, 6>{15.0, 1e-5, 0.0, 45.0, 0.0, -1e-5};
  writeRaster(dir / "dem_geographic.tif", degrees);
  Raster complex = plain();
  complex.type = GDT_CFloat32;
  writeRaster(dir / "dem_complex.tif", complex);
  Raster empty = plain();
  empty.no_data = -9999.0;
  empty.values.assign(empty.values.size(), -9999.0);
  writeRaster(dir / "dem_all_no_data.tif", empty);
  // 50000 x 30000 = 1.5e9 samples, over kMaxDemSamples, in a few kB.
  wtc::io::testing::writeSparseRaster(dir / "dem_huge.tif", 50000, 30000,
                                      {500000.0, 0.01, 0.0, 800300.0, 0.0, -0.01});
  return 0;
}
