#pragma once
// The CSV time series of a run (wtc::sim), written as it goes, whole rows
// at a time, so an interrupted run leaves valid files up to its last write
// (at most a quarter of a second old). One file per kind of signal, one row
// per recorded instant, SI units named in the headers:
//   bodies.csv  t, then per body: x y z qw qx qy qz vx vy vz wx wy wz
//   drives.csv  t, then per drive: position rate command target_rate effort saturated
//   wheels.csv  t, then per wheel: contacts fx fy fz max_slip
//   hitch.csv   t dx dy dz px py pz   (the towed system only)
//   drawbar.csv t pull extension point_speed   (a scene with a drawbar only)
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "wtc/sim/run.hpp"

namespace wtc::sim {

namespace detail {
/// A CSV file written whole rows at a time. Numbers come out as an ostream
/// of precision 9 writes them (printf's %.9g: formatGeneral9, the same bytes
/// as std::to_chars with that precision), without the stream. Rows are held in
/// memory and go out in one write every 64 KiB or quarter second, and at
/// flush(): a killed process leaves whole rows up to its last write.
class CsvFile {
 public:
  CsvFile() = default;
  CsvFile(const CsvFile&) = delete;
  CsvFile& operator=(const CsvFile&) = delete;
  /// Writes the rows still held: a run that ends by an exception keeps them.
  ~CsvFile() { flush(); }
  void open(const std::filesystem::path& path);
  bool isOpen() const { return file_ != nullptr; }
  CsvFile& operator<<(double value);
  CsvFile& operator<<(std::size_t value);
  CsvFile& operator<<(int value);
  CsvFile& operator<<(char c) {
    row_.push_back(c);
    return *this;
  }
  CsvFile& operator<<(std::string_view text) {
    row_.append(text);
    return *this;
  }
  void endRow();
  /// Writes the rows held (a no-op for a file never opened).
  void flush();

 private:
  struct Close {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::unique_ptr<std::FILE, Close> file_;
  std::string row_;
  std::chrono::steady_clock::time_point last_write_{};
};
}  // namespace detail

class Recorder {
 public:
  /// Creates the files in `dir` (which must exist). Throws
  /// InvalidInputError naming a file it cannot open.
  Recorder(const std::filesystem::path& dir, const Run& run);
  /// Appends one row per file for the run's current state.
  void record(const Run& run);
  /// Writes every row recorded so far (SceneRun::advance does at its end).
  void flush();

 private:
  detail::CsvFile bodies_, drives_, wheels_, hitch_, drawbar_;
  std::vector<int> actuated_, wheel_bodies_;
};

}  // namespace wtc::sim
