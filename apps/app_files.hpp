#pragma once
// What wtc-sim and wtc-study share as programs (not as physics): their
// command lines' exit statuses and version, finding their own data files
// and running their plotting scripts. Each app defines WTC_SOURCE_DIR,
// WTC_INSTALL_DATADIR and WTC_VERSION (apps/CMakeLists.txt).
#include <CLI/CLI.hpp>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "wtc/base/error.hpp"
#include "io/content_hash.hpp"

namespace wtc::apps {

/// This build of the running program: FNV-1a of its executable (16 hex
/// digits), recorded in each summary so that results of different builds
/// are not mixed unnoticed; empty if the file cannot be read.
inline std::string programIdentity() {
  try {
    return wtc::io::fileDigest("/proc/self/exe");
  } catch (const wtc::InvalidInputError&) {
    return {};
  }
}

/// Adds --version: "<program> <project version> (build <identity>)".
inline void addVersionFlag(CLI::App& app, const std::string& program) {
  app.set_version_flag("--version", [program] {
    const std::string build = programIdentity();
    return program + " " + WTC_VERSION + (build.empty() ? "" : " (build " + build + ")");
  });
}

/// Parses the command line. Returns the exit status when the program is
/// to end here: 0 after --help or --version (printed), 2 for a command-line
/// error (printed: the documented status of bad input, where CLI11's own
/// codes are 104-109).
inline std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
    return std::nullopt;
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
}

/// A file of an app's own: beside its sources (apps/<app>/<name>) in a build
/// tree, else where it is installed.
inline std::filesystem::path ownFile(const std::string& app, const std::string& name) {
  const std::filesystem::path source = std::filesystem::path(WTC_SOURCE_DIR) / "apps" / app / name;
  if (std::filesystem::exists(source)) return source;
  return std::filesystem::path(WTC_INSTALL_DATADIR) / name;
}

/// `text` as one shell word: single-quoted, ' written as '\''.
inline std::string shellWord(const std::string& text) {
  std::string word = "'";
  for (const char c : text) word.append(c == '\'' ? std::string("'\\''") : std::string(1, c));
  return word + "'";
}

/// Runs `script` on `dir` (then `options`, each a word) with the first
/// Python on PATH, else Debian's (where python3-matplotlib puts it). True
/// if it drew.
inline bool runPlotScript(const std::filesystem::path& script, const std::filesystem::path& dir,
                          const std::vector<std::string>& options = {}) {
  std::string args = " " + shellWord(script.string()) + " " + shellWord(dir.string());
  for (const std::string& o : options) args += " " + shellWord(o);
  int rc = std::system(("python3" + args + " 2>/dev/null").c_str());
  if (rc != 0) rc = std::system(("/usr/bin/python3" + args).c_str());
  return rc == 0;
}

}  // namespace wtc::apps
