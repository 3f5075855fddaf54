#pragma once
// A fresh scratch directory per test, under GoogleTest's TempDir(), for the
// broken files the tests write.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace wtc::io::testing {

class TempDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::path(::testing::TempDir()) /
           (std::string("wtc_io_") + info->test_suite_name() + "_" + info->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  /// Writes `bytes` to dir/name and returns the path.
  std::filesystem::path write(const std::string& name, const std::string& bytes) const {
    const std::filesystem::path path = dir_ / name;
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }
  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path dir_;
};

/// The message of the InvalidInputError `f` throws, or "(no error)".
template <typename F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

/// The repository's directories (WTC_SOURCE_DIR is a compile definition).
inline std::filesystem::path sourceDir() { return WTC_SOURCE_DIR; }
inline std::filesystem::path samplesDir() { return sourceDir() / "terrains" / "samples"; }

}  // namespace wtc::io::testing
