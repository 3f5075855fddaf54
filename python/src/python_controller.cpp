#include "python_controller.hpp"

#include <cmath>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "vehicle/controllers/controller_types.hpp"
#include "wtc/base/error.hpp"

namespace wtc::python {
namespace {

// What update's `sensors` argument is: the state of this step, valid for
// the call only (arrays are built when read). Owned by its Python object
// (a controller may keep it); the call's end clears its pointers, and a
// read after it is refused.
struct Sensors {
  const vehicle::VehicleState* state = nullptr;
  const vehicle::VehicleDescription* vehicle = nullptr;
  std::span<const vehicle::DriveCommand> commands;
};

const vehicle::VehicleState& stateOf(const Sensors& s) {
  if (s.state == nullptr) throw InvalidInputError("wtc.Sensors: read outside the update call it was given to");
  return *s.state;
}

const vehicle::VehicleDescription& vehicleOf(const Sensors& s) {
  stateOf(s);
  return *s.vehicle;
}

template <class Get>
py::array_t<double> rows3(const Sensors& s, Get get) {
  const vehicle::VehicleState& state = stateOf(s);
  const auto n = static_cast<py::ssize_t>(state.bodies.size());
  py::array_t<double> a({n, py::ssize_t{3}});
  double* out = a.mutable_data();
  for (py::ssize_t i = 0; i < n; ++i) Eigen::Map<Eigen::Vector3d>(out + 3 * i) = get(state, i);
  return a;
}

class PythonController final : public vehicle::Controller {
 public:
  PythonController(SharedObject object, vehicle::VehicleDescription vehicle)
      : object_(std::move(object)), vehicle_(std::move(vehicle)) {
    py::gil_scoped_acquire gil;
    if (!py::hasattr(*object_, "update")) {
      throw InvalidInputError("Python controller " + py::repr(*object_).cast<std::string>() +
                              " has no update(t, sensors) method");
    }
    update_ = share(object_->attr("update"));
  }

  void update(const vehicle::VehicleState& state, std::span<vehicle::DriveCommand> commands) override {
    py::gil_scoped_acquire gil;
    py::object wrapped = py::cast(Sensors{&state, &vehicle_, commands});
    Sensors& sensors = wrapped.cast<Sensors&>();
    py::object result;
    try {
      result = (*update_)(state.time, wrapped);
    } catch (...) {
      sensors = Sensors{};
      throw;
    }
    // The object may outlive the call (kept by the controller): it must not
    // reach this step's state after it.
    sensors = Sensors{};
    if (!result.is_none()) apply(result, commands);
  }

  // summary() -> {name: number} or None. What it returns is checked whole
  // before any field is taken: a refusal (InvalidInputError, which runScene
  // turns into a warning) names every value that is not a finite number, and
  // the run's own figures and outputs are kept.
  void summarize(std::map<std::string, double>& fields) const override {
    py::gil_scoped_acquire gil;
    if (!py::hasattr(*object_, "summary")) return;
    py::object s;
    try {
      s = object_->attr("summary")();
    } catch (py::error_already_set& e) {
      throw InvalidInputError("Python controller: summary() raised " + std::string(e.what()));
    }
    if (s.is_none()) return;
    if (!py::isinstance<py::dict>(s)) {
      throw InvalidInputError("Python controller: summary() returned " + py::repr(s).cast<std::string>() +
                              " (expected a dict {name: number} or None)");
    }
    std::map<std::string, double> taken;
    std::string refused;
    for (const auto& [k, v] : s.cast<py::dict>()) {
      const std::string key = py::str(k);
      // PyNumber_Check: int, float, bool, NumPy scalars; not a str that reads as one.
      const bool number = PyNumber_Check(v.ptr()) == 1 && !py::isinstance<py::str>(v);
      const double x = number ? v.cast<double>() : 0.0;
      if (number && std::isfinite(x)) {
        taken[key] = x;
      } else {
        refused += std::string(refused.empty() ? "" : ", ") + "'" + key + "': " + py::repr(v).cast<std::string>();
      }
    }
    if (!refused.empty()) {
      throw InvalidInputError("Python controller: summary() gave values that are not finite numbers (" + refused +
                              "); its summary is left out");
    }
    fields.insert(taken.begin(), taken.end());
  }

  bool failed() const override { return !failure().empty(); }
  std::string failure() const override {
    py::gil_scoped_acquire gil;
    if (!py::hasattr(*object_, "failure")) return {};
    const py::object f = object_->attr("failure")();
    return f.is_none() ? std::string() : py::str(f).cast<std::string>();
  }

