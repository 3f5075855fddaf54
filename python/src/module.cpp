// wtc._wtc: the compiled half of the Python package wtc (python/wtc/ is the
// other half, and what users import).
#include "bindings.hpp"

PYBIND11_MODULE(_wtc, m) {
  m.doc() = "WTC's C++ core, bound with pybind11 (import wtc, not wtc._wtc; docs/python.md)";
  m.attr("__version__") = WTC_VERSION;  // the project's (CMakeLists.txt), as wtc-sim --version says
  wtc::python::bindErrors(m);
  wtc::python::bindScenes(m);
  wtc::python::bindTerrain(m);
  wtc::python::bindControllers(m);
  wtc::python::bindRuns(m);
  wtc::python::bindSimulation(m);
  wtc::python::bindSoil(m);
}
