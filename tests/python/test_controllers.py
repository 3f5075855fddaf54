"""Controllers written in Python: the shipped path controller rewritten in Python (examples/python/my_controller.py)
drives the towed run the C++ one drives, to 1e-9; a scene may name a Python controller; its errors are said."""
import json
import subprocess
import sys

import numpy as np
import pytest

import wtc

DURATION = 3.0  # s: 7500 steps of 0.4 ms, through the S-curve's first bend
TOLERANCE = 1e-9  # m, m/s, rad/s, N


@pytest.fixture
def my_controller(source_dir):
    sys.path.insert(0, str(source_dir / "examples/python"))
    import my_controller
    yield my_controller
    sys.path.remove(str(source_dir / "examples/python"))


def run_series(scene, controller=None):
    sim = wtc.Simulation(scene, controller=controller)
    assert sim.step(round(DURATION / scene.dt)) == round(DURATION / scene.dt)
    return sim.series()


@pytest.mark.parametrize("engine", ["bullet", "ode"])
def test_a_python_path_controller_drives_the_towed_run_of_the_cpp_one(source_dir, my_controller, engine):
    scene = wtc.load_scene(source_dir / "scenes/towed_path.yaml", engine=engine, duration=DURATION)
    assert scene.controller_type == "path"
    cpp = run_series(scene)
    python = run_series(scene, my_controller.PathController(**my_controller.S_CURVE))
    for key in ["position", "quaternion", "linear_velocity", "angular_velocity", "joint_rate", "wheel_force",
                "drive_command", "drive_effort"]:
        np.testing.assert_allclose(python[key], cpp[key], rtol=0, atol=TOLERANCE, err_msg=key)
    # The tug went through the bend: the comparison is of a run that turned.
    assert abs(cpp["position"][-1, 0, 1] - cpp["position"][0, 0, 1]) > 0.01


def test_a_python_controller_reports_its_figures_in_the_summary(source_dir, my_controller, tmp_path):
    scene = wtc.load_scene(source_dir / "scenes/towed_path.yaml", duration=1.0)
    cpp = wtc.run(scene, out=tmp_path / "cpp", progress=False, plots=False, replay=False)
    python = wtc.run(scene, out=tmp_path / "py", progress=False, plots=False, replay=False,
                     controller=my_controller.PathController(**my_controller.S_CURVE))
    for key in ["max_tracking_error_m", "rms_tracking_error_m", "final_tracking_error_m", "distance_m"]:
        assert python[key] == pytest.approx(cpp[key], abs=TOLERANCE), key


def scene_naming(source_dir, tmp_path, controller):
    text = (source_dir / "scenes/towed_path.yaml").read_text()
    start = text.index("controller:\n")
    end = text.index("output:")
    text = text[:start] + controller + text[end:]
    text = text.replace("../terrains/", f"{source_dir}/terrains/").replace("../vehicles/", f"{source_dir}/vehicles/")
    (tmp_path / "my_controller.py").write_text((source_dir / "examples/python/my_controller.py").read_text())
    scene = tmp_path / "towed_python.yaml"
    scene.write_text(text)
    return scene


PYTHON_PATH_CONTROLLER = """controller:
  type: python
  module: my_controller
  class: PathController
  settings: {body: tug, left_drive: tug_left_wheel, right_drive: tug_right_wheel, lead: 1.0, x: [-9, 0.8],
             y: [0, 0, $b2, $b3], gains: [1.0, 1.0], max_tracking_error: 0.5, end_time: 12}
"""


def test_a_scene_names_a_python_controller_and_wtc_sim_refuses_it(source_dir, tmp_path, wtc_sim):
    scene_file = scene_naming(source_dir, tmp_path, PYTHON_PATH_CONTROLLER)
    scene = wtc.load_scene(scene_file, duration=DURATION)
    assert scene.controller_type == "python"
    cpp = run_series(wtc.load_scene(source_dir / "scenes/towed_path.yaml", duration=DURATION))
    python = run_series(scene)
    np.testing.assert_allclose(python["position"], cpp["position"], rtol=0, atol=TOLERANCE)

    refused = subprocess.run([wtc_sim, str(scene_file), "--quiet", "--out", str(tmp_path / "out")],
                             capture_output=True, text=True)
    assert refused.returncode == 2
    assert "python3 -m wtc run" in refused.stderr, refused.stderr
    assert f"{scene_file}:" in refused.stderr

    ran = subprocess.run([sys.executable, "-m", "wtc", "run", str(scene_file), "--duration", "0.2", "--quiet",
                          "--no-plots", "--out", str(tmp_path / "py")], capture_output=True, text=True)
    assert ran.returncode in (0, 1), ran.stderr
    assert (tmp_path / "py/bodies.csv").exists()


