#pragma once
// An accuracy study's plan (wtc::study): every distinct run it makes. A
// study file (bench/accuracy_study.yaml; format in docs/accuracy-study.md)
// names scenarios (a scene each), one reference setting and sweeps of
// settings; wtc::study::loadStudyPlan expands it. Each run is a scene file and
// its overrides (as `wtc-sim --set`), keyed by a hash of both, so the same
// settings always land in the same directory and a finished run is never
// made twice.
#include <filesystem>
#include <string>
#include <vector>

#include "wtc/sim/scene_file.hpp"

namespace wtc::study {

struct PlannedRun {
  std::string scenario;                 ///< The study's name for the scene.
  std::filesystem::path scene_file;     ///< Absolute.
  std::vector<sim::Override> overrides;  ///< engine, mode and dt always; then the scenario's and the sweep's.
  /// Where each override was set, parallel to `overrides`: "<study
  /// file>:<line>:<col>: <key>" (sweeps.step.dt, base.engine, ...).
  std::vector<std::string> origins;
  std::string sweep;       ///< The first sweep that asked for it ("reference" for the reference).
  std::string label;       ///< "bullet force 0.4 ms", then any other setting ("effects=coulomb").
  std::string key;         ///< <scenario>-<16 hex digits of FNV-1a over the scene file and the overrides>.
  bool reference = false;  ///< The run every other run of the scenario is compared with.
};

struct StudyPlan {
  std::string name;
  std::filesystem::path source;        ///< The study file.
  std::vector<std::string> scenarios;  ///< In the file's order.
  std::vector<PlannedRun> runs;        ///< Distinct keys; per scenario its reference first.
};

}  // namespace wtc::study
