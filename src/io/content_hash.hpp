#pragma once
// FNV-1a, 64 bits (wtc::io): a hash that is the same on every build and
// machine (std::hash is not), for keys that name content: a study run's key
// (its scene file and settings), the build of wtc-sim that made a run.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace wtc::io {

inline constexpr std::uint64_t kFnv1aOffset = 14695981039346656037ull;

/// FNV-1a of `bytes`, continuing from `hash` (the offset basis to start).
std::uint64_t fnv1a(std::string_view bytes, std::uint64_t hash = kFnv1aOffset);

/// The hash as 16 lower-case hex digits.
std::string hexDigits(std::uint64_t hash);

/// hexDigits(fnv1a(the file's bytes)). Throws InvalidInputError naming the
/// file if it cannot be read.
std::string fileDigest(const std::filesystem::path& file);

}  // namespace wtc::io
