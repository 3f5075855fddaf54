#pragma once
// Heightfields from digital elevation models: a GeoTIFF (or any raster GDAL
// reads: a 16-bit PNG, an ESRI ASCII grid, a VRT) or a NumPy .npy array.
//
// Georeferencing. A raster with a geotransform gives its own spacing (the
// pixel size) and map position; it must be north-up (no rotation or shear
// terms) and, if it names a coordinate system, a projected one: a
// geographic CRS (degrees) has no metres to give and is refused (reproject
// it first, e.g. `gdalwarp -t_srs EPSG:32633`). A projected CRS in other
// linear units (feet) is converted to metres. Heights are taken at pixel
// centres. A raster without a geotransform (a PNG, a .npy) needs `spacing`,
// and its map frame is its grid: the south-west sample at (0, 0), x east,
// y north.
//
// Heights. height = height_scale x (value x band scale + band offset) in
// the band's vertical unit (m, cm, mm, ft, US survey ft) converted to
// metres. A float band without a unit is taken as metres; an integer band
// with neither unit nor scale (a 16-bit PNG of counts) needs height_scale.
//
// No-data. A sample equal to the band's no-data value, or NaN, is no
// ground: every cell it touches becomes a hole (wtc::Heightfield::
// cell_holes). A raster with no valid cell is refused.
//
// Window and step. `crop` = [x0, y0, x1, y1] in map coordinates (m) keeps
// the samples whose centres lie inside (only those rows and columns are
// read); `step` = n keeps every n-th of them in x and y (the kept samples
// are the file's own heights, not averages). Placement: frame local (the
// default) puts the kept south-west sample at `translation`, like any
// heightfield; frame map puts every sample at its map coordinates plus
// `translation` (an offset from a UTM origin, say).
//
// Errors: InvalidInputError starting "<path>: " with the reason, e.g.
// "dem.tif: the raster is rotated or sheared (geotransform terms 0.3, 0),
// WTC reads north-up rasters only". docs/bad-input.md lists them.
#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "wtc/terrain/heightfield.hpp"

namespace wtc::io {

/// How a DEM becomes a heightfield (see the file comment).
struct DemRequest {
  /// Grid spacing (m, > 0): required for a raster without a geotransform,
  /// refused for one with (the raster states its own).
  std::optional<Eigen::Vector2d> spacing;
  /// [x0, y0, x1, y1] in map coordinates (m), x0 < x1, y0 < y1.
  std::optional<Eigen::Vector4d> crop;
  int step = 1;                                   ///< Keep every step-th sample (>= 1).
  std::optional<double> height_scale;             ///< Multiplies the heights in metres (finite).
  bool map_frame = false;                         ///< Samples at map coordinates (+ translation).
  Eigen::Vector3d translation{Eigen::Vector3d::Zero()};  ///< Placement (m).
  double base_depth = 1.0;                        ///< As wtc::Heightfield::base_depth (m, > 0).
  int band = 1;                                   ///< Raster band (1-based; a .npy has one).
};

/// What a DEM said about itself, for a report.
struct DemInfo {
  int file_cols = 0, file_rows = 0;      ///< Raster size (samples).
  bool georeferenced = false;            ///< Whether it had a geotransform.
  std::string crs;                       ///< Its coordinate system's name ("" if none).
  std::string vertical_unit;             ///< The band's unit as written ("" if none).
  std::int64_t no_data_samples = 0;      ///< Within the kept samples.
  Eigen::Vector2d map_south_west{Eigen::Vector2d::Zero()};  ///< Map coordinates of the kept south-west sample (m).
};

/// Reads a DEM (format by content for GDAL, by the .npy extension for
/// NumPy) into a validated heightfield. At most kMaxDemSamples kept samples
/// (wtc/io/file_limits.hpp), checked before any height is read.
Heightfield readDem(const std::filesystem::path& path, const DemRequest& request = {}, DemInfo* info = nullptr);

/// Whether readHeightfieldFile's formats (CSV, PGM) leave this path to
/// readDem: .npy and anything that is not .csv, .txt or .pgm.
bool isDemPath(const std::filesystem::path& path);

/// What writeDemGeoTiff writes besides the heights.
struct DemWriteOptions {
  int epsg = 0;                       ///< A projected CRS in metres (0: none written).
  /// Map coordinates of sample (0, 0), the south-west one (m).
  Eigen::Vector2d map_south_west{Eigen::Vector2d::Zero()};
  bool float32 = true;                ///< Float32 samples (else Float64).
};

/// Writes `field` as a north-up, DEFLATE-compressed, tiled GeoTIFF in
/// metres (vertical unit "m"); holes become NaN samples where every cell
/// around them is a hole, and the no-data value is NaN. readDem reads it
/// back to the same grid (heights to float32's precision by default).
void writeDemGeoTiff(const std::filesystem::path& path, const Heightfield& field, const DemWriteOptions& options = {});

}  // namespace wtc::io
