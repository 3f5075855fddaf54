#include "content_hash.hpp"

#include <cstdio>

#include "file_support.hpp"

namespace wtc::io {

std::uint64_t fnv1a(std::string_view bytes, std::uint64_t hash) {
  for (const unsigned char c : bytes) {
    hash ^= c;
    hash *= 1099511628211ull;  // the 64-bit FNV prime
  }
  return hash;
}

std::string hexDigits(std::uint64_t hash) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return hex;
}

std::string fileDigest(const std::filesystem::path& file) { return hexDigits(fnv1a(detail::readDataFile(file))); }

}  // namespace wtc::io
