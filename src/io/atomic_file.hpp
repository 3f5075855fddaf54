#pragma once
// Writing a whole file so that a reader never sees half of it (wtc::io):
// the text goes to "<file>.tmp", which is then renamed over `file`. Run
// summaries and a study's tables are written this way.
#include <filesystem>
#include <string_view>

namespace wtc::io {

/// Throws InvalidInputError naming the file it cannot write.
void writeFileAtomically(const std::filesystem::path& file, std::string_view text);

}  // namespace wtc::io
