// DEMs to heightfields (rules in include/wtc/io/dem_file.hpp): GDAL reads
// the rasters, NpyArray the .npy files; one pipeline places, crops, steps
// and converts both.
#include "wtc/io/dem_file.hpp"

#include <gdal.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

#include "file_support.hpp"
#include "npy_array.hpp"
#include "wtc/base/error.hpp"
#include "wtc/io/file_limits.hpp"

namespace wtc::io {
namespace {

using detail::where;

// Metres per vertical unit as GDAL bands write it; nullopt if unknown.
std::optional<double> metresPerUnit(std::string unit) {
  for (char& c : unit) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (unit == "m" || unit == "metre" || unit == "meter" || unit == "metres" || unit == "meters") return 1.0;
  if (unit == "cm" || unit == "centimetre" || unit == "centimeter") return 0.01;
  if (unit == "mm" || unit == "millimetre" || unit == "millimeter") return 0.001;
  if (unit == "ft" || unit == "foot" || unit == "feet" || unit == "international foot") return 0.3048;
  // The US survey foot: 1200/3937 m exactly (NIST).
  if (unit == "us survey foot" || unit == "us-ft" || unit == "ftus" || unit == "us_survey_foot") return 1200.0 / 3937.0;
  return std::nullopt;
}

// What the pipeline needs of a raster, whoever reads it.
struct RasterFacts {
  std::int64_t cols = 0, rows = 0;
  std::optional<std::array<double, 6>>
      geotransform;  // GDAL's: x = g0 + (j) g1 + (i) g2, y = g3 + j g4 + i g5 (corners)
  double metres_per_map_unit = 1.0;
  std::string crs;
  bool integer = false;
  std::string unit;
  std::optional<double> band_scale, band_offset;
  std::optional<double> no_data;
};

// Reads `count` values of file row `row` starting at column `col0` into
// out[0 .. count), raw (before scale, unit and no-data).
class RasterSource {
 public:
  virtual ~RasterSource() = default;
  virtual const RasterFacts& facts() const = 0;
  virtual void readRow(std::int64_t row, std::int64_t col0, std::int64_t count, double* out) = 0;
};

class NpySource final : public RasterSource {
 public:
  explicit NpySource(const std::filesystem::path& path) : array_(path) {
    facts_.cols = array_.cols();
    facts_.rows = array_.rows();
    facts_.integer = array_.isInteger();
  }
  const RasterFacts& facts() const override { return facts_; }
  void readRow(std::int64_t row, std::int64_t col0, std::int64_t count, double* out) override {
    for (std::int64_t k = 0; k < count; ++k) out[k] = array_.at(row, col0 + k);
  }

