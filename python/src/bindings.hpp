#pragma once
// The Python module wtc._wtc (pybind11): each part of the API binds itself
// from its own file, in the order module.cpp calls them (errors first, so
// that the others' exceptions translate). docs/python.md is the reference.
#include <pybind11/pybind11.h>

#include <filesystem>
#include <memory>
#include <vector>

#include "wtc/sim/run_summary.hpp"
#include "wtc/sim/scene.hpp"
#include "wtc/sim/scene_file.hpp"
#include "wtc/terrain/terrain.hpp"

namespace wtc::python {

namespace py = pybind11;

/// A scene as load_scene read it, with what it was read from: the file and
/// the overrides, which make a run's settings key (its directory's marker)
/// the same as wtc-sim's for the same command line.
struct LoadedScene {
  sim::Scene scene;
  std::filesystem::path file;            ///< As given (absolute in the marker).
  std::vector<sim::Override> overrides;  ///< In the order given.
};

/// A terrain, shared with the scenes and engines that use it.
struct TerrainHandle {
  std::shared_ptr<const Terrain> terrain;
};

/// Body `b` of `vehicle` as a dict: name, index, parent, mass (kg), pose
/// (4 x 4, the centre-of-mass frame in the vehicle frame V at the
/// reference configuration, m), joint (type, axis), and for a wheel its
/// radius r_f and tread width w (m) and axle (body frame).
py::dict bodyDescription(const vehicle::VehicleDescription& vehicle, int b);

/// A run's summary as a dict (summary.json's figures; docs/python.md).
py::dict summaryDict(const sim::RunSummary& summary);

void bindErrors(py::module_& m);
void bindScenes(py::module_& m);
void bindRuns(py::module_& m);
void bindSimulation(py::module_& m);
void bindTerrain(py::module_& m);
void bindControllers(py::module_& m);
void bindSoil(py::module_& m);

}  // namespace wtc::python
