#pragma once
// What a mesh file's header says it holds, checked against the file's size
// before assimp reads it. Internal to wtc::io.
//
// Why: assimp trusts declared counts and allocates for them first. Its OFF
// reader keeps the counts in 32 bits (a count of 353535235358 wraps to
// 1.3e9 vertices, ~16 GB; the assimp test model invalid/OutOfMemory.off),
// its PLY reader reserves every declared element, and its binary STL test
// `84 + 50 n == size` is computed in 32 bits, so a 88-byte file declaring
// 85899346 triangles passes it and asks for ~6 GB. A declared count that
// cannot fit in the file is refused here with the count and the size.
#include <cstdint>
#include <filesystem>
#include <string_view>

namespace wtc::io::detail {

/// Fewest bytes any OFF vertex line takes: three one-digit coordinates and
/// three separators ("0 0 0\n").
inline constexpr std::uint64_t kOffMinBytesPerVertex = 6;
/// Fewest bytes any OFF face line takes: a one-digit count and a separator.
inline constexpr std::uint64_t kOffMinBytesPerFace = 2;
/// Fewest bytes a property of an ASCII PLY element takes: a digit and a separator.
inline constexpr std::uint64_t kPlyAsciiMinBytesPerProperty = 2;
/// Binary STL: an 80-byte header and a 32-bit count, then 50 bytes per triangle.
inline constexpr std::uint64_t kStlHeaderBytes = 84;
inline constexpr std::uint64_t kStlBytesPerTriangle = 50;

/// Throws InvalidInputError "<path>: <format> header declares ... but the
/// file has only N bytes" when the header of `bytes` (the first bytes of the
/// file at `path`, of total size `file_size`) declares more elements than
/// the file can hold. Recognises OFF (and its C/N/ST/4/n variants), PLY
/// (ASCII and binary) and binary STL by content; other files pass.
void checkDeclaredCounts(const std::filesystem::path& path, std::string_view bytes, std::uint64_t file_size);

/// Same, reading the head of the file itself.
void checkDeclaredCounts(const std::filesystem::path& path);

}  // namespace wtc::io::detail