def test_a_scene_with_a_python_controller_that_cannot_be_imported_is_refused_at_its_line(source_dir, tmp_path):
    scene_file = scene_naming(source_dir, tmp_path, PYTHON_PATH_CONTROLLER.replace("my_controller", "no_such_module"))
    with pytest.raises(wtc.InvalidInputError, match=r"towed_python.yaml:\d+:\d+: .*no_such_module"):
        wtc.load_scene(scene_file)
    scene_file = scene_naming(source_dir, tmp_path, PYTHON_PATH_CONTROLLER.replace("lead: 1.0", "lead: -1.0"))
    with pytest.raises(wtc.InvalidInputError, match=r"towed_python.yaml:\d+:\d+: .*lead -1.0 m must be > 0"):
        wtc.load_scene(scene_file)


class Raising:
    def update(self, t, sensors):
        if t > 0.01:
            raise ZeroDivisionError("my controller's own error")
        return None


class BadCommand:
    def update(self, t, sensors):
        return {"no_such_wheel": 1.0}


class CommandsTheTowedBody:
    def update(self, t, sensors):
        return {"towed": 1.0}


def test_a_python_controllers_errors_reach_the_caller(source_dir):
    scene = wtc.load_scene(source_dir / "scenes/towed_path.yaml", duration=0.1)
    with pytest.raises(ZeroDivisionError, match="my controller's own error"):
        wtc.Simulation(scene, controller=Raising()).step(100)
    with pytest.raises(wtc.InvalidInputError, match="'no_such_wheel', which is no body of the vehicle"):
        wtc.Simulation(scene, controller=BadCommand()).step(1)
    # Issue 57 row 10: a command to a body without a drive was dropped without a word.
    with pytest.raises(wtc.InvalidInputError, match="command for 'towed', which has no drive"):
        wtc.Simulation(scene, controller=CommandsTheTowedBody()).step(1)
    with pytest.raises(wtc.InvalidInputError, match="has no update"):
        wtc.Simulation(scene, controller=object())


def test_a_run_whose_python_controller_raises_ends_failed_not_running(source_dir, tmp_path):
    # Issue 52 row 2: summary.json kept "running" after the exception reached the caller.
    scene = wtc.load_scene(source_dir / "scenes/towed_path.yaml", duration=0.1)
    with pytest.raises(ZeroDivisionError, match="my controller's own error"):
        wtc.run(scene, out=tmp_path / "run", progress=False, plots=False, replay=False, controller=Raising())
    summary = json.loads((tmp_path / "run/summary.json").read_text())
    assert summary["status"] == "failed"
    assert summary["success"] is False
    assert [f["criterion"] for f in summary["failed_criteria"]] == ["error"]
    assert "my controller's own error" in summary["failed_criteria"][0]["detail"]
    assert "my controller's own error" in summary["warnings"][0]


class NotNumbersInSummary:
    def update(self, t, sensors):
        return None

    def summary(self):
        return {"laps": 3, "verdict": "good", "ratio": float("nan")}


def test_a_python_summary_that_is_not_numbers_is_a_warning_and_the_run_is_kept(source_dir, tmp_path):
    # Issue 57 row 5: pybind11's "Unable to cast Python instance to C++ type" after the whole run, which was lost.
    scene = wtc.load_scene(source_dir / "scenes/towed_path.yaml", duration=0.1)
    result = wtc.run(scene, out=tmp_path / "run", progress=False, plots=False, replay=False,
                     controller=NotNumbersInSummary())
    warning = next(w for w in result["warnings"] if w.startswith("controller: "))
    assert "summary() gave values that are not finite numbers" in warning
    assert "'verdict': 'good'" in warning and "'ratio': nan" in warning and "laps" not in warning
    assert "laps" not in result
    summary = json.loads((tmp_path / "run/summary.json").read_text())
    assert summary["status"] == "completed"
    assert summary["warnings"] == result["warnings"]
    assert (tmp_path / "run/bodies.csv").exists()


class Recording:
    """Reads every sensor once, commands the tug's wheels by index and by (mode, value)."""

    def __init__(self):
        self.calls = []

    def update(self, t, sensors):
        left, right = sensors.index("tug_left_wheel"), sensors.index("tug_right_wheel")
        self.calls.append((t, sensors.position.shape, sensors.rotation.shape, sensors.wheel_contacts[left],
                           sensors.contact_points(left)[2].sum(), sensors.wheel_force[left][2]))
        return {left: 2.0, right: ("velocity", 2.0)}


