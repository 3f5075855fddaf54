// Declared counts of OFF, PLY and binary STL headers against the file size
// (why: see mesh_header_check.hpp).
#include "mesh_header_check.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "file_support.hpp"
#include "wtc/base/error.hpp"

namespace wtc::io::detail {
namespace {

constexpr std::uint64_t kSaturated = std::numeric_limits<std::uint64_t>::max();
/// The head read to find a header: PLY headers with long comments fit.
constexpr std::size_t kHeadBytes = 64 * 1024;

std::uint64_t saturatingAdd(std::uint64_t a, std::uint64_t b) { return a > kSaturated - b ? kSaturated : a + b; }
std::uint64_t saturatingMul(std::uint64_t a, std::uint64_t b) {
  return (a != 0 && b > kSaturated / a) ? kSaturated : a * b;
}

// A decimal count as written (not wrapped to 32 bits the way assimp reads
// it), saturating; false if `text` does not start with a digit.
bool parseCount(std::string_view text, std::uint64_t& value) {
  if (text.empty() || !std::isdigit(static_cast<unsigned char>(text.front()))) return false;
  value = 0;
  for (const char c : text) {
    if (!std::isdigit(static_cast<unsigned char>(c))) break;
    value = saturatingAdd(saturatingMul(value, 10), static_cast<std::uint64_t>(c - '0'));
  }
  return true;
}

std::string countText(std::uint64_t n) { return n == kSaturated ? "more than 1.8e19" : std::to_string(n); }

// Whitespace-separated tokens of `bytes`, skipping '#' comments to the end
// of their line (OFF's comments).
class Tokens {
 public:
  explicit Tokens(std::string_view bytes) : bytes_(bytes) {}
  std::string_view next() {
    while (pos_ < bytes_.size()) {
      const char c = bytes_[pos_];
      if (c == '#') {
        while (pos_ < bytes_.size() && bytes_[pos_] != '\n') ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        ++pos_;
      } else {
        break;
      }
    }
    const std::size_t start = pos_;
    while (pos_ < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[pos_])) && bytes_[pos_] != '#') {
      ++pos_;
    }
    return bytes_.substr(start, pos_ - start);
  }

 private:
  std::string_view bytes_;
  std::size_t pos_ = 0;
};

void refuse(const std::filesystem::path& path, const std::string& format, const std::string& declared,
            std::uint64_t needed, std::uint64_t file_size) {
  throw InvalidInputError(where(path) + format + " header declares " + declared + ", which needs at least " +
                          countText(needed) + " bytes, but the file has only " + std::to_string(file_size) +
                          " bytes (a damaged or hostile file; refused before allocating for it)");
}

// OFF keyword with assimp's optional prefixes: [ST][C][N][4][n]OFF.
bool isOffKeyword(std::string_view token) {
  std::size_t i = 0;
  if (token.substr(i, 2) == "ST") i += 2;
  if (token.substr(i, 1) == "C") ++i;
  if (token.substr(i, 1) == "N") ++i;
  if (token.substr(i, 1) == "4") ++i;
  const bool dimension = token.substr(i, 1) == "n";
  if (dimension) ++i;
  return token.substr(i) == "OFF";
}

void checkOffFaces(const std::filesystem::path& path, std::string_view bytes);

bool hasOffExtension(const std::filesystem::path& path) {
  return detail::lowerExtension(path) == ".off";
}

// What assimp's OFF reader takes for the keyword and the first count in a
// header's first token: it skips the keyword's letters ([ST][C][N][4][n]OFF)
// and reads the count from what follows them, glued or not ("OFF3585235358",
// "ST353523355"); a file named *.off is read by it even without a keyword
// ("3535235358 6 0"). All three found by fuzzing (assimp asked for 4-43 GB).
// Returns the keyword ("OFF" when there is none but the name says OFF; ""
// if the file is not OFF) and the first count's text in `rest` ("" when it
// is the next token).
std::string_view offKeywordOf(const std::filesystem::path& path, std::string_view token, std::string_view& rest) {
  rest = {};
  const std::size_t off = token.find("OFF");
  const bool keyword = off != std::string_view::npos && isOffKeyword(token.substr(0, off + 3));
  if (!keyword && !hasOffExtension(path)) return {};
  std::size_t letters = 0;  // the end of the token's last letter
  for (std::size_t i = 0; i < token.size(); ++i) {
    if (std::isalpha(static_cast<unsigned char>(token[i]))) letters = i + 1;
  }
  rest = token.substr(keyword ? off + 3 : letters);
  return keyword ? token.substr(0, off + 3) : std::string_view("OFF");
}

