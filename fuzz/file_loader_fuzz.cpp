// libFuzzer target: one of WTC's file loaders (chosen at build time by
// WTC_FUZZ_LOADER) on fuzzed file contents. A file must load or be refused
// with wtc::InvalidInputError; a crash, a sanitizer report, or any other
// exception escaping the loader is a finding.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include "wtc/base/error.hpp"
#include "wtc/io/mesh_file.hpp"
#include "wtc/sim/scene_file.hpp"
#include "wtc/io/terrain_file.hpp"
#include "wtc/vehicle/vehicle_file.hpp"

namespace {

// The fuzzed file's path; relative references in it resolve next to it.
std::filesystem::path fuzzFile() {
  static const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                            ("wtc_fuzz_" + std::to_string(getpid())) /
                                            (std::string("input.") + WTC_FUZZ_EXTENSION);
  return path;
}

void load(const std::filesystem::path& path) {
  const std::string loader = WTC_FUZZ_LOADER;
  if (loader == "terrain") {
    (void)wtc::io::loadTerrain(path);
  } else if (loader == "vehicle") {
    (void)wtc::vehicle::loadVehicle(path);
  } else if (loader == "scene") {
    (void)wtc::sim::loadScene(path);
  } else {
    (void)wtc::io::readMeshFile(path);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path path = fuzzFile();
  std::filesystem::create_directories(path.parent_path());
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    load(path);
  } catch (const wtc::InvalidInputError&) {
    // Refused with a message: fine.
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s loader let through %s\n", WTC_FUZZ_LOADER, e.what());
    std::abort();
  }
  return 0;
}
