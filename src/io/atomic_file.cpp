#include "atomic_file.hpp"

#include <fstream>

#include "wtc/base/error.hpp"

namespace wtc::io {

void writeFileAtomically(const std::filesystem::path& file, std::string_view text) {
  const std::filesystem::path tmp = file.string() + ".tmp";
  {
    std::ofstream out(tmp);
    out << text;
    if (!out) throw InvalidInputError("cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, file);
}

}  // namespace wtc::io
