#pragma once
// The ruts of soil that remembers, in a file (wtc::io; docs/soft-soil.md):
// what a run leaves in a GroundMemory, written at its end and read into the
// memory of another run, so that a second vehicle drives in the first one's
// ruts (wtc-sim writes ground_memory.csv beside a run's series; a scene's
// ground_memory_from reads one).
//
// The file is CSV, one touched node a line, sorted by y then x:
//   x_m, y_m, plastic_sinkage_m, max_pressure_pa
// the node's world position (m; 17 digits, its own to roundoff), the
// surface below the fresh one (m; < 0 where bulldozed soil was raised) and
// the largest normal stress the node carried (Pa), each to the digits its
// stored float holds, so that a memory written and read back is the same
// to the bit. Lines starting with '#' are comments (numpy.loadtxt reads
// the file as it is).
//
// Errors: InvalidInputError naming the file, and the line where a line is
// wrong: "ruts.csv:7:1: (1.03, 0.5) is no node of the terrain's soil
// regions", a row of other than four values, a negative pressure.
#include <filesystem>

#include "wtc/tyre/ground_memory.hpp"

namespace wtc::io {

/// Writes every touched node of `memory`. Throws naming a file it cannot write.
void writeGroundMemoryCsv(const std::filesystem::path& path, const GroundMemory& memory);

/// Writes the file's nodes into `memory` (nodes it does not name keep what
/// they hold). A file over kMaxDataFileBytes is refused by name.
void readGroundMemoryCsv(const std::filesystem::path& path, GroundMemory& memory);

}  // namespace wtc::io
