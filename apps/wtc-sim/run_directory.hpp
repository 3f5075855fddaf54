#pragma once
// wtc-sim's output directory: where a run may write, and what --skip-done
// may do to a directory it finds. Design note:
//
// wtc-sim never removes what it did not write. Each directory it runs in
// carries a marker of its own (kMarker, JSON: the scene file, its name,
// engine and mode, and the settings key: FNV-1a of the scene file's bytes
// and the command line's overrides), written before the first step. With
// --skip-done a directory is
//   - skipped (exit 0) when it holds a run that ended (summary.json says
//     completed or crashed) of the same settings, or of unknown settings
//     when it has no marker (a run made before markers: nothing is removed);
//   - made anew when it holds an unfinished run of the same settings: its
//     marker, and nothing but files a run writes (kRunFiles), which alone
//     are removed;
//   - refused otherwise (any other file, or another run's marker), with
//     nothing removed.
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <span>
#include <sstream>
#include <string>

#include "wtc/base/error.hpp"
#include "io/content_hash.hpp"
#include "wtc/sim/run_summary_file.hpp"
#include "wtc/sim/scene_file.hpp"

namespace wtc::apps {

/// wtc-sim's marker in a directory it runs in.
inline constexpr const char* kMarker = ".wtc-run";

/// Every file a run of wtc-sim writes in its directory: the marker, the
/// summary (and its temporary name: io::writeFileAtomically), the series
/// (sim::Recorder), the replay page (sim::Replay, writeReplayPage) and the
/// figures (plot_run.py).
inline constexpr const char* kRunFiles[] = {kMarker,       "summary.json", "summary.json.tmp",   "bodies.csv",
                                            "drives.csv",  "wheels.csv",   "hitch.csv",          "replay_data.js",
                                            "replay.html", "three.min.js", "OrbitControls.js",   "trajectories.png",
                                            "angles.png",  "efforts.png",  "contact_forces.png", "hitch.png"};

/// The settings a run is made of: 16 hex digits of FNV-1a over the scene
/// file's bytes and each override ("path=value\n", in order). Empty if the
/// file cannot be read (loading it will say why).
inline std::string settingsKey(const std::filesystem::path& scene_file, std::span<const sim::Override> overrides) {
  std::ifstream in(scene_file, std::ios::binary);
  if (!in || !std::filesystem::is_regular_file(scene_file)) return {};
  std::ostringstream bytes;
  bytes << in.rdbuf();
  std::uint64_t h = io::fnv1a(bytes.str());
  for (const sim::Override& o : overrides) h = io::fnv1a(o.path + "=" + o.value + "\n", h);
  return io::hexDigits(h);
}

/// What --skip-done does with a directory.
enum class SkipDone { kRun, kSkip, kRedo };

namespace detail {

inline bool isRunFile(const std::filesystem::directory_entry& e) {
  const std::string name = e.path().filename().string();
  for (const char* f : kRunFiles) {
    if (name == f) return e.is_regular_file() && !e.is_symlink();
  }
  return false;
}

// The marker's settings key, or "" if `dir` has no readable marker.
inline std::string markerKey(const std::filesystem::path& dir) {
  std::ifstream in(dir / kMarker);
  if (!in) return {};
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  return j.is_object() && j.contains("settings") && j["settings"].is_string() ? j["settings"].get<std::string>()
                                                                              : std::string();
}

}  // namespace detail

/// Refuses `--out dir` when it exists and is not a directory.
inline void requireDirectoryOrNothing(const std::string& dir) {
  const std::filesystem::path p(dir);
  if (std::filesystem::exists(p) && !std::filesystem::is_directory(p)) {
    throw InvalidInputError("--out " + dir +
                            (std::filesystem::is_regular_file(p) ? ": is a file, not a directory"
                                                                 : ": exists and is not a directory") +
                            " (give a new or empty directory)");
  }
}

/// What --skip-done does with `dir` for a run of settings `key` (the
/// design note); InvalidInputError naming the directory and what is in the
/// way when it must be refused.
inline SkipDone skipDone(const std::string& dir, const std::string& key) {
  namespace fs = std::filesystem;
  requireDirectoryOrNothing(dir);
  if (!fs::exists(dir) || fs::is_empty(dir)) return SkipDone::kRun;
  const std::string marker = detail::markerKey(dir);
  if (marker.empty()) {
    if (sim::runEnded(dir) && !fs::exists(fs::path(dir) / kMarker)) return SkipDone::kSkip;
    throw InvalidInputError("--out " + dir + ": the directory is not empty and has no " + kMarker +
                            " marker of a wtc-sim run; --skip-done redoes only a run of its own, and removes nothing "
                            "else (choose another directory, or empty this one)");
  }
  if (marker != key) {
    throw InvalidInputError("--out " + dir + ": holds a run of other settings (its " + kMarker + " says " + marker +
                            ", this run's are " + key + "); nothing was removed");
  }
  if (sim::runEnded(dir)) return SkipDone::kSkip;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    if (!detail::isRunFile(e)) {
      throw InvalidInputError("--out " + dir + ": holds an unfinished run and '" + e.path().filename().string() +
                              "', which wtc-sim did not write; nothing was removed (move it, or choose another "
                              "directory)");
    }
  }
  return SkipDone::kRedo;
}

/// Removes the files an unfinished run left in `dir` (skipDone said kRedo:
/// there is nothing else).
inline void removeRunFiles(const std::filesystem::path& dir) {
  for (const std::filesystem::directory_entry& e : std::filesystem::directory_iterator(dir)) {
    if (detail::isRunFile(e)) std::filesystem::remove(e.path());
  }
}

/// Writes the marker of a run of `key` into `dir`.
inline void writeMarker(const std::filesystem::path& dir, const std::string& key, const std::string& scene_file,
                        const std::string& scene, const std::string& engine, const std::string& mode) {
  const nlohmann::json j = {{"program", "wtc-sim"}, {"scene_file", scene_file}, {"scene", scene}, {"engine", engine},
                            {"mode", mode},         {"settings", key}};
  std::ofstream out(dir / kMarker);
  out << j.dump(2) << '\n';
  if (!out) throw InvalidInputError("cannot write " + (dir / kMarker).string());
}

}  // namespace wtc::apps
