// wtc.soils and wtc.wheel_on_soil: the shipped soils and the wheel-soil
// steady state (docs/soft-soil.md), for sweeps written in Python.
#include <pybind11/stl.h>

#include <string>

#include "bindings.hpp"
#include "wtc/base/error.hpp"
#include "wtc/tyre/wheel_soil.hpp"

namespace wtc::python {
namespace {

Soil shipped(const std::string& name) {
  const std::optional<Soil> soil = namedSoil(name);
  if (!soil) {
    std::string known;
    for (const std::string& n : soilNames()) known += (known.empty() ? "" : ", ") + n;
    throw InvalidInputError("wtc.wheel_on_soil: unknown soil '" + name + "' (shipped: " + known + ")");
  }
  return *soil;
}

// A name, or a dict of fields over {"base": name} (or over a default soil).
Soil soilOf(const py::object& given) {
  if (py::isinstance<py::str>(given)) return shipped(given.cast<std::string>());
  if (!py::isinstance<py::dict>(given)) {
    throw InvalidInputError("wtc.wheel_on_soil: soil must be a shipped soil's name or a dict of its fields");
  }
  const py::dict fields = given.cast<py::dict>();
  Soil soil = fields.contains("base") ? shipped(fields["base"].cast<std::string>()) : Soil{.name = "custom"};
  for (const auto& [key, value] : fields) {
    const std::string name = key.cast<std::string>();
    if (name == "base") continue;
    if (name == "name") {
      soil.name = value.cast<std::string>();
      continue;
    }
    bool known = false;
    for (const SoilField& f : soilFields()) {
      if (name == f.name) {
        soil.*f.member = value.cast<double>();
        known = true;
      }
    }
    if (!known) throw InvalidInputError("wtc.wheel_on_soil: unknown soil field '" + name + "'");
  }
  validate(soil, "wtc.wheel_on_soil");
  return soil;
}

py::dict fieldsOf(const Soil& soil) {
  py::dict d;
  d["name"] = soil.name;
  for (const SoilField& f : soilFields()) d[f.name] = soil.*f.member;
  return d;
}

py::dict soils() {
  py::dict all;
  for (const std::string& name : soilNames()) all[name.c_str()] = fieldsOf(*namedSoil(name));
  return all;
}

py::dict wheelOnSoil(const py::object& soil_given, double radius, double width, double load, double slip,
                     double slip_angle) {
  const Soil soil = soilOf(soil_given);
  if (!(radius > 0.0) || !(width > 0.0)) {
    throw InvalidInputError("wtc.wheel_on_soil: radius = " + formatNumber(radius) + " and width = " +
                            formatNumber(width) + " must be > 0 (m)");
  }
  if (!(slip >= -1.0 && slip <= 1.0)) {
    throw InvalidInputError("wtc.wheel_on_soil: slip = " + formatNumber(slip) + " must be in [-1, 1]");
  }
  const SoilSteadyState s = steadyWheelOnSoil(soil, radius, width, load, slip, slip_angle);
  py::dict d;
  d["sinkage"] = s.sinkage;
  d["normal"] = s.forces.normal;
  d["drawbar_pull"] = s.forces.drawbar_pull;
  d["torque"] = s.forces.torque;
  d["lateral"] = s.forces.lateral;
  d["bulldozing"] = s.forces.bulldozing;
  d["entry_angle"] = s.forces.entry_angle;
  d["exit_angle"] = s.forces.exit_angle;
  d["max_stress_angle"] = s.forces.max_stress_angle;
  return d;
}

}  // namespace

void bindSoil(py::module_& m) {
  m.def("soils", &soils, "The shipped soils: {name: {field: value}} (units in docs/soft-soil.md).");
  m.def("wheel_on_soil", &wheelOnSoil, py::arg("soil"), py::arg("radius"), py::arg("width"), py::arg("load"),
        py::arg("slip"), py::arg("slip_angle") = 0.0,
        "The steady state of a rigid wheel on a soil (a shipped soil's name, or a dict of fields over 'base'): "
        "sinkage (m), normal, drawbar_pull, lateral, bulldozing (N), torque (N m), the arc's angles (rad).");
}

}  // namespace wtc::python