 private:
  int bodyIndex(const py::handle& key) const {
    if (py::isinstance<py::str>(key)) {
      const std::string name = key.cast<std::string>();
      const int b = vehicle_.find(name);
      if (b < 0)
        throw InvalidInputError("Python controller: command for '" + name + "', which is no body of the vehicle");
      return b;
    }
    const int b = key.cast<int>();
    if (b < 0 || b >= static_cast<int>(vehicle_.bodies.size())) {
      throw InvalidInputError("Python controller: command for body " + std::to_string(b) + " of " +
                              std::to_string(vehicle_.bodies.size()));
    }
    return b;
  }

  static vehicle::DriveCommand command(const py::handle& value, const vehicle::DriveCommand& last) {
    if (py::isinstance<py::str>(value)) {
      if (value.cast<std::string>() == "off") return {vehicle::DriveMode::kOff, last.value};
      throw InvalidInputError("Python controller: command '" + value.cast<std::string>() +
                              "' (expected a rate, (\"velocity\" | \"position\", value) or \"off\")");
    }
    if (py::isinstance<py::tuple>(value) || py::isinstance<py::list>(value)) {
      const py::sequence pair = py::reinterpret_borrow<py::sequence>(value);
      if (pair.size() != 2) throw InvalidInputError("Python controller: a command pair is (mode, value)");
      const std::string mode = pair[0].cast<std::string>();
      const double v = pair[1].cast<double>();
      if (mode == "velocity") return {vehicle::DriveMode::kVelocity, v};
      if (mode == "position") return {vehicle::DriveMode::kPosition, v};
      throw InvalidInputError("Python controller: mode '" + mode + "' (expected velocity or position)");
    }
    return {vehicle::DriveMode::kVelocity, value.cast<double>()};
  }

  void apply(const py::object& result, std::span<vehicle::DriveCommand> commands) const {
    if (!py::isinstance<py::dict>(result)) {
      throw InvalidInputError("Python controller: update returned " + py::repr(result).cast<std::string>() +
                              " (expected a dict {body: command} or None)");
    }
    for (const auto& [key, value] : result.cast<py::dict>()) {
      const int b = bodyIndex(key);
      // A body without a drive takes no command: said, not dropped (issue 57 row 10).
      if (!vehicle_.bodies[static_cast<std::size_t>(b)].joint.actuator) {
        throw InvalidInputError("Python controller: command for '" + vehicle_.bodies[static_cast<std::size_t>(b)].name +
                                "', which has no drive (the driven bodies: Scene.drives)");
      }
      commands[static_cast<std::size_t>(b)] = command(value, commands[static_cast<std::size_t>(b)]);
    }
  }

