// wtc.Simulation: a scene stepped from Python (sim::Run, as runScene steps
// it), its series kept in C++ and handed over as NumPy arrays.
//
// Each recorded step appends its numbers to flat buffers (no Python object
// per step); series() copies them once into arrays shaped (steps, ...).
// The engine steps without the GIL; Ctrl-C is looked at between steps
// (SignalWatch) and raises KeyboardInterrupt after the step it came in.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <Eigen/Geometry>
#include <atomic>
#include <chrono>

#include "bindings.hpp"
#include "python_controller.hpp"
#include "signal_watch.hpp"
#include "wtc/base/error.hpp"
#include "wtc/sim/engine_table.hpp"
#include "wtc/sim/run.hpp"
#include "wtc/sim/scene_run.hpp"

namespace wtc::python {
namespace {

// Numbers per body, per wheel and per drive in a recorded row.
constexpr int kBodyColumns = 13;  // x y z (m), qw qx qy qz, vx vy vz (m/s), wx wy wz (rad/s)
constexpr int kWheelColumns = 4;  // contacts, Fx Fy Fz (N)

class Simulation final : private sim::RunObserver {
 public:
  explicit Simulation(std::shared_ptr<LoadedScene> loaded, int record_every)
      : loaded_(std::move(loaded)),
        engine_(sim::makeEngine(scene().engine, *scene().terrain, scene().vehicle, scene().placement)),
        wheels_(scene().vehicle.wheels()),
        drives_(scene().vehicle.actuated()),
        every_(record_every),
        watch_(stop_) {
    if (record_every < 1) {
      throw InvalidInputError("wtc.Simulation: record_every = " + std::to_string(record_every) + " must be >= 1");
    }
    sim::RunOptions options;
    options.stop = &stop_;
    options.observer = this;
    scene_run_ = std::make_unique<sim::SceneRun>(scene(), *engine_, options);
  }

  // Steps n times (GIL released) as runScene does, recording every
  // every_-th step; stops at the scene's duration or a non-finite or
  // diverged state. Returns the steps taken.
  std::uint64_t step(std::uint64_t n) {
    stop_ = false;
    std::uint64_t done = 0;
    {
      py::gil_scoped_release nogil;
      done = scene_run_->advance(n);
    }
    watch_.raiseIfSignalled();
    return done;
  }

  // The benchmark's measure (bench/python_controller_bench.py): seconds
  // per call of a fresh controller's update on this step's sensors, `n`
  // calls, the GIL released between them as in a run. `controller`: a
  // Python one, or None for the scene's own.
  double controllerCallSeconds(const py::object& controller, int n) const {
    std::unique_ptr<vehicle::Controller> c =
        controller.is_none() ? scene().make_controller() : makePythonController(share(controller), scene().vehicle);
    if (!c) throw InvalidInputError("wtc.Simulation: the scene has no controller to time");
    const sim::Run& r = run();
    std::vector<vehicle::DriveCommand> commands(r.commands().begin(), r.commands().end());
    py::gil_scoped_release nogil;
    c->update(r.state(), commands);  // a first call (a controller may read its geometry once)
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < n; ++i) c->update(r.state(), commands);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / std::max(n, 1);
  }

  const sim::Scene& scene() const { return loaded_->scene; }
  const sim::Run& run() const { return scene_run_->run(); }
  bool ended() const { return scene_run_->ended(); }

