#pragma once
// Heightfields from files: a CSV table of numbers or a grayscale PGM image
// (P2 text or P5 binary, 8 or 16 bit). The file holds only the heights; the
// layout (spacing, origin, scale, base) comes from HeightfieldLayout.
//
// Orientation: a file is a map seen from above, north up. Its first row
// (first line of the CSV, top row of the image) is the north edge, the
// largest y; within a row, values run west to east along +x. So file row k
// of n becomes grid row n - 1 - k of wtc::Heightfield (whose row 0 is at
// origin.y()), and an image of the ground looks right in any viewer.
//
// Scale: height = height_scale x value (m), value being the CSV number or
// the image gray level (0 ... maxval). One rule for both formats: an 8-bit
// image with height_scale 0.01 spans 0 ... 2.55 m, a 16-bit one with
// height_scale 1e-4 spans 0 ... 6.5535 m.
//
// CSV: one row of the grid per line; values separated by commas, or by
// spaces/tabs when the line has no comma; blank lines and lines starting
// with '#' are skipped; every row must have the same number of values.
//
// Errors: InvalidInputError whose message starts with "<path>:<line>:<column>:"
// (1-based, column in characters) wherever a position is known, e.g.
// "ground.csv:3:9: 'abc' is not a number (row 3, value 2)"; a path that is
// not a regular file, or a file over kMaxDataFileBytes
// (wtc/io/file_limits.hpp), is refused by name before it is read.
#include <Eigen/Core>
#include <filesystem>

#include "wtc/terrain/heightfield.hpp"

namespace wtc::io {

/// Where the samples of a file go (see wtc::Heightfield for the frame).
struct HeightfieldLayout {
  double spacing_x = 1.0;  ///< Between columns (m, > 0).
  double spacing_y = 1.0;  ///< Between rows (m, > 0).
  /// World position of grid sample (0, 0), the south-west corner, at value 0 (m).
  Eigen::Vector3d origin{Eigen::Vector3d::Zero()};
  double height_scale = 1.0;  ///< Metres per file unit (m, finite).
  double base_depth = 1.0;    ///< Flat base below the lowest height (m, > 0).
};

/// Reads a CSV heightfield. The result is validated (wtc::validate).
Heightfield readHeightfieldCsv(const std::filesystem::path& path, const HeightfieldLayout& layout = {});

/// Reads a PGM (P2 or P5) heightfield. The result is validated.
Heightfield readHeightfieldPgm(const std::filesystem::path& path, const HeightfieldLayout& layout = {});

/// By extension: ".pgm" -> PGM, ".csv" or ".txt" -> CSV; anything else throws.
Heightfield readHeightfieldFile(const std::filesystem::path& path, const HeightfieldLayout& layout = {});

}  // namespace wtc::io