 private:
  detail::NpyArray array_;
  RasterFacts facts_;
};

void registerGdal() {
  static std::once_flag once;
  std::call_once(once, [] { GDALAllRegister(); });
}

// GDAL's messages are the user's to read in our error, not on stderr.
class QuietGdal {
 public:
  QuietGdal() {
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
  }
  ~QuietGdal() { CPLPopErrorHandler(); }
  QuietGdal(const QuietGdal&) = delete;
  QuietGdal& operator=(const QuietGdal&) = delete;
  static std::string lastMessage() {
    const char* text = CPLGetLastErrorMsg();
    return text && *text ? std::string(": ") + text : std::string();
  }
};

struct DatasetCloser {
  void operator()(void* dataset) const { GDALClose(dataset); }
};
using Dataset = std::unique_ptr<void, DatasetCloser>;

class GdalSource final : public RasterSource {
 public:
  GdalSource(const std::filesystem::path& path, int band_number) : path_(path) {
    registerGdal();
    const QuietGdal quiet;
    dataset_.reset(GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
    if (!dataset_) {
      throw InvalidInputError(where(path) + "not a raster GDAL can read" + QuietGdal::lastMessage());
    }
    const int bands = GDALGetRasterCount(dataset_.get());
    if (band_number < 1 || band_number > bands) {
      throw InvalidInputError(where(path) + "band " + std::to_string(band_number) + " does not exist (the raster has " +
                              std::to_string(bands) + ")");
    }
    band_ = GDALGetRasterBand(dataset_.get(), band_number);
    int block_cols = 0, block_rows = 0;
    GDALGetBlockSize(band_, &block_cols, &block_rows);
    block_rows_ = std::max(block_rows, 1);
    facts_.cols = GDALGetRasterXSize(dataset_.get());
    facts_.rows = GDALGetRasterYSize(dataset_.get());
    readGeoreference();
    readBand(band_number);
  }
  const RasterFacts& facts() const override { return facts_; }
  void readRow(std::int64_t row, std::int64_t col0, std::int64_t count, double* out) override {
    const QuietGdal quiet;
    // Rows come in order: once they leave a row of blocks, its decoded
    // blocks are dropped, so that GDAL's cache (5 % of the memory by
    // default) does not grow to the whole raster beside the heights.
    const std::int64_t block_row = row / block_rows_;
    if (block_row != last_block_row_) {
      GDALFlushRasterCache(band_);
      last_block_row_ = block_row;
    }
    if (GDALRasterIO(band_, GF_Read, static_cast<int>(col0), static_cast<int>(row), static_cast<int>(count), 1, out,
                     static_cast<int>(count), 1, GDT_Float64, 0, 0) != CE_None) {
      throw InvalidInputError(where(path_) + "cannot read row " + std::to_string(row) + QuietGdal::lastMessage());
    }
  }

 private:
  void readGeoreference() {
    std::array<double, 6> g{};
    if (GDALGetGeoTransform(dataset_.get(), g.data()) == CE_None) facts_.geotransform = g;
    OGRSpatialReferenceH srs = GDALGetSpatialRef(dataset_.get());
    if (!srs) return;
    const char* name = OSRGetName(srs);
    facts_.crs = name ? name : "";
    if (OSRIsGeographic(srs)) {
      throw InvalidInputError(where(path_) + "the raster's coordinate system '" + facts_.crs +
                              "' is geographic (degrees): WTC needs metres; reproject it to a projected system, "
                              "e.g. gdalwarp -t_srs EPSG:32633 (UTM 33N)");
    }
    if (OSRIsProjected(srs) || OSRIsLocal(srs)) facts_.metres_per_map_unit = OSRGetLinearUnits(srs, nullptr);
  }
  void readBand(int band_number) {
    const GDALDataType type = GDALGetRasterDataType(band_);
    const std::string band = "band " + std::to_string(band_number);
    if (type == GDT_Unknown || GDALDataTypeIsComplex(type)) {
      throw InvalidInputError(where(path_) + band + " holds " + GDALGetDataTypeName(type) +
                              " values, not heights (expected real numbers)");
    }
    const GDALColorInterp colour = GDALGetRasterColorInterpretation(band_);
    if (colour != GCI_GrayIndex && colour != GCI_Undefined) {
      throw InvalidInputError(where(path_) + band + " is a colour channel (" + GDALGetColorInterpretationName(colour) +
                              "), not heights: give a one-band elevation raster");
    }
    facts_.integer = GDALDataTypeIsInteger(type) != 0;
    const char* unit = GDALGetRasterUnitType(band_);
    facts_.unit = unit ? unit : "";
    int has = 0;
    const double scale = GDALGetRasterScale(band_, &has);
    if (has && scale != 1.0) facts_.band_scale = scale;
    const double offset = GDALGetRasterOffset(band_, &has);
    if (has && offset != 0.0) facts_.band_offset = offset;
    const double no_data = GDALGetRasterNoDataValue(band_, &has);
    if (has) facts_.no_data = no_data;
  }

  std::filesystem::path path_;
  Dataset dataset_;
  GDALRasterBandH band_ = nullptr;
  std::int64_t block_rows_ = 1;
  std::int64_t last_block_row_ = -1;
  RasterFacts facts_;
};

// One axis of the grid: the file indices of the kept samples, in the
// order of increasing map coordinate, and the first one's map coordinate.
struct Axis {
  std::int64_t first = 0;   // file index of the kept sample with the smallest map coordinate
  std::int64_t stride = 1;  // file index step to the next kept sample (+-step)
  std::int64_t count = 0;
  double spacing = 1.0;  // m
  double start = 0.0;    // map coordinate of the first kept sample (m)
};

// Kept samples of one axis: file index k has map coordinate
// centre0 + k delta (delta signed, m); those inside [lo, hi], every step-th.
Axis keepAlong(std::int64_t size, double centre0, double delta, std::optional<std::array<double, 2>> window, int step) {
  Axis axis;
  axis.spacing = std::abs(delta) * step;
  // In map order: index k_m = (delta > 0 ? m : size - 1 - m).
  const auto fileIndex = [&](std::int64_t m) { return delta > 0 ? m : size - 1 - m; };
  const auto coordinate = [&](std::int64_t m) { return centre0 + static_cast<double>(fileIndex(m)) * delta; };
  std::int64_t lo = 0, hi = size - 1;  // in map order
  if (window) {
    // A window edge on a sample centre keeps the sample: a tolerance of a
    // millionth of the spacing absorbs the window's decimal rounding.
    const double slack = 1e-6 * std::abs(delta);
    const double a = coordinate(0);
    const auto below = static_cast<double>(std::ceil(((*window)[0] - slack - a) / std::abs(delta)));
    const auto above = static_cast<double>(std::floor(((*window)[1] + slack - a) / std::abs(delta)));
    lo = static_cast<std::int64_t>(std::clamp(below, 0.0, static_cast<double>(size)));
    hi = static_cast<std::int64_t>(std::clamp(above, -1.0, static_cast<double>(size - 1)));
  }
  axis.count = hi < lo ? 0 : (hi - lo) / step + 1;
  axis.first = fileIndex(lo);
  axis.stride = delta > 0 ? step : -step;
  axis.start = coordinate(lo);
  return axis;
}

std::unique_ptr<RasterSource> openSource(const std::filesystem::path& path, int band) {
  detail::requireRegularFile(path, kMaxDataFileBytes, detail::kDataFileKind);
  const std::string ext = detail::lowerExtension(path);
  if (ext == ".npy") {
    if (band != 1) throw InvalidInputError(where(path) + "a .npy array has one band; band = " + std::to_string(band));
    return std::make_unique<NpySource>(path);
  }
  return std::make_unique<GdalSource>(path, band);
}

}  // namespace

bool isDemPath(const std::filesystem::path& path) {
  const std::string ext = detail::lowerExtension(path);
  return ext != ".csv" && ext != ".txt" && ext != ".pgm";
}

Heightfield readDem(const std::filesystem::path& path, const DemRequest& request, DemInfo* info) {
  if (request.step < 1) throw InvalidInputError(where(path) + "step = " + std::to_string(request.step) + " (>= 1)");
  if (request.height_scale && !std::isfinite(*request.height_scale)) {
    throw InvalidInputError(where(path) + "height_scale = " + formatNumber(*request.height_scale) + " is not finite");
  }
  if (request.crop) {
    const Eigen::Vector4d& w = *request.crop;
    if (!w.allFinite() || !(w[0] < w[2]) || !(w[1] < w[3])) {
      throw InvalidInputError(where(path) + "crop [" + formatNumber(w[0]) + ", " + formatNumber(w[1]) + ", " +
                              formatNumber(w[2]) + ", " + formatNumber(w[3]) +
                              "] is not a window [x0, y0, x1, y1] with x0 < x1, y0 < y1");
    }
  }
  const std::unique_ptr<RasterSource> source = openSource(path, request.band);
  const RasterFacts& f = source->facts();

  // Map coordinates of the pixel centres: x = cx0 + j dx, y = cy0 + i dy (m).
  double cx0 = 0, dx = 1, cy0 = 0, dy = -1;
  if (f.geotransform) {
    const auto& g = *f.geotransform;
    if (g[2] != 0.0 || g[4] != 0.0) {
      throw InvalidInputError(where(path) + "the raster is rotated or sheared (geotransform terms " +
                              formatNumber(g[2]) + ", " + formatNumber(g[4]) +
                              "): WTC reads north-up rasters only; warp it first (gdalwarp)");
    }
    if (!(std::isfinite(g[1]) && std::isfinite(g[5]) && g[1] != 0.0 && g[5] != 0.0 && std::isfinite(g[0]) &&
          std::isfinite(g[3]))) {
      throw InvalidInputError(where(path) + "the raster's pixel size " + formatNumber(g[1]) + " x " +
                              formatNumber(g[5]) + " or origin is not usable");
    }
    if (request.spacing) {
      throw InvalidInputError(
          where(path) + "the raster states its own spacing (" + formatNumber(std::abs(g[1]) * f.metres_per_map_unit) +
          " x " + formatNumber(std::abs(g[5]) * f.metres_per_map_unit) + " m): leave out spacing (step coarsens it)");
    }
    const double u = f.metres_per_map_unit;
    dx = g[1] * u;
    dy = g[5] * u;
    cx0 = (g[0] + 0.5 * g[1]) * u;
    cy0 = (g[3] + 0.5 * g[5]) * u;
  } else {
    if (!request.spacing) {
      throw InvalidInputError(where(path) + "the raster has no georeferencing: give spacing (m)");
    }
    dx = request.spacing->x();
    dy = -request.spacing->y();
    if (!(dx > 0.0 && -dy > 0.0 && std::isfinite(dx) && std::isfinite(dy))) {
      throw InvalidInputError(where(path) + "spacing " + formatNumber(dx) + " x " + formatNumber(-dy) +
                              " is not > 0 and finite");
    }
    cx0 = 0.0;
    cy0 = static_cast<double>(f.rows - 1) * -dy;  // the last file row (south) at y = 0
  }

  std::optional<std::array<double, 2>> wx, wy;
  if (request.crop) {
    wx = std::array<double, 2>{(*request.crop)[0], (*request.crop)[2]};
    wy = std::array<double, 2>{(*request.crop)[1], (*request.crop)[3]};
  }
  const Axis ax = keepAlong(f.cols, cx0, dx, wx, request.step);
  const Axis ay = keepAlong(f.rows, cy0, dy, wy, request.step);
  if (ax.count < 2 || ay.count < 2) {
    throw InvalidInputError(where(path) + "the kept samples (" + std::to_string(ax.count) + " x " +
                            std::to_string(ay.count) + " of the raster's " + std::to_string(f.cols) + " x " +
                            std::to_string(f.rows) + ") are too few for a heightfield (2 x 2)" +
                            (request.crop ? ": the crop window misses the raster or is too small" : ""));
  }
  const auto kept = static_cast<std::uint64_t>(ax.count) * static_cast<std::uint64_t>(ay.count);
  if (kept > kMaxDemSamples) {
    throw InvalidInputError(where(path) + std::to_string(ax.count) + " x " + std::to_string(ay.count) + " = " +
                            std::to_string(kept) + " samples, more than the " + std::to_string(kMaxDemSamples) +
                            " a heightfield may take (wtc::io::kMaxDemSamples): crop it or give a step");
  }

  // Heights: h = height_scale x unit x (raw x scale + offset).
  double unit = 1.0;
  if (!f.unit.empty()) {
    const auto m = metresPerUnit(f.unit);
    if (!m) {
      throw InvalidInputError(where(path) + "vertical unit '" + f.unit +
                              "' is not one WTC knows (m, cm, mm, ft, US survey foot)");
    }
    unit = *m;
  } else if (f.integer && !f.band_scale && !request.height_scale) {
    throw InvalidInputError(where(path) +
                            "integer samples with no vertical unit or scale (counts, as in a 16-bit "
                            "PNG): give height_scale (m per count)");
  }
  const double factor = request.height_scale.value_or(1.0) * unit;
  const double scale = f.band_scale.value_or(1.0);
  const double offset = f.band_offset.value_or(0.0);

  Heightfield field;
  field.cols = static_cast<int>(ax.count);
  field.rows = static_cast<int>(ay.count);
  field.spacing_x = ax.spacing;
  field.spacing_y = ay.spacing;
  field.base_depth = request.base_depth;
  field.heights.resize(kept);
  std::vector<std::uint8_t> no_data;  // per sample, filled at the first one
  std::int64_t no_data_count = 0;
  const std::int64_t col_lo = std::min(ax.first, ax.first + (ax.count - 1) * ax.stride);
  const std::int64_t span = std::abs((ax.count - 1) * ax.stride) + 1;
  std::vector<double> row_values(static_cast<std::size_t>(span));
  for (std::int64_t r = 0; r < ay.count; ++r) {
    const std::int64_t file_row = ay.first + r * ay.stride;
    source->readRow(file_row, col_lo, span, row_values.data());
    for (std::int64_t c = 0; c < ax.count; ++c) {
      const std::int64_t file_col = ax.first + c * ax.stride;
      const double raw = row_values[static_cast<std::size_t>(file_col - col_lo)];
      const std::size_t k = static_cast<std::size_t>(r) * ax.count + c;
      if (std::isnan(raw) || (f.no_data && raw == *f.no_data)) {
        if (no_data.empty()) no_data.assign(kept, 0);
        no_data[k] = 1;
        ++no_data_count;
        continue;
      }
      const double h = factor * (raw * scale + offset);
      if (!std::isfinite(h)) {
        throw InvalidInputError(where(path) + "sample at row " + std::to_string(file_row) + ", column " +
                                std::to_string(file_col) + " is " + formatNumber(raw) +
                                ", which gives no finite height");
      }
      field.heights[k] = h;
    }
  }
  if (no_data_count == static_cast<std::int64_t>(kept)) {
    throw InvalidInputError(where(path) + "all " + std::to_string(kept) + " kept samples are no-data: no ground");
  }
  if (no_data_count > 0) {
    try {
      holesAtMissingSamples(field, no_data);
    } catch (const InvalidInputError& e) {
      throw InvalidInputError(where(path) + e.what());
    }
  }
  field.origin = request.translation;
  if (request.map_frame) field.origin += Eigen::Vector3d(ax.start, ay.start, 0.0);
  try {
    validate(field);
  } catch (const InvalidInputError& e) {
    throw InvalidInputError(where(path) + e.what());
  }
  if (info) {
    info->file_cols = static_cast<int>(f.cols);
    info->file_rows = static_cast<int>(f.rows);
    info->georeferenced = f.geotransform.has_value();
    info->crs = f.crs;
    info->vertical_unit = f.unit;
    info->no_data_samples = no_data_count;
    info->map_south_west = Eigen::Vector2d(ax.start, ay.start);
  }
  return field;
}

void writeDemGeoTiff(const std::filesystem::path& path, const Heightfield& field, const DemWriteOptions& options) {
  validate(field);
  registerGdal();
  const QuietGdal quiet;
  GDALDriverH driver = GDALGetDriverByName("GTiff");
  if (!driver) throw InvalidInputError(where(path) + "GDAL has no GTiff driver");
  const char* create_options[] = {"TILED=YES", "COMPRESS=DEFLATE", "PREDICTOR=3", "BIGTIFF=IF_SAFER", nullptr};
  const GDALDataType type = options.float32 ? GDT_Float32 : GDT_Float64;
  Dataset dataset(
      GDALCreate(driver, path.c_str(), field.cols, field.rows, 1, type, const_cast<char**>(create_options)));
  if (!dataset) throw InvalidInputError(where(path) + "cannot create the GeoTIFF" + QuietGdal::lastMessage());
  // Corner of the north-west pixel: samples sit at pixel centres.
  const double top = options.map_south_west.y() + (field.rows - 1 + 0.5) * field.spacing_y;
  std::array<double, 6> g{
      options.map_south_west.x() - 0.5 * field.spacing_x, field.spacing_x, 0.0, top, 0.0, -field.spacing_y};
  GDALSetGeoTransform(dataset.get(), g.data());
  if (options.epsg != 0) {
    OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
    const bool ok = OSRImportFromEPSG(srs, options.epsg) == OGRERR_NONE && OSRIsProjected(srs);
    if (ok) GDALSetSpatialRef(dataset.get(), srs);
    OSRDestroySpatialReference(srs);
    if (!ok) {
      throw InvalidInputError(where(path) + "EPSG:" + std::to_string(options.epsg) +
                              " is not a projected coordinate system GDAL knows");
    }
  }
  GDALRasterBandH band = GDALGetRasterBand(dataset.get(), 1);
  GDALSetRasterUnitType(band, "m");
  GDALSetRasterNoDataValue(band, std::numeric_limits<double>::quiet_NaN());
  std::vector<double> row(static_cast<std::size_t>(field.cols));
  const bool holes = field.hasHoles();
  for (int i = 0; i < field.rows; ++i) {
    const int r = field.rows - 1 - i;  // file rows run north to south
    for (int c = 0; c < field.cols; ++c) {
      // NaN where every cell around the sample is a hole.
      bool ground = !holes;
      for (int dr = -1; dr <= 0 && !ground; ++dr) {
        for (int dc = -1; dc <= 0 && !ground; ++dc) {
          const int cr = r + dr, cc = c + dc;
          ground = cr >= 0 && cc >= 0 && cr < field.rows - 1 && cc < field.cols - 1 && !field.isHole(cr, cc);
        }
      }
      row[static_cast<std::size_t>(c)] = ground ? field.height(r, c) : std::numeric_limits<double>::quiet_NaN();
    }
    if (GDALRasterIO(band, GF_Write, 0, i, field.cols, 1, row.data(), field.cols, 1, GDT_Float64, 0, 0) != CE_None) {
      throw InvalidInputError(where(path) + "cannot write row " + std::to_string(i) + QuietGdal::lastMessage());
    }
  }
  dataset.reset();  // GDALClose flushes; its failure shows as the last error
  if (CPLGetLastErrorType() == CE_Failure) {
    throw InvalidInputError(where(path) + "writing the GeoTIFF failed" + QuietGdal::lastMessage());
  }
}

}  // namespace wtc::io
