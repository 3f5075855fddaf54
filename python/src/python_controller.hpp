#pragma once
// Controllers written in Python (docs/python.md). Design note:
//
// A Python controller is any object with update(t, sensors) -> commands,
// called every control period (every engine step, as a C++
// vehicle::Controller is) with the same sensors a C++ controller reads
// (vehicle::VehicleState, as wtc.Sensors: arrays per body) and giving the
// same commands (vehicle::DriveCommand per body: a mapping from a body's
// name or index to a rate, or to ("velocity" | "position", value), or to
// "off"; bodies it leaves out keep their last command; None changes
// nothing). Optional: summary() -> {name: number} (added to the run's
// summary fields, units in the names) and failure() -> str or None (a
// run whose controller failed fails, saying why).
//
// The engine steps without the GIL; update takes it for its call and gives
// it back. Python objects held here are released with the GIL taken.
//
// A scene names one so: controller: {type: python, module: my_ctrl,
// class: Climb, settings: {...}}: the type is registered with the
// controller table (vehicle::addControllerType) when wtc is imported, and
// each run makes a fresh instance, class(**settings), with the module
// imported from the scene's folder or sys.path. wtc-sim, which has no
// Python, refuses such a scene and says to run it from Python.
#include <memory>

#include "bindings.hpp"
#include "wtc/vehicle/controller.hpp"

namespace wtc::python {

/// A Python object kept alive from C++ code that may run without the GIL:
/// copied and released with the GIL taken.
using SharedObject = std::shared_ptr<py::object>;
SharedObject share(py::object object);

/// `controller` (an object with update(t, sensors)) as a C++ controller
/// of `vehicle`.
std::unique_ptr<vehicle::Controller> makePythonController(SharedObject controller,
                                                          const vehicle::VehicleDescription& vehicle);

}  // namespace wtc::python
