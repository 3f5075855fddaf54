#pragma once
// A path in the system's temporary folder that no other test process uses.
// ctest runs the suite's tests in parallel, and several checkouts of the
// project may run their suites on one machine at once: a fixed name there is
// a race (one process's file read back half written by another).

#include <unistd.h>

#include <filesystem>
#include <string>

namespace wtc::test {

/// temp_directory_path() / "wtc_tests_<process id>" / name, the folder made:
/// the name itself is kept whole (error messages show it).
inline std::filesystem::path scratchPath(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("wtc_tests_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir / name;
}

}  // namespace wtc::test