  SharedObject object_, update_;
  vehicle::VehicleDescription vehicle_;
};

// A YAML value as a Python one: numbers, strings, booleans, lists, mappings.
py::object fromYaml(const io::detail::YamlReader& in, const YAML::Node& node, const std::string& what) {
  if (node.IsMap()) {
    py::dict d;
    for (const auto& kv : node) {
      const std::string key = kv.first.as<std::string>();
      d[py::str(key)] = fromYaml(in, kv.second, what + "." + key);
    }
    return d;
  }
  if (node.IsSequence()) {
    py::list l;
    for (std::size_t i = 0; i < node.size(); ++i) l.append(fromYaml(in, node[i], what + "[" + std::to_string(i) + "]"));
    return l;
  }
  if (node.IsNull()) return py::none();
  const std::string text = node.Scalar();
  if (text == "true" || text == "false") return py::bool_(text == "true");
  double number = 0.0;
  if (YAML::convert<double>::decode(node, number)) {
    long long whole = 0;
    if (text.find_first_of(".eE") == std::string::npos && YAML::convert<long long>::decode(node, whole)) {
      return py::int_(whole);
    }
    return py::float_(number);
  }
  return py::str(text);
}

// `controller: {type: python, module: m, class: C, settings: {...}}`.
vehicle::ControllerFactory readPythonController(const io::detail::YamlReader& in, const YAML::Node& node,
                                                const vehicle::VehicleDescription& vehicle) {
  in.checkKeys(node, {"type", "module", "class", "settings"});
  const YAML::Node module_node = in.require(node, "module"), class_node = in.require(node, "class");
  const std::string module_name = in.string(module_node, "module"), class_name = in.string(class_node, "class");
  py::gil_scoped_acquire gil;
  py::dict settings;
  if (const auto s = io::detail::YamlReader::get(node, "settings")) {
    if (!s->IsMap()) in.fail(*s, "settings: expected a mapping (the class's keyword arguments)");
    settings = fromYaml(in, *s, "settings");
  }
  // The scene's own folder first: a controller beside its scene.
  const std::string folder = std::filesystem::absolute(in.path()).parent_path().string();
  py::list path = py::module_::import("sys").attr("path");
  if (!path.contains(folder)) path.insert(0, folder);
  py::object cls;
  try {
    cls = py::module_::import(module_name.c_str()).attr(class_name.c_str());
  } catch (py::error_already_set& e) {
    in.fail(e.matches(PyExc_AttributeError) ? class_node : module_node,
            "cannot use Python controller " + module_name + "." + class_name + ": " + e.what());
  }
  const auto make = [cls = share(cls), settings = share(settings), vehicle] {
    py::gil_scoped_acquire gil;
    py::object controller = (*cls)(**py::reinterpret_borrow<py::dict>(*settings));
    return makePythonController(share(std::move(controller)), vehicle);
  };
  try {
    make();  // its refusal of the settings, at the scene's line
  } catch (py::error_already_set& e) {
    in.fail(node, "Python controller " + module_name + "." + class_name + ": " + e.what());
  } catch (const InvalidInputError& e) {
    in.fail(node, e.what());
  }
  return make;
}

}  // namespace

py::dict bodyDescription(const vehicle::VehicleDescription& vehicle, int b) {
  if (b < 0 || b >= static_cast<int>(vehicle.bodies.size())) {
    throw InvalidInputError("body " + std::to_string(b) + ": vehicle '" + vehicle.name + "' has " +
                            std::to_string(vehicle.bodies.size()) + " bodies");
  }
  const vehicle::Body& body = vehicle.bodies[static_cast<std::size_t>(b)];
  py::array_t<double> pose({py::ssize_t{4}, py::ssize_t{4}});
  auto m = pose.mutable_unchecked<2>();
  const Eigen::Matrix4d own = vehicle::ownFrame(body, body.pose).matrix();
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) m(i, j) = own(i, j);
  }
  static const char* const kJointNames[] = {"revolute", "prismatic", "ball", "fixed"};
  py::dict d;
  d["name"] = body.name;
  d["index"] = b;
  d["parent"] = body.parent;
  d["mass"] = body.mass;
  d["pose"] = pose;
  d["joint"] = kJointNames[static_cast<int>(body.joint.type)];
  d["joint_axis"] = std::array<double, 3>{body.joint.axis.x(), body.joint.axis.y(), body.joint.axis.z()};
  d["driven"] = body.joint.actuator.has_value();
  if (body.wheel) {
    d["radius"] = body.wheel->geometry.free_radius;
    d["width"] = body.wheel->geometry.tread_width;
    const Eigen::Vector3d axle = body.own_axes.transpose() * body.wheel->axle;  // in the body's own axes
    d["axle"] = std::array<double, 3>{axle.x(), axle.y(), axle.z()};
  }
  return d;
}

SharedObject share(py::object object) {
  return SharedObject(new py::object(std::move(object)), [](py::object* o) {
    py::gil_scoped_acquire gil;
    delete o;
  });
}

std::unique_ptr<vehicle::Controller> makePythonController(SharedObject controller,
                                                          const vehicle::VehicleDescription& vehicle) {
  return std::make_unique<PythonController>(std::move(controller), vehicle);
}

namespace {

std::shared_ptr<LoadedScene> withController(const LoadedScene& loaded, py::object controller) {
  auto copy = std::make_shared<LoadedScene>(loaded);
  copy->scene.controller_type = "python";
  copy->scene.make_controller = [object = share(std::move(controller)), vehicle = loaded.scene.vehicle] {
    return makePythonController(object, vehicle);
  };
  return copy;
}

}  // namespace