def test_a_python_controller_is_called_every_step_with_the_sensors(source_dir):
    scene = wtc.load_scene(source_dir / "scenes/towed_path.yaml", duration=0.1)
    controller = Recording()
    sim = wtc.Simulation(scene, controller=controller)
    sim.step(50)
    assert len(controller.calls) == 50
    times = [c[0] for c in controller.calls]
    np.testing.assert_allclose(np.diff(times), scene.dt, rtol=1e-9)
    t, positions, rotations, contacts, load, force_z = controller.calls[-1]
    assert positions == (len(scene.bodies), 3) and rotations == (len(scene.bodies), 3, 3)
    assert contacts >= 1 and load > 0 and force_z > 0  # the wheel stands on the ground
    drives = scene.drives
    commands = sim.series()["drive_command"][-1]
    assert commands[drives.index("tug_left_wheel")] == 2.0 and commands[drives.index("tug_right_wheel")] == 2.0


class Keeping:
    """Keeps the sensors it was given (a mistake: they are the step's)."""

    def __init__(self):
        self.kept = None

    def update(self, t, sensors):
        self.kept = sensors


def test_sensors_kept_past_their_call_are_refused(source_dir):
    scene = wtc.load_scene(source_dir / "scenes/towed_path.yaml", duration=0.1)
    controller = Keeping()
    wtc.Simulation(scene, controller=controller).step(2)
    for read in [lambda s: s.position, lambda s: s.bodies, lambda s: s.description("tug"), lambda s: s.command_values,
                 lambda s: s.contact_points(1)]:
        with pytest.raises(wtc.InvalidInputError, match="read outside the update call it was given to"):
            read(controller.kept)


class SpeedAlongTheBase:
    """A speed controller as users write one: the base's forward speed is its velocity along the x axis of
    sensors.rotation, held at `target` by integral action on the four wheels' rate."""

    GAIN = 20.0  # rad/s per (m/s) per s: at 0.1 m a wheel, a time constant of 1 / (0.1 x 20) = 0.5 s

    def __init__(self, target, dt):
        self.target, self.dt = target, dt
        self.rate = 0.0
        self.first_rotation = None
        self.speed = self.world_speed = 0.0

    def update(self, t, sensors):
        base = sensors.index("base_link")
        rotation = sensors.rotation[base]
        if self.first_rotation is None:
            self.first_rotation = rotation.copy()
        velocity = sensors.linear_velocity[base]
        self.speed = rotation[:, 0] @ velocity
        self.world_speed = velocity[0]
        self.rate += self.GAIN * (self.target - self.speed) * self.dt
        return {w: self.rate for w in ("fl_wheel", "fr_wheel", "rl_wheel", "rr_wheel")}


def test_users_read_a_links_own_axes_not_the_principal_axes_it_is_integrated_in(source_dir, tmp_path):
    # Issue 57 row 3: a lidar on a fixed joint off the base's axes gives the merged base products of inertia,
    # and the engines integrate it in principal axes (of arbitrary sign and order). Reported as they were, the
    # root came out yawed 180 degrees and a controller like this one drove at 0.92 m/s instead of 0.3.
    scene = wtc.load_scene(source_dir / "tests/urdf/skid_lidar_drive.yaml")
    np.testing.assert_allclose(scene.body("base_link")["pose"][:3, :3], np.eye(3), atol=1e-12)
    np.testing.assert_allclose(scene.body("fl_wheel")["axle"], [0, 0, 1], atol=1e-12)  # the joint's axis, as written
    controller = SpeedAlongTheBase(0.3, scene.dt)
    wtc.run(scene, out=tmp_path / "run", progress=False, plots=False, replay=False, controller=controller)
    np.testing.assert_allclose(controller.first_rotation, np.eye(3), atol=1e-9)
    assert controller.speed == pytest.approx(0.3, abs=0.01)
    assert controller.world_speed == pytest.approx(0.3, abs=0.01)  # forward is world +x, as placed
    # bodies.csv's quaternion of the base: base_link's axes, level and facing +x after 3 s on flat ground.
    series = np.genfromtxt(tmp_path / "run/bodies.csv", delimiter=",", names=True)
    qw, qz = series["base_linkqw"][-1], series["base_linkqz"][-1]
    assert abs(qw) == pytest.approx(1.0, abs=1e-3) and abs(qz) < 0.01  # |yaw| < 1.2 degrees
