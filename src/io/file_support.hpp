#pragma once
// Small helpers shared by the file readers of wtc::io. Internal.
#include <cstdint>
#include <filesystem>
#include <string>

#include "wtc/io/file_limits.hpp"

namespace wtc::io::detail {

/// Checks that `path` is a regular file (symbolic links followed) of at
/// most `max_bytes`, and returns its size. Throws InvalidInputError
/// "<path>: file not found", "<path>: not a regular file (a FIFO)" (or a
/// directory, a character device, ...) or "<path>: 70000000 bytes, more
/// than the 67108864 bytes (64 MiB) WTC reads from a description file".
/// `kind` names the cap's file kind in that message.
std::uint64_t requireRegularFile(const std::filesystem::path& path, std::uint64_t max_bytes, const char* kind);

/// The whole file as bytes, after requireRegularFile's checks (made on
/// the opened file, so that a file swapped for a FIFO in between is not
/// waited on either), reading at most `max_bytes`. Throws as above, or
/// "<path>: cannot read: <reason>".
std::string readWholeFile(const std::filesystem::path& path, std::uint64_t max_bytes, const char* kind);

/// The kinds of file, with their caps (wtc/io/file_limits.hpp).
inline constexpr const char* kDescriptionFileKind = "a description file (YAML)";
inline constexpr const char* kDataFileKind = "a data file (heightfield, mesh)";

/// readWholeFile for the YAML description files (kMaxDescriptionFileBytes).
std::string readDescriptionFile(const std::filesystem::path& path);
/// readWholeFile for data files (kMaxDataFileBytes).
std::string readDataFile(const std::filesystem::path& path);

/// The file's extension in lower case (".TIF" -> ".tif"), by which the
/// readers pick a format.
std::string lowerExtension(const std::filesystem::path& path);

/// "<path>:<line>:<column>: " (1-based), the prefix of positioned messages.
std::string where(const std::filesystem::path& path, long line, long column);

/// "<path>: ", the prefix of messages without a position.
std::string where(const std::filesystem::path& path);

}  // namespace wtc::io::detail