void bindControllers(py::module_& m) {
  py::class_<Sensors>(m, "Sensors", "What a controller reads at a step (valid during its update call).")
      .def_property_readonly(
          "time", [](const Sensors& s) { return stateOf(s).time; }, "(s)")
      .def_property_readonly("bodies",
                             [](const Sensors& s) {
                               std::vector<std::string> names;
                               for (const auto& b : vehicleOf(s).bodies) names.push_back(b.name);
                               return names;
                             })
      .def(
          "index",
          [](const Sensors& s, const std::string& name) {
            const int b = vehicleOf(s).find(name);
            if (b < 0) throw InvalidInputError("wtc.Sensors.index: no body '" + name + "'");
            return b;
          },
          py::arg("name"), "A body's index by its name.")
      .def(
          "description",
          [](const Sensors& s, const py::object& body) {
            const int b =
                py::isinstance<py::str>(body) ? vehicleOf(s).find(body.cast<std::string>()) : body.cast<int>();
            if (b < 0)
              throw InvalidInputError("wtc.Sensors.description: no body " + py::repr(body).cast<std::string>());
            return bodyDescription(vehicleOf(s), b);
          },
          py::arg("body"), "The body's description (name or index): wtc.Scene.body's dict.")
      .def_property_readonly(
          "position",
          [](const Sensors& s) {
            return rows3(s, [](const vehicle::VehicleState& x, py::ssize_t i) -> Eigen::Vector3d {
              return x.bodies[static_cast<std::size_t>(i)].pose.translation();
            });
          },
          "(B, 3) centres of mass (m, world)")
      .def_property_readonly(
          "rotation",
          [](const Sensors& s) {
            const vehicle::VehicleState& x = stateOf(s);
            const vehicle::VehicleDescription& v = vehicleOf(s);
            const auto n = static_cast<py::ssize_t>(x.bodies.size());
            py::array_t<double> a({n, py::ssize_t{3}, py::ssize_t{3}});
            auto r = a.mutable_unchecked<3>();
            for (py::ssize_t i = 0; i < n; ++i) {
              const auto b = static_cast<std::size_t>(i);
              const Eigen::Matrix3d R = vehicle::ownFrame(v.bodies[b], x.bodies[b].pose).linear();
              for (int j = 0; j < 3; ++j)
                for (int k = 0; k < 3; ++k) r(i, j, k) = R(j, k);
            }
            return a;
          },
          "(B, 3, 3) rotations from each body's own axes (a URDF link's as written) to the world")
      .def_property_readonly(
          "linear_velocity",
          [](const Sensors& s) {
            return rows3(s, [](const vehicle::VehicleState& x, py::ssize_t i) -> Eigen::Vector3d {
              return x.bodies[static_cast<std::size_t>(i)].linear_velocity;
            });
          },
          "(B, 3) (m/s, world)")
      .def_property_readonly(
          "angular_velocity",
          [](const Sensors& s) {
            return rows3(s, [](const vehicle::VehicleState& x, py::ssize_t i) -> Eigen::Vector3d {
              return x.bodies[static_cast<std::size_t>(i)].angular_velocity;
            });
          },
          "(B, 3) (rad/s, world)")
      .def_property_readonly(
          "joint_position",
          [](const Sensors& s) {
            const auto& v = stateOf(s).joint_position;
            return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
          },
          "(B,) each body's joint to its parent (rad or m; 0 for roots)")
      .def_property_readonly(
          "joint_rate",
          [](const Sensors& s) {
            const auto& v = stateOf(s).joint_rate;
            return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
          },
          "(B,) (rad/s or m/s)")
      .def_property_readonly(
          "wheel_contacts",
          [](const Sensors& s) {
            const auto& w = stateOf(s).wheels;
            py::array_t<int> a(static_cast<py::ssize_t>(w.size()));
            for (std::size_t i = 0; i < w.size(); ++i) a.mutable_at(static_cast<py::ssize_t>(i)) = w[i].contacts;
            return a;
          },
          "(B,) contacts of each wheel this step (0 for bodies that are not wheels)")
      .def_property_readonly(
          "wheel_force",
          [](const Sensors& s) {
            return rows3(s, [](const vehicle::VehicleState& x, py::ssize_t i) -> Eigen::Vector3d {
              return x.wheels[static_cast<std::size_t>(i)].force;
            });
          },
          "(B, 3) ground force on each wheel (N, world)")
      .def_property_readonly(
          "contact_normal",
          [](const Sensors& s) {
            return rows3(s, [](const vehicle::VehicleState& x, py::ssize_t i) -> Eigen::Vector3d {
              return x.wheels[static_cast<std::size_t>(i)].contact_normal;
            });
          },
          "(B, 3) load-weighted mean contact normal (unit; +z without contact)")
      .def(
          "contact_points",
          [](const Sensors& s, int body) {
            const auto& w = stateOf(s).wheels.at(static_cast<std::size_t>(body));
            const auto n = static_cast<py::ssize_t>(w.points.size());
            py::array_t<double> p({n, py::ssize_t{3}}), nn({n, py::ssize_t{3}}), load(n);
            for (py::ssize_t k = 0; k < n; ++k) {
              const vehicle::SensedContact& c = w.points[static_cast<std::size_t>(k)];
              for (int j = 0; j < 3; ++j) {
                p.mutable_at(k, j) = c.point[j];
                nn.mutable_at(k, j) = c.normal[j];
              }
              load.mutable_at(k) = c.load;
            }
            return py::make_tuple(p, nn, load);
          },
          py::arg("body"), "A wheel's contacts: (points (k, 3) m, normals (k, 3), loads (k,) N)")
      .def_property_readonly(
          "command_values",
          [](const Sensors& s) {
            stateOf(s);
            py::array_t<double> a(static_cast<py::ssize_t>(s.commands.size()));
            for (std::size_t i = 0; i < s.commands.size(); ++i)
              a.mutable_at(static_cast<py::ssize_t>(i)) = s.commands[i].value;
            return a;
          },
          "(B,) the last commands' values (rad/s, m/s, rad or m)");
  m.def("_with_controller", &withController, py::arg("scene"), py::arg("controller"),
        "The scene with its controller replaced by a Python object (update(t, sensors)).");
  if (vehicle::findControllerType("python") == nullptr) vehicle::addControllerType({"python", &readPythonController});
}

}  // namespace wtc::python
