#include "file_support.hpp"

#include <cctype>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "wtc/base/error.hpp"

namespace wtc::io::detail {
namespace {

// What a file of mode `mode` is, for "not a regular file (...)".
const char* typeName(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "of an unknown type";
}

std::string capText(std::uint64_t bytes) {
  return std::to_string(bytes) + " bytes (" + std::to_string(bytes / kBytesPerMiB) + " MiB)";
}

[[noreturn]] void refuseSize(const std::filesystem::path& path, std::uint64_t size, std::uint64_t max_bytes,
                             const char* kind, bool at_least) {
  throw InvalidInputError(where(path) + (at_least ? "at least " : "") + std::to_string(size) +
                          " bytes, more than the " + capText(max_bytes) + " WTC reads from " + kind +
                          " (docs/bad-input.md)");
}

void checkStat(const std::filesystem::path& path, const struct stat& st, std::uint64_t max_bytes, const char* kind) {
  if (!S_ISREG(st.st_mode)) {
    throw InvalidInputError(where(path) + "not a regular file (" + typeName(st.st_mode) + ")");
  }
  if (static_cast<std::uint64_t>(st.st_size) > max_bytes) {
    refuseSize(path, static_cast<std::uint64_t>(st.st_size), max_bytes, kind, false);
  }
}

[[noreturn]] void refuseErrno(const std::filesystem::path& path, int error, const char* doing) {
  if (error == ENOENT || error == ENOTDIR) throw InvalidInputError(where(path) + "file not found");
  throw InvalidInputError(where(path) + doing + std::strerror(error));
}

// Closes the descriptor on every way out.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::uint64_t requireRegularFile(const std::filesystem::path& path, std::uint64_t max_bytes, const char* kind) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) refuseErrno(path, errno, "cannot read: ");
  checkStat(path, st, max_bytes, kind);
  return static_cast<std::uint64_t>(st.st_size);
}

std::string readWholeFile(const std::filesystem::path& path, std::uint64_t max_bytes, const char* kind) {
  // O_NONBLOCK: opening a FIFO without a writer returns at once (and is
  // then refused) instead of waiting; it changes nothing for a regular file.
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) {
    const int error = errno;
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) checkStat(path, st, max_bytes, kind);  // a socket cannot be opened
    refuseErrno(path, error, "cannot open: ");
  }
  struct stat st {};
  if (::fstat(file.fd, &st) != 0) refuseErrno(path, errno, "cannot read: ");
  checkStat(path, st, max_bytes, kind);
  std::string bytes(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t filled = 0;
  for (;;) {
    // A file that grew since fstat: read on, but never past the cap.
    if (filled == bytes.size()) {
      if (bytes.size() > max_bytes) refuseSize(path, bytes.size(), max_bytes, kind, true);
      bytes.resize(std::min<std::uint64_t>(max_bytes + 1, std::max<std::size_t>(2 * bytes.size(), 4096)));
    }
    const ssize_t got = ::read(file.fd, bytes.data() + filled, bytes.size() - filled);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) refuseErrno(path, errno, "cannot read: ");
    if (got == 0) break;
    filled += static_cast<std::size_t>(got);
  }
  if (filled > max_bytes) refuseSize(path, filled, max_bytes, kind, true);
  bytes.resize(filled);
  return bytes;
}

std::string readDescriptionFile(const std::filesystem::path& path) {
  return readWholeFile(path, kMaxDescriptionFileBytes, kDescriptionFileKind);
}

std::string readDataFile(const std::filesystem::path& path) {
  return readWholeFile(path, kMaxDataFileBytes, kDataFileKind);
}

std::string where(const std::filesystem::path& path, long line, long column) {
  return path.string() + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
}

std::string where(const std::filesystem::path& path) { return path.string() + ": "; }

std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace wtc::io::detail