  py::dict series() const {
    const auto rows = static_cast<py::ssize_t>(time_.size());
    const auto bodies = static_cast<py::ssize_t>(scene().vehicle.bodies.size());
    const auto wheels = static_cast<py::ssize_t>(wheels_.size());
    const auto drives = static_cast<py::ssize_t>(drives_.size());
    py::array_t<double> body({rows, bodies, static_cast<py::ssize_t>(kBodyColumns)}, body_.data());
    py::array_t<double> wheel({rows, wheels, static_cast<py::ssize_t>(kWheelColumns)}, wheel_.data());
    py::dict d;
    d["time"] = py::array_t<double>(rows, time_.data());
    d["position"] = body[py::make_tuple(py::ellipsis(), py::slice(0, 3, 1))];
    d["quaternion"] = body[py::make_tuple(py::ellipsis(), py::slice(3, 7, 1))];
    d["linear_velocity"] = body[py::make_tuple(py::ellipsis(), py::slice(7, 10, 1))];
    d["angular_velocity"] = body[py::make_tuple(py::ellipsis(), py::slice(10, 13, 1))];
    d["joint_position"] = py::array_t<double>({rows, bodies}, joint_position_.data());
    d["joint_rate"] = py::array_t<double>({rows, bodies}, joint_rate_.data());
    d["wheel_contacts"] = wheel[py::make_tuple(py::ellipsis(), 0)];
    d["wheel_force"] = wheel[py::make_tuple(py::ellipsis(), py::slice(1, 4, 1))];
    d["drive_effort"] = py::array_t<double>({rows, drives}, drive_effort_.data());
    d["drive_command"] = py::array_t<double>({rows, drives}, drive_command_.data());
    return d;
  }

  // The run's summary as wtc.run gives it (without the outputs); before
  // the scene's end, that of a run interrupted there.
  py::dict summary() const { return summaryDict(scene_run_->summary()); }

 private:
  // After each step (and at the start): a row every every_-th step, and a
  // look at Python's signals.
  void observe(const sim::Run& run) override {
    if (run.steps() % static_cast<std::uint64_t>(every_) == 0) record(run);
    watch_.observe(run);
  }

  void record(const sim::Run& run) {
    const vehicle::VehicleState& s = run.state();
    time_.push_back(s.time);
    for (std::size_t b = 0; b < s.bodies.size(); ++b) {
      const vehicle::BodyKinematics& k = s.bodies[b];
      const Eigen::Quaterniond q(vehicle::ownFrame(run.engine().vehicle().bodies[b], k.pose).linear());
      const Eigen::Vector3d p = k.pose.translation();
      body_.insert(body_.end(),
                   {p.x(), p.y(), p.z(), q.w(), q.x(), q.y(), q.z(), k.linear_velocity.x(), k.linear_velocity.y(),
                    k.linear_velocity.z(), k.angular_velocity.x(), k.angular_velocity.y(), k.angular_velocity.z()});
      joint_position_.push_back(s.joint_position[b]);
      joint_rate_.push_back(s.joint_rate[b]);
    }
    for (const int w : wheels_) {
      const WheelForces& f = run.wheelForces(w);
      wheel_.insert(wheel_.end(), {static_cast<double>(f.contacts.size()), f.force.x(), f.force.y(), f.force.z()});
    }
    for (const int b : drives_) {
      drive_effort_.push_back(run.drives()[b].last_effort);
      drive_command_.push_back(run.commands()[b].value);
    }
  }

  std::shared_ptr<LoadedScene> loaded_;  // holds the terrain the engine uses
  std::unique_ptr<sim::Engine> engine_;
  std::vector<int> wheels_, drives_;
  int every_;
  std::atomic<bool> stop_{false};
  SignalWatch watch_;
  std::unique_ptr<sim::SceneRun> scene_run_;  // last: made in the constructor's body, with this as its observer
  std::vector<double> time_, body_, joint_position_, joint_rate_, wheel_, drive_effort_, drive_command_;
};

// The current state as arrays: one row per body (or wheel, or drive).
py::dict state(const Simulation& sim) {
  const vehicle::VehicleState& s = sim.run().state();
  const auto bodies = static_cast<py::ssize_t>(s.bodies.size());
  py::array_t<double> position({bodies, py::ssize_t{3}}), quaternion({bodies, py::ssize_t{4}}),
      linear({bodies, py::ssize_t{3}}), angular({bodies, py::ssize_t{3}});
  auto p = position.mutable_unchecked<2>();
  auto q = quaternion.mutable_unchecked<2>();
  auto v = linear.mutable_unchecked<2>();
  auto w = angular.mutable_unchecked<2>();
  for (py::ssize_t b = 0; b < bodies; ++b) {
    const vehicle::BodyKinematics& k = s.bodies[static_cast<std::size_t>(b)];
    const Eigen::Quaterniond r(vehicle::ownFrame(sim.run().engine().vehicle().bodies[b], k.pose).linear());
    for (int i = 0; i < 3; ++i) {
      p(b, i) = k.pose.translation()[i];
      v(b, i) = k.linear_velocity[i];
      w(b, i) = k.angular_velocity[i];
    }
    q(b, 0) = r.w();
    q(b, 1) = r.x();
    q(b, 2) = r.y();
    q(b, 3) = r.z();
  }
  py::dict d;
  d["time"] = s.time;
  d["position"] = position;
  d["quaternion"] = quaternion;
  d["linear_velocity"] = linear;
  d["angular_velocity"] = angular;
  d["joint_position"] = py::array_t<double>(bodies, s.joint_position.data());
  d["joint_rate"] = py::array_t<double>(bodies, s.joint_rate.data());
  return d;
}

}  // namespace

