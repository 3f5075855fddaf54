#pragma once
// The CSV time series of a run (wtc::sim), written as it goes: a row is
// flushed as soon as it is complete, so an interrupted run leaves valid
// files up to its last row. One file per kind of signal, one row per
// recorded instant, SI units named in the headers:
//   bodies.csv  t, then per body: x y z qw qx qy qz vx vy vz wx wy wz
//   drives.csv  t, then per drive: position rate command target_rate effort saturated
//   wheels.csv  t, then per wheel: contacts fx fy fz max_slip
//   hitch.csv   t dx dy dz px py pz   (the towed system only)
//   drawbar.csv t pull extension point_speed   (a scene with a drawbar only)
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>
#include <vector>

#include "wtc/sim/run.hpp"

namespace wtc::sim {

namespace detail {
/// A CSV file written a whole row at a time: the row is composed in memory
/// and goes out in one write, so a killed process leaves whole rows only.
class CsvFile {
 public:
  void open(const std::filesystem::path& path);
  bool isOpen() const { return file_ != nullptr; }
  template <typename T>
  CsvFile& operator<<(const T& value) {
    row_ << value;
    return *this;
  }
  void endRow();

 private:
  struct Close {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::unique_ptr<std::FILE, Close> file_;
  std::ostringstream row_;
};
}  // namespace detail

class Recorder {
 public:
  /// Creates the files in `dir` (which must exist). Throws
  /// InvalidInputError naming a file it cannot open.
  Recorder(const std::filesystem::path& dir, const Run& run);
  /// Appends one row per file for the run's current state.
  void record(const Run& run);

 private:
  detail::CsvFile bodies_, drives_, wheels_, hitch_, drawbar_;
  std::vector<int> actuated_, wheel_bodies_;
};

}  // namespace wtc::sim
