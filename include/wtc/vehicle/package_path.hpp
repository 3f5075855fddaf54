#pragma once
// package:// URIs (ROS's), resolved as ROS tools do: package://NAME/REST is
// the file REST inside the package NAME, found on a package path. An entry
// DIR of the path is the package NAME when DIR/package.xml names it (how
// vehicles/, whose package.xml names it wtc_vehicles, is found), or holds it
// as DIR/NAME when that folder exists (how tests/urdf/packages holds
// wtc_test_pkg), or holds it anywhere below, in a folder of any name whose
// package.xml names it (a ROS workspace: src/<repository>/<package>; the
// crawl ROS's tools make, not into packages, hidden folders or folders
// marked CATKIN_IGNORE, COLCON_IGNORE or AMENT_IGNORE, at most ten folders
// deep). The path comes from the caller (wtc-sim's --package-path)
// followed by the environment's WTC_PACKAGE_PATH (':'-separated).
#include <filesystem>
#include <string>
#include <vector>

namespace wtc::vehicle {

/// The folders of WTC_PACKAGE_PATH, in order (empty when it is unset).
std::vector<std::filesystem::path> packagePathFromEnvironment();

/// The file `uri` names: a package:// URI resolved on `package_path`, a
/// file:// URI or a plain path relative to `base_dir`. Throws
/// InvalidInputError "<where>: package://NAME/REST: package 'NAME' is on
/// none of the package path's folders (a, b)" (or "the package path is
/// empty"), or that the file is not in the package.
std::filesystem::path resolveResourceUri(const std::string& uri, const std::filesystem::path& base_dir,
                                         const std::vector<std::filesystem::path>& package_path,
                                         const std::string& where);

}  // namespace wtc::vehicle
