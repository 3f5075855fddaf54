// package:// resolution (wtc/vehicle/package_path.hpp).
#include "wtc/vehicle/package_path.hpp"

#include <cstdlib>
#include <system_error>

#include <tinyxml.h>

#include "wtc/base/error.hpp"

namespace wtc::vehicle {
namespace {

constexpr std::string_view kPackageScheme = "package://";
constexpr std::string_view kFileScheme = "file://";

// The <name> of DIR/package.xml, or "" when there is none or it cannot be read.
std::string manifestName(const std::filesystem::path& dir) {
  std::error_code ec;
  const std::filesystem::path manifest = dir / "package.xml";
  if (!std::filesystem::is_regular_file(manifest, ec)) return {};
  TiXmlDocument doc(manifest.string());
  if (!doc.LoadFile()) return {};
  const TiXmlElement* package = doc.FirstChildElement("package");
  const TiXmlElement* name = package ? package->FirstChildElement("name") : nullptr;
  return name && name->GetText() ? std::string(name->GetText()) : std::string();
}

// How deep below a package path's folder the crawl looks for a package
// (folders): a ROS workspace keeps its packages at src/<repository>/<package>,
// three levels down; ten leaves room and bounds a crawl of a wrong folder.
constexpr int kPackageCrawlDepth = 10;

// The package called `name` below `root`, as ROS finds one (rospack's and
// ament's crawl): a folder whose package.xml names it, whatever the folder
// is called; the crawl does not enter a package, a hidden folder, one
// marked CATKIN_IGNORE, COLCON_IGNORE or AMENT_IGNORE, or a symbolic link to
// a folder (no cycles). "" when there is none.
std::filesystem::path crawlForPackage(const std::filesystem::path& root, const std::string& name) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, ec);
  for (const fs::recursive_directory_iterator end; !ec && it != end; it.increment(ec)) {
    const fs::directory_entry& entry = *it;
    if (!entry.is_directory(ec) || entry.is_symlink(ec)) {
      if (entry.is_symlink(ec)) it.disable_recursion_pending();
      continue;
    }
    const std::string folder = entry.path().filename().string();
    if (folder.empty() || folder.front() == '.' || it.depth() >= kPackageCrawlDepth) {
      it.disable_recursion_pending();
      continue;
    }
    if (fs::exists(entry.path() / "CATKIN_IGNORE", ec) || fs::exists(entry.path() / "COLCON_IGNORE", ec) ||
        fs::exists(entry.path() / "AMENT_IGNORE", ec)) {
      it.disable_recursion_pending();
      continue;
    }
    if (fs::is_regular_file(entry.path() / "package.xml", ec)) {
      if (manifestName(entry.path()) == name) return entry.path();
      it.disable_recursion_pending();  // a package holds no packages
    }
  }
  return {};
}

}  // namespace

std::vector<std::filesystem::path> packagePathFromEnvironment() {
  std::vector<std::filesystem::path> out;
  const char* value = std::getenv("WTC_PACKAGE_PATH");
  if (value == nullptr) return out;
  const std::string text(value);
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(':', start), text.size());
    if (end > start) out.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

std::filesystem::path resolveResourceUri(const std::string& uri, const std::filesystem::path& base_dir,
                                         const std::vector<std::filesystem::path>& package_path,
                                         const std::string& where) {
  if (uri.rfind(kFileScheme, 0) == 0) return std::filesystem::path(uri.substr(kFileScheme.size()));
  if (uri.rfind(kPackageScheme, 0) != 0) {
    const std::filesystem::path p(uri);
    return p.is_absolute() ? p : base_dir / p;
  }
  const std::string rest = uri.substr(kPackageScheme.size());
  const std::size_t slash = rest.find('/');
  if (slash == std::string::npos || slash == 0 || slash + 1 == rest.size()) {
    throw InvalidInputError(where + ": " + uri + " is not package://NAME/PATH");
  }
  const std::string name = rest.substr(0, slash);
  const std::string inside = rest.substr(slash + 1);
  std::string searched;
  for (const std::filesystem::path& dir : package_path) {
    searched += (searched.empty() ? "" : ", ") + dir.string();
    std::error_code ec;
    std::filesystem::path package;
    if (manifestName(dir) == name) {
      package = dir;
    } else if (std::filesystem::is_directory(dir / name, ec)) {
      package = dir / name;
    } else if (const std::filesystem::path crawled = crawlForPackage(dir, name); !crawled.empty()) {
      package = crawled;  // a workspace: the package is named by its package.xml, not its folder
    } else {
      continue;
    }
    const std::filesystem::path file = package / inside;
    if (!std::filesystem::exists(file, ec)) {
      throw InvalidInputError(where + ": " + uri + ": package '" + name + "' (" + package.string() + ") has no file '" +
                              inside + "'");
    }
    return file;
  }
  throw InvalidInputError(where + ": " + uri + ": package '" + name + "' is on none of the package path's folders (" +
                          (searched.empty() ? std::string("the package path is empty: give --package-path, "
                                                          "WTC_PACKAGE_PATH or the vehicle file's package_path")
                                            : searched) +
                          ")");
}

}  // namespace wtc::vehicle
