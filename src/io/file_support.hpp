#pragma once
// Small helpers shared by the file readers of wtc::io. Internal.
#include <filesystem>
#include <string>

namespace wtc::io::detail {

/// The whole file as bytes. Throws InvalidInputError "<path>: file not found"
/// or "<path>: cannot read: <reason>".
std::string readWholeFile(const std::filesystem::path& path);

/// "<path>:<line>:<column>: " (1-based), the prefix of positioned messages.
std::string where(const std::filesystem::path& path, long line, long column);

/// "<path>: ", the prefix of messages without a position.
std::string where(const std::filesystem::path& path);

}  // namespace wtc::io::detail
