// What the loaders read (wtc/io/file_limits.hpp): every loader refuses a
// path that is not a regular file (a character device like /dev/zero, a
// FIFO, a directory, a socket), by name and without reading it, follows a
// symbolic link to a regular file, and refuses a file over its kind's cap
// with the file's size and the cap. The caps are tested on sparse files:
// their size is there, their bytes are not.
#include "wtc/io/file_limits.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <functional>
#include <string>
#include <vector>

#include "temp_dir.hpp"
#include "wtc/io/heightfield_file.hpp"
#include "wtc/io/mesh_file.hpp"
#include "wtc/io/terrain_file.hpp"
#include "wtc/sim/scene_file.hpp"
#include "wtc/study/study_file.hpp"
#include "wtc/vehicle/vehicle_file.hpp"

namespace wtc::io {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using testing::errorOf;
using ::testing::HasSubstr;
using testing::sourceDir;

struct Loader {
  const char* name;
  std::function<void(const fs::path&)> load;
};

// Every loader of a user's file, given the path directly.
std::vector<Loader> loaders() {
  return {{"terrain", [](const fs::path& p) { loadTerrain(p); }},
          {"vehicle", [](const fs::path& p) { vehicle::loadVehicle(p); }},
          {"scene", [](const fs::path& p) { sim::loadScene(p); }},
          {"study", [](const fs::path& p) { study::loadStudyPlan(p); }},
          {"heightfield csv", [](const fs::path& p) { readHeightfieldCsv(p, {}); }},
          {"heightfield pgm", [](const fs::path& p) { readHeightfieldPgm(p, {}); }},
          {"mesh", [](const fs::path& p) { readMeshFile(p); }}};
}

class FileLimitsTest : public testing::TempDirTest {
 protected:
  // A FIFO with no writer: opening it for reading the usual way waits for one.
  fs::path fifo(const std::string& name) const {
    const fs::path path = dir() / name;
    EXPECT_EQ(::mkfifo(path.c_str(), 0600), 0) << path;
    return path;
  }
  // A listening Unix socket bound at dir/name (closed at the end of the test).
  fs::path socket(const std::string& name) {
    const fs::path path = dir() / name;
    socket_ = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    EXPECT_LT(path.string().size(), sizeof address.sun_path);
    path.string().copy(address.sun_path, sizeof address.sun_path - 1);
    EXPECT_EQ(::bind(socket_, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0) << path;
    return path;
  }
  // A file of `bytes` bytes that holds none (sparse).
  fs::path sparse(const std::string& name, std::uint64_t bytes) const {
    const fs::path path = write(name, "");
    fs::resize_file(path, bytes);
    return path;
  }
  void TearDown() override {
    if (socket_ >= 0) ::close(socket_);
    TempDirTest::TearDown();
  }

 private:
  int socket_ = -1;
};

TEST_F(FileLimitsTest, EveryLoaderRefusesWhatIsNotARegularFileByName) {
  const std::vector<std::pair<fs::path, std::string>> specials = {
      {"/dev/zero", "not a regular file (a character device)"},
      {"/dev/null", "not a regular file (a character device)"},
      {fifo("pipe.yaml"), "not a regular file (a FIFO)"},
      {dir(), "not a regular file (a directory)"},
      {socket("socket.yaml"), "not a regular file (a socket)"}};
  for (const Loader& loader : loaders()) {
    for (const auto& [path, problem] : specials) {
      EXPECT_THAT(errorOf([&] { loader.load(path); }), HasSubstr(path.string() + ": " + problem))
          << loader.name << " on " << path;
    }
  }
}

TEST_F(FileLimitsTest, ReferencedFilesThatAreNotRegularAreRefusedWhereTheyAreNamed) {
  // Case: a scene whose vehicle is /dev/zero (it grew to 21.9 GB), at its line and key.
  const fs::path scene =
      write("scene.yaml", "name: s\nduration: 1\nterrain: " + (sourceDir() / "terrains/flat.yaml").string() +
                              "\nvehicle: /dev/zero\ncontroller: {type: none}\n");
  EXPECT_THAT(errorOf([&] { sim::loadScene(scene); }),
              HasSubstr(scene.string() + ":4:10: vehicle: /dev/zero: not a regular file (a character device)"));
  // Case: a terrain's heightfield and mesh files.
  const fs::path csv = fifo("heights.csv");
  const fs::path terrain = write("terrain.yaml",
                                 "materials: {a: {}}\npieces:\n  - {type: heightfield, spacing: 1, file: heights.csv}\n"
                                 "  - {type: mesh, file: /dev/zero}\n");
  EXPECT_THAT(errorOf([&] { loadTerrain(terrain); }), HasSubstr(csv.string() + ": not a regular file (a FIFO)"));
  fs::remove(csv);
  write("heights.csv", "0, 0\n0, 0\n");
  EXPECT_THAT(errorOf([&] { loadTerrain(terrain); }), HasSubstr("/dev/zero: not a regular file (a character device)"));
  // Case: a study's scene.
  const fs::path study = write("study.yaml",
                               "name: s\nbase: {engine: bullet, mode: force, dt: 0.001}\nreference: {}\nsweeps: {}\n"
                               "scenarios:\n  a: {scene: /dev/zero}\n");
  EXPECT_THAT(errorOf([&] { study::loadStudyPlan(study); }),
              HasSubstr(":6:14: scenarios.a: scene: /dev/zero: not a regular file (a character device)"));
  // Case: a file a mesh refers to (an OBJ's material library): assimp would
  // open a FIFO and wait on it.
  fifo("materials.mtl");
  const fs::path obj = write("tri.obj", "mtllib materials.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_THAT(errorOf([&] { readMeshFile(obj); }),
              AllOf(HasSubstr(obj.string() + ": refers to "), HasSubstr("materials.mtl: not a regular file (a FIFO)")));
}

TEST_F(FileLimitsTest, ASymbolicLinkToARegularFileIsFollowed) {
  fs::create_symlink(sourceDir() / "terrains/flat.yaml", dir() / "link.yaml");
  EXPECT_EQ(loadTerrain(dir() / "link.yaml").pieceCount(), 1u);
  fs::create_symlink(sourceDir() / "terrains/samples/rock.obj", dir() / "rock.obj");
  EXPECT_FALSE(readMeshFile(dir() / "rock.obj").parts.empty());
  // A link to a device is the device.
  fs::create_symlink("/dev/zero", dir() / "zero.yaml");
  EXPECT_THAT(errorOf([&] { loadTerrain(dir() / "zero.yaml"); }), HasSubstr("not a regular file (a character device)"));
}

TEST_F(FileLimitsTest, FilesOverTheCapAreRefusedWithTheirSizeAndTheCap) {
  // Case: a description file one byte over 64 MiB, each kind.
  const fs::path big = sparse("big.yaml", kMaxDescriptionFileBytes + 1);
  for (const Loader& loader : loaders()) {
    if (std::string(loader.name).starts_with("heightfield") || std::string(loader.name) == "mesh") continue;
    EXPECT_THAT(errorOf([&] { loader.load(big); }),
                HasSubstr(big.string() + ": 67108865 bytes, more than the 67108864 bytes (64 MiB) WTC "
                                         "reads from a description file (YAML)"))
        << loader.name;
  }
  // Case: data files one byte over 4 GiB.
  for (const char* name : {"big.csv", "big.pgm", "big.obj", "big.off"}) {
    const fs::path data = sparse(name, kMaxDataFileBytes + 1);
    const std::string expected =
        data.string() + ": 4294967297 bytes, more than the 4294967296 bytes (4096 MiB) WTC reads from a data file";
    if (data.extension() == ".csv" || data.extension() == ".pgm") {
      EXPECT_THAT(errorOf([&] { readHeightfieldFile(data, {}); }), HasSubstr(expected)) << name;
    } else {
      EXPECT_THAT(errorOf([&] { readMeshFile(data); }), HasSubstr(expected)) << name;
    }
    fs::remove(data);
  }
}

}  // namespace
}  // namespace wtc::io
