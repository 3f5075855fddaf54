#pragma once
// What WTC's loaders read from a user's file: only regular files (a FIFO,
// a device, a directory or a socket is refused by name; a symbolic link to
// a regular file is followed), and at most these many bytes, so that a
// path like /dev/zero or a runaway file is an error, not a process that
// fills the memory. A file over its cap is refused with its size and the
// cap. docs/bad-input.md lists the messages.
#include <cstdint>

namespace wtc::io {

/// One mebibyte (bytes).
inline constexpr std::uint64_t kBytesPerMiB = std::uint64_t{1} << 20;

/// YAML description files: scenes, vehicles, terrains, studies (bytes).
/// The shipped ones are under 10 kB; 64 MiB leaves room for a terrain
/// written out by a program with its heights inline (about 5e6 numbers),
/// while yaml-cpp's nodes (a few hundred bytes each) keep what it holds
/// in memory to a few GB.
inline constexpr std::uint64_t kMaxDescriptionFileBytes = 64 * kBytesPerMiB;

/// Data files: heightfields (CSV, PGM) and meshes, with every file a mesh
/// references (bytes). 4 GiB holds the largest heightfield a terrain can
/// number, (2^31 - 1) / 2 pieces = 1.07e9 cells, as a 16-bit PGM (2.1 GB),
/// a 1e8-cell CSV (docs/terrain.md's largest field) at up to 40 bytes a
/// value, and a binary STL of 8e7 triangles (50 bytes each).
inline constexpr std::uint64_t kMaxDataFileBytes = 4096 * kBytesPerMiB;

/// Samples a DEM may give a heightfield (wtc/io/dem_file.hpp), after its
/// crop and step: 2^30, about the most cells a terrain can number
/// ((2^31 - 1) / 2 pieces), 8 GiB of heights. A compressed GeoTIFF can
/// hold far more samples than its bytes suggest, so the count is checked
/// before any height is read.
inline constexpr std::uint64_t kMaxDemSamples = std::uint64_t{1} << 30;

}  // namespace wtc::io
