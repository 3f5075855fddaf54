#!/usr/bin/env python3
"""What a controller written in Python costs per call, against the C++ controller in the same run.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_controller_bench.py [--seconds 2] [--repeats 3]

Two measures, each the best of --repeats, the C++ and Python controllers alternating:
  per call:  Simulation._controller_call_seconds: a fresh controller's update called --calls times on the sensors of
             one step (after --seconds of the run, the C++ controller driving), the GIL released between calls as
             in a run: what a call costs, GIL, wtc.Sensors and the commands' conversion included.
  per step:  the whole run stepped for --seconds (wtc.Simulation, series every 25th step as wtc-sim's 100 Hz), wall
             time per 0.4 ms step, with the C++ controller and with the Python one.
Cases:
  robot_straight (the six-wheel robot, Bullet, force mode): its schedule controller (vehicle::ScheduleController)
    against RobotSchedule below (the same schedule: six wheel rates, four section positions), and NoOp (returns
    None: the call alone).
  towed_path (the tug and towed body on the S-curve, Bullet, force mode): vehicle::PathController against
    examples/python/my_controller.py's PathController (the same law, bit for bit).
docs/python.md quotes the output.
"""
import argparse
import pathlib
import sys
import time

import wtc

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "examples/python"))
from my_controller import PathController, S_CURVE  # noqa: E402


class RobotSchedule:
    """scenes/robot_straight.yaml's schedule: the six wheels ramp from 0 to 4 rad/s over the first second, the
    carriers and sliders hold position 0."""

    WHEELS = ["front_left_wheel", "front_right_wheel", "middle_left_wheel", "middle_right_wheel", "rear_left_wheel",
              "rear_right_wheel"]
    SECTIONS = ["front_carrier", "front_slider", "rear_carrier", "rear_slider"]

    def update(self, t, sensors):
        rate = 4.0 * min(t, 1.0)
        commands = {w: rate for w in self.WHEELS}
        commands.update({s: ("position", 0.0) for s in self.SECTIONS})
        return commands


class NoOp:
    def update(self, t, sensors):
        return None


def seconds_per_step(scene, controller, steps):
    sim = wtc.Simulation(scene, controller=controller, record_every=25)
    start = time.perf_counter()
    sim.step(steps)
    return (time.perf_counter() - start) / steps


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--seconds", type=float, default=2.0, help="simulated time of each run (s)")
    parser.add_argument("--calls", type=int, default=20000, help="calls timed per controller")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    cases = {
        "robot_straight": (wtc.load_scene(ROOT / "scenes/robot_straight.yaml"),
                           {"C++": lambda: None, "Python": RobotSchedule, "no-op": NoOp}),
        "towed_path": (wtc.load_scene(ROOT / "scenes/towed_path.yaml"),
                       {"C++": lambda: None, "Python": lambda: PathController(**S_CURVE)}),
    }
    for name, (scene, controllers) in cases.items():
        steps = round(args.seconds / scene.dt)
        at = wtc.Simulation(scene)
        at.step(steps)
        call = {k: float("inf") for k in controllers}
        step = {k: float("inf") for k in controllers if k != "no-op"}
        for _ in range(args.repeats):
            for label, make in controllers.items():
                call[label] = min(call[label], at._controller_call_seconds(make(), args.calls))
                if label in step:
                    step[label] = min(step[label], seconds_per_step(scene, make(), steps))
        print(f"{name} ({scene.engine}, {scene.mode}, dt {scene.dt * 1e3:g} ms; best of {args.repeats}):")
        for label in controllers:
            line = f"  {label:7s} {call[label] * 1e6:7.2f} us per call ({call[label] / call['C++']:.0f} x C++'s)"
            if label in step:
                line += (f"; run {step[label] * 1e6:.1f} us per step ({step[label] / step['C++']:.3f} x C++'s), "
                         f"{step[label] / scene.dt:.1%} of real time")
            print(line)


if __name__ == "__main__":
    main()
