#pragma once
// What wtc-sim and wtc-study share as programs (not as physics): finding
// their own data files and running their plotting scripts. Each app defines
// WTC_SOURCE_DIR and WTC_INSTALL_DATADIR (apps/CMakeLists.txt).
#include <cstdlib>
#include <filesystem>
#include <string>

namespace wtc::apps {

/// A file of an app's own: beside its sources (apps/<app>/<name>) in a build
/// tree, else where it is installed.
inline std::filesystem::path ownFile(const std::string& app, const std::string& name) {
  const std::filesystem::path source = std::filesystem::path(WTC_SOURCE_DIR) / "apps" / app / name;
  if (std::filesystem::exists(source)) return source;
  return std::filesystem::path(WTC_INSTALL_DATADIR) / name;
}

/// Runs `script` on `dir` with the first Python on PATH, else Debian's
/// (where python3-matplotlib puts it). True if it drew.
inline bool runPlotScript(const std::filesystem::path& script, const std::filesystem::path& dir) {
  const std::string args = " '" + script.string() + "' '" + dir.string() + "'";
  int rc = std::system(("python3" + args + " 2>/dev/null").c_str());
  if (rc != 0) rc = std::system(("/usr/bin/python3" + args).c_str());
  return rc == 0;
}

}  // namespace wtc::apps
