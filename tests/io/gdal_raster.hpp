#pragma once
// Rasters written through GDAL's own API (a MEM dataset copied by the
// GTiff or PNG driver), for the DEM reader's tests and the bad-input files
// (tests/io/make_bad_dems.cpp): what GDAL means by a geotransform, a unit
// and a no-data value, independent of writeDemGeoTiff.
#include <gdal.h>
#include <ogr_srs_api.h>

#include <array>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace wtc::io::testing {

// A raster as GDAL's GTiff (or PNG, through a MEM copy) driver writes it.
struct Raster {
  int cols = 0, rows = 0;
  std::vector<double> values;  // file order: the top (first) row first
  GDALDataType type = GDT_Float32;
  std::optional<std::array<double, 6>> geotransform;
  int epsg = 0;
  std::string unit;
  std::optional<double> no_data, scale, offset;
  bool palette = false;
  std::string driver = "GTiff";
  std::vector<std::string> options;
};

inline void writeRaster(const std::filesystem::path& path, const Raster& r) {
  GDALAllRegister();
  GDALDriverH mem = GDALGetDriverByName("MEM");
  GDALDatasetH ds = GDALCreate(mem, "", r.cols, r.rows, 1, r.type, nullptr);
  if (!ds) throw std::runtime_error("writeRaster: GDAL's MEM driver made no dataset");
  if (r.geotransform) {
    std::array<double, 6> g = *r.geotransform;
    GDALSetGeoTransform(ds, g.data());
  }
  if (r.epsg) {
    OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
    if (OSRImportFromEPSG(srs, r.epsg) != OGRERR_NONE) throw std::runtime_error("writeRaster: EPSG:" + std::to_string(r.epsg));
    GDALSetSpatialRef(ds, srs);
    OSRDestroySpatialReference(srs);
  }
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  if (!r.unit.empty()) GDALSetRasterUnitType(band, r.unit.c_str());
  if (r.no_data) GDALSetRasterNoDataValue(band, *r.no_data);
  if (r.scale) GDALSetRasterScale(band, *r.scale);
  if (r.offset) GDALSetRasterOffset(band, *r.offset);
  if (r.palette) {
    GDALColorTableH table = GDALCreateColorTable(GPI_RGB);
    GDALColorEntry entry{10, 20, 30, 255};
    GDALSetColorEntry(table, 0, &entry);
    GDALSetRasterColorTable(band, table);
    GDALDestroyColorTable(table);
  }
  std::vector<double> values = r.values;
  if (GDALRasterIO(band, GF_Write, 0, 0, r.cols, r.rows, values.data(), r.cols, r.rows, GDT_Float64, 0, 0) != CE_None) {
    throw std::runtime_error(std::string("writeRaster: ") + CPLGetLastErrorMsg());
  }
  std::vector<const char*> options;
  for (const std::string& o : r.options) options.push_back(o.c_str());
  options.push_back(nullptr);
  GDALDatasetH out = GDALCreateCopy(GDALGetDriverByName(r.driver.c_str()), path.c_str(), ds, FALSE,
                                    const_cast<char**>(options.data()), nullptr, nullptr);
  if (!out) throw std::runtime_error(path.string() + ": " + CPLGetLastErrorMsg());
  GDALClose(out);
  GDALClose(ds);
}

// A cols x rows float32 GeoTIFF with no block written (SPARSE_OK): a few
// kB on disk for any size (tiles of 2048 x 2048: few offsets to list),
// every sample reading as 0.
inline void writeSparseRaster(const std::filesystem::path& path, int cols, int rows, const std::array<double, 6>& g) {
  GDALAllRegister();
  const char* options[] = {"SPARSE_OK=TRUE", "TILED=YES", "BLOCKXSIZE=2048", "BLOCKYSIZE=2048", nullptr};
  GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), cols, rows, 1, GDT_Float32,
                               const_cast<char**>(options));
  if (!ds) throw std::runtime_error(path.string() + ": " + CPLGetLastErrorMsg());
  std::array<double, 6> transform = g;
  GDALSetGeoTransform(ds, transform.data());
  GDALClose(ds);
}

}  // namespace wtc::io::testing