void bindSimulation(py::module_& m) {
  py::class_<Simulation>(m, "Simulation", "A scene stepped from Python (docs/python.md).")
      .def(py::init<std::shared_ptr<LoadedScene>, int>(), py::arg("scene"), py::arg("record_every") = 1,
           "The scene's engine, vehicle and controller, before the first step; records every record_every-th step.")
      .def("step", &Simulation::step, py::arg("n") = 1, "Steps n times; returns the steps taken.")
      .def_property_readonly(
          "time", [](const Simulation& s) { return s.run().time(); }, "simulated time (s)")
      .def_property_readonly("steps", [](const Simulation& s) { return s.run().steps(); })
      .def_property_readonly("ended", &Simulation::ended,
                             "True at the scene's duration or after a non-finite or diverged state.")
      .def_property_readonly("bodies",
                             [](const Simulation& s) {
                               std::vector<std::string> names;
                               for (const auto& b : s.scene().vehicle.bodies) names.push_back(b.name);
                               return names;
                             })
      .def("state", &state, "The state after the last step: arrays per body.")
      .def(
          "wheel_forces",
          [](const Simulation& s) {
            const std::vector<int> wheels = s.scene().vehicle.wheels();
            py::array_t<double> force({static_cast<py::ssize_t>(wheels.size()), py::ssize_t{3}});
            py::array_t<double> torque({static_cast<py::ssize_t>(wheels.size()), py::ssize_t{3}});
            py::array_t<int> contacts(static_cast<py::ssize_t>(wheels.size()));
            auto f = force.mutable_unchecked<2>();
            auto t = torque.mutable_unchecked<2>();
            auto c = contacts.mutable_unchecked<1>();
            for (std::size_t k = 0; k < wheels.size(); ++k) {
              const WheelForces& w = s.run().wheelForces(wheels[k]);
              const auto i = static_cast<py::ssize_t>(k);
              for (int j = 0; j < 3; ++j) {
                f(i, j) = w.force[j];
                t(i, j) = w.torque[j];
              }
              c(i) = static_cast<int>(w.contacts.size());
            }
            py::dict d;
            d["force"] = force;
            d["torque"] = torque;
            d["contacts"] = contacts;
            return d;
          },
          "The ground's force (N) and torque about the centre (N m) on each wheel, and its contacts, last step.")
      .def(
          "drive_efforts",
          [](const Simulation& s) {
            const std::vector<int> drives = s.scene().vehicle.actuated();
            py::array_t<double> effort(static_cast<py::ssize_t>(drives.size()));
            auto e = effort.mutable_unchecked<1>();
            for (std::size_t k = 0; k < drives.size(); ++k) {
              e(static_cast<py::ssize_t>(k)) = s.run().drives()[drives[k]].last_effort;
            }
            return effort;
          },
          "Each drive's effort in the last step (N m or N), in the order of Scene.drives.")
      .def("_controller_call_seconds", &Simulation::controllerCallSeconds, py::arg("controller"), py::arg("n"),
           "Seconds per call of a fresh controller's update on this step's sensors (None: the scene's).")
      .def("series", &Simulation::series, "The recorded series, arrays shaped (rows, ...).")
      .def("summary", &Simulation::summary,
           "The run's summary as wtc.run returns it (without out); before the scene's end, an interrupted run's.");
}

}  // namespace wtc::python