void checkOff(const std::filesystem::path& path, std::string_view bytes, std::uint64_t file_size) {
  Tokens tokens(bytes);
  std::string_view glued;
  const std::string_view keyword = offKeywordOf(path, tokens.next(), glued);
  if (keyword.empty()) return;
  // The next token: the one glued to the keyword, else the next one.
  const auto next = [&] {
    const std::string_view t = glued.empty() ? tokens.next() : glued;
    glued = {};
    return t;
  };
  if (keyword.find('n') != std::string_view::npos) next();  // nOFF: the dimension comes first
  std::uint64_t vertices = 0, faces = 0;
  if (!parseCount(next(), vertices) || !parseCount(next(), faces)) return;  // assimp refuses it
  const std::uint64_t needed =
      saturatingAdd(saturatingMul(vertices, kOffMinBytesPerVertex), saturatingMul(faces, kOffMinBytesPerFace));
  // The last line may lack its newline: one byte of slack.
  if (needed > saturatingAdd(file_size, 1)) {
    refuse(path, "OFF", countText(vertices) + " vertices and " + countText(faces) + " faces", needed, file_size);
  }
  checkOffFaces(path, bytes);
}

// OFF face lines, which assimp 5.2 trusts: a face of zero vertices, a face
// listing more vertices than its line holds, or an index past the vertex
// count make its reader touch memory it does not own (found by
// wtc_fuzz_mesh_off; docs/fuzzing.md). Lines split at '\n' or '\r' as
// assimp splits them; blank lines and '#' comments skipped.
void checkOffFaces(const std::filesystem::path& path, std::string_view bytes) {
  struct Line {
    std::string_view text;
    long number;
  };
  std::vector<Line> lines;
  long number = 1;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= bytes.size(); ++i) {
    if (i == bytes.size() || bytes[i] == '\n' || bytes[i] == '\r') {
      const std::string_view text = bytes.substr(start, i - start);
      const std::size_t first = text.find_first_not_of(" \t");
      if (first != std::string_view::npos && text[first] != '#') lines.push_back({text, number});
      if (i < bytes.size() && bytes[i] == '\n') ++number;
      start = i + 1;
    }
  }
  if (lines.empty()) return;
  // The keyword line, then the counts (on it or on the next lines).
  std::uint64_t counts[2] = {0, 0};
  int found = 0;
  std::size_t next = 0;
  bool keyword = true;
  while (found < 2 && next < lines.size()) {
    Tokens tokens(lines[next++].text);
    std::string_view glued;
    if (keyword) {
      const std::string_view k = offKeywordOf(path, tokens.next(), glued);
      if (k.find('n') != std::string_view::npos) {  // nOFF: skip the dimension, glued or next
        if (glued.empty()) {
          tokens.next();
        } else {
          glued = {};
        }
      }
      keyword = false;
    }
    for (std::string_view t = glued.empty() ? tokens.next() : glued; !t.empty() && found < 2; t = tokens.next()) {
      if (!parseCount(t, counts[found++])) return;  // assimp refuses it
    }
  }
  const std::uint64_t vertices = counts[0], faces = counts[1];
  next += static_cast<std::size_t>(std::min<std::uint64_t>(vertices, lines.size()));
  for (std::uint64_t f = 0; f < faces && next < lines.size(); ++f, ++next) {
    Tokens tokens(lines[next].text);
    const auto at = where(path, lines[next].number, 1) + "face " + std::to_string(f) + ": ";
    std::uint64_t n = 0;
    if (!parseCount(tokens.next(), n) || n == 0) {
      throw InvalidInputError(at + "a face needs a vertex count of at least 1 first on its line");
    }
    for (std::uint64_t k = 0; k < n; ++k) {
      std::uint64_t index = 0;
      if (!parseCount(tokens.next(), index)) {
        throw InvalidInputError(at + "declares " + countText(n) + " vertices but its line lists " + std::to_string(k));
      }
      if (index >= vertices) {
        throw InvalidInputError(at + "vertex index " + countText(index) + " is out of range (the file declares " +
                                countText(vertices) + " vertices)");
      }
    }
  }
}

std::uint64_t plyTypeBytes(std::string_view type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" || type == "float32") {
    return 4;
  }
  if (type == "double" || type == "float64") return 8;
  return 0;  // unknown: assimp refuses or skips it; count it as nothing
}

