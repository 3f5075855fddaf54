// wtc.load_scene and wtc.Scene: a scene file read with overrides, as
// wtc-sim reads it (sim::loadScene; its errors are wtc.InvalidInputError
// with the file, line, column and key).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "wtc/base/error.hpp"
#include "wtc/sim/engine.hpp"
#include "wtc/sim/engine_table.hpp"

namespace wtc::python {
namespace {

std::shared_ptr<LoadedScene> loadScene(const std::filesystem::path& path,
                                       const std::vector<std::pair<std::string, std::string>>& overrides) {
  auto loaded = std::make_shared<LoadedScene>();
  loaded->file = path;
  for (const auto& [key, value] : overrides) loaded->overrides.push_back({key, value});
  loaded->scene = sim::loadScene(path, loaded->overrides, sim::requireEngine);
  return loaded;
}

std::vector<std::string> bodyNames(const LoadedScene& s, const std::vector<int>& indices) {
  std::vector<std::string> names;
  for (const int i : indices) names.push_back(s.scene.vehicle.bodies[i].name);
  return names;
}

}  // namespace

void bindScenes(py::module_& m) {
  py::class_<LoadedScene, std::shared_ptr<LoadedScene>>(m, "Scene",
                                                        "A scene file as read, with its overrides (wtc.load_scene).")
      .def_property_readonly("name", [](const LoadedScene& s) { return s.scene.name; })
      .def_property_readonly("description", [](const LoadedScene& s) { return s.scene.description; })
      .def_property_readonly("file", [](const LoadedScene& s) { return s.file; })
      .def_property_readonly("overrides",
                             [](const LoadedScene& s) {
                               std::vector<std::pair<std::string, std::string>> o;
                               for (const sim::Override& x : s.overrides) o.emplace_back(x.path, x.value);
                               return o;
                             })
      .def_property_readonly("engine", [](const LoadedScene& s) { return s.scene.engine.engine; })
      .def_property_readonly("mode", [](const LoadedScene& s) { return std::string(sim::modeName(s.scene.engine)); })
      .def_property_readonly(
          "dt", [](const LoadedScene& s) { return s.scene.engine.step_seconds; }, "step (s)")
      .def_property_readonly(
          "duration", [](const LoadedScene& s) { return s.scene.duration_seconds; }, "simulated time (s)")
      .def_property_readonly("parameters", [](const LoadedScene& s) { return s.scene.parameters; })
      .def_property_readonly("controller_type", [](const LoadedScene& s) { return s.scene.controller_type; })
      .def_property_readonly("bodies",
                             [](const LoadedScene& s) {
                               std::vector<std::string> names;
                               for (const auto& b : s.scene.vehicle.bodies) names.push_back(b.name);
                               return names;
                             })
      .def_property_readonly("wheels", [](const LoadedScene& s) { return bodyNames(s, s.scene.vehicle.wheels()); })
      .def_property_readonly("drives", [](const LoadedScene& s) { return bodyNames(s, s.scene.vehicle.actuated()); })
      .def_property_readonly("terrain", [](const LoadedScene& s) { return TerrainHandle{s.scene.terrain}; })
      .def(
          "body",
          [](const LoadedScene& s, const std::string& name) {
            const int b = s.scene.vehicle.find(name);
            if (b < 0)
              throw InvalidInputError("wtc.Scene.body: vehicle '" + s.scene.vehicle.name + "' has no body '" + name +
                                      "'");
            return bodyDescription(s.scene.vehicle, b);
          },
          py::arg("name"),
          "The body's description: name, index, parent, mass (kg), pose (4 x 4 in the vehicle frame, m), joint, "
          "and a wheel's radius, width (m) and axle.")
      .def("__repr__", [](const LoadedScene& s) {
        return "<wtc.Scene " + s.scene.name + ": " + s.scene.engine.engine + ", " +
               std::string(sim::modeName(s.scene.engine)) + ", dt " + formatNumber(s.scene.engine.step_seconds) +
               " s, " + formatNumber(s.scene.duration_seconds) + " s>";
      });
  m.def("_load_scene", &loadScene, py::arg("path"), py::arg("overrides"),
        "The scene file at `path` with overrides [(key.path, YAML text)], in order (wtc.load_scene).");
}

}  // namespace wtc::python