void checkPly(const std::filesystem::path& path, std::string_view bytes, std::uint64_t file_size) {
  // assimp takes "ply" in any case ("pLy" hung it too), and reads a *.ply
  // file as PLY whatever its first bytes.
  std::string magic(bytes.substr(0, 3));
  std::transform(magic.begin(), magic.end(), magic.begin(), [](unsigned char c) { return std::tolower(c); });
  if (magic != "ply" && detail::lowerExtension(path) != ".ply") return;
  // A PLY header is lines of printable ASCII ending in a line end_header
  // (PLY's definition); assimp 5.2 loops forever on headers with control or
  // non-ASCII bytes, with or without end_header (found by fuzzing:
  // wtc_fuzz_mesh_ply hung twice), so refuse both. end_header counts only
  // where a line starts: assimp hung on "propertyend_header" (fuzzing again).
  std::size_t end = bytes.find("end_header");
  while (end != std::string_view::npos && end > 0 && bytes[end - 1] != '\n') end = bytes.find("end_header", end + 1);
  const std::size_t header_end = end == std::string_view::npos ? bytes.size() : end;
  for (std::size_t i = 0; i < header_end; ++i) {
    const auto c = static_cast<unsigned char>(bytes[i]);
    if ((c < 0x20 && c != '\n' && c != '\r' && c != '\t') || c >= 0x7f) {
      throw InvalidInputError(where(path) + "PLY header holds a byte that is not printable ASCII (" +
                              std::to_string(c) + ") at byte " + std::to_string(i) + ": not a PLY file");
    }
  }
  if (end == std::string_view::npos) {
    if (file_size > bytes.size()) return;  // the header goes on past the head read: assimp decides
    throw InvalidInputError(where(path) + "PLY header has no end_header line: not a PLY file");
  }
  // end_header ends its line (PLY's grammar; assimp 5.2 hangs on
  // end_header followed by a byte: found by fuzzing). Other header lines
  // are left to assimp: old exporters wrote free text there (Blender's
  // "Created by ..." in assimp's own Wuson.ply), which it reads.
  const std::size_t after = end + std::string_view("end_header").size();
  if (!(after == bytes.size() || bytes[after] == '\n' || bytes.substr(after, 2) == "\r\n")) {
    throw InvalidInputError(where(path) + "PLY header: end_header must end its line: not a PLY file");
  }

  std::size_t body = bytes.find('\n', end);
  body = body == std::string_view::npos ? bytes.size() : body + 1;
  bool ascii = true;
  struct Element {
    std::string name;
    std::uint64_t count = 0;
    std::uint64_t min_bytes = 0;
  };
  std::vector<Element> elements;
  std::size_t line_start = 0;
  while (line_start < end) {
    std::size_t line_end = bytes.find('\n', line_start);
    if (line_end == std::string_view::npos) line_end = bytes.size();
    Tokens tokens(bytes.substr(line_start, line_end - line_start));
    line_start = line_end + 1;
    const std::string_view word = tokens.next();
    if (word == "format") {
      ascii = tokens.next() == "ascii";
    } else if (word == "element") {
      Element e;
      e.name = std::string(tokens.next());
      if (!parseCount(tokens.next(), e.count)) return;  // assimp refuses it
      elements.push_back(std::move(e));
    } else if (word == "property" && !elements.empty()) {
      std::string_view type = tokens.next();
      if (type == "list") type = tokens.next();  // an empty list is just its count
      elements.back().min_bytes += ascii ? kPlyAsciiMinBytesPerProperty : plyTypeBytes(type);
    }
  }
  std::uint64_t needed = 0;
  std::string declared;
  for (const auto& e : elements) {
    // An element without properties still takes a line (ASCII); count one byte.
    needed = saturatingAdd(needed, saturatingMul(e.count, std::max<std::uint64_t>(e.min_bytes, 1)));
    declared += (declared.empty() ? "" : ", ") + countText(e.count) + " '" + e.name + "'";
  }
  const std::uint64_t available = file_size - std::min<std::uint64_t>(file_size, body) + (ascii ? 1 : 0);
  if (needed > available)
    refuse(path, ascii ? "ASCII PLY" : "binary PLY", declared, saturatingAdd(needed, body), file_size);
}

void checkBinaryStl(const std::filesystem::path& path, std::string_view bytes, std::uint64_t file_size) {
  if (file_size < kStlHeaderBytes || bytes.size() < kStlHeaderBytes) return;
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);  // little-endian, as the format says
  const std::uint64_t needed = kStlHeaderBytes + kStlBytesPerTriangle * count;
  // assimp takes the file for binary STL when 84 + 50 n equals the size in
  // 32-bit arithmetic; only the wrapped equality is a lie.
  const auto wrapped = static_cast<std::uint32_t>(needed);
  if (wrapped == static_cast<std::uint32_t>(file_size) && needed != file_size) {
    refuse(path, "binary STL", std::to_string(count) + " triangles", needed, file_size);
  }
}

}  // namespace

void checkDeclaredCounts(const std::filesystem::path& path, std::string_view bytes, std::uint64_t file_size) {
  checkOff(path, bytes, file_size);
  checkPly(path, bytes, file_size);
  checkBinaryStl(path, bytes, file_size);
}

void checkDeclaredCounts(const std::filesystem::path& path) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) return;  // assimp reports what is wrong with the file
  std::ifstream in(path, std::ios::binary);
  std::string head(std::min<std::uintmax_t>(size, kHeadBytes), '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  // An OFF file's faces are checked too: read all of it (text, and its
  // declared counts already fit its size).
  std::string_view glued;
  if (size > head.size() && !offKeywordOf(path, Tokens(head).next(), glued).empty()) {
    checkDeclaredCounts(path, readDataFile(path), size);
    return;
  }
  checkDeclaredCounts(path, head, size);
}

}  // namespace wtc::io::detail
