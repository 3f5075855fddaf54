"""The package: imported from the build tree, scenes loaded with overrides, C++ errors as wtc.Error."""
import os
import subprocess
import sys

import pytest

import wtc


def test_imports_from_the_build_tree_with_its_api():
    for name in ["load_scene", "run", "Simulation", "Terrain", "load_terrain", "heightfield", "Error",
                 "InvalidInputError", "Sensors"]:
        assert hasattr(wtc, name), name


def test_load_scene_applies_engine_mode_and_overrides(source_dir):
    scene = wtc.load_scene(source_dir / "scenes/robot_ledge.yaml", engine="ode", mode="constraint",
                           set={"ledge_height": 0.5}, duration=2)
    assert scene.engine == "ode"
    assert scene.mode == "constraint"
    assert scene.parameters["ledge_height"] == 0.5
    assert scene.duration == 2.0
    assert scene.dt == pytest.approx(4e-4)
    assert scene.overrides == [("engine", "ode"), ("mode", "constraint"), ("duration", "2.0"),
                               ("ledge_height", "0.5")]
    assert "middle_left_wheel" in scene.wheels


def test_invalid_input_is_a_wtc_error_and_a_value_error():
    assert issubclass(wtc.InvalidInputError, wtc.Error)
    assert issubclass(wtc.InvalidInputError, ValueError)
    assert issubclass(wtc.Error, Exception)


def test_an_error_in_a_scene_file_carries_the_cpp_message_with_file_line_and_key(source_dir, tmp_path):
    scene = tmp_path / "bad.yaml"
    text = (source_dir / "scenes/robot_straight.yaml").read_text()
    scene.write_text(text.replace("dt: 0.0004", "dt: -0.0004"))
    with pytest.raises(wtc.InvalidInputError) as error:
        wtc.load_scene(scene)
    message = str(error.value)
    line = next(n for n, l in enumerate(scene.read_text().splitlines(), 1) if l.startswith("dt:"))
    assert message.startswith(f"{scene}:{line}:"), message
    assert "dt: must be > 0 s" in message


def test_an_override_error_names_the_override(source_dir):
    with pytest.raises(wtc.InvalidInputError, match=r"--set dt=-1\.0: dt: must be > 0 s"):
        wtc.load_scene(source_dir / "scenes/robot_ledge.yaml", dt=-1)


def test_an_unknown_engine_is_refused_as_the_scene_is_loaded_naming_the_known_ones(source_dir):
    # Refused by load_scene itself (issue 57 row 10: it was accepted, and Simulation failed later), before the
    # terrain: a terrain that is not there is never reached.
    with pytest.raises(wtc.InvalidInputError, match=r"--set engine=bulet: engine: unknown engine 'bulet' \(expected "
                                                    r"bullet, ode"):
        wtc.load_scene(source_dir / "scenes/robot_straight.yaml", engine="bulet", set={"terrain": "no_such.yaml"})


def test_a_missing_file_is_an_invalid_input_error(tmp_path):
    with pytest.raises(wtc.InvalidInputError, match="nothing.yaml"):
        wtc.load_scene(tmp_path / "nothing.yaml")
    with pytest.raises(wtc.InvalidInputError, match="nothing.yaml"):
        wtc.load_terrain(tmp_path / "nothing.yaml")


def test_cmake_install_puts_an_importable_package_under_the_prefix(tmp_path, source_dir):
    prefix = tmp_path / "prefix"
    subprocess.run([os.environ["WTC_CMAKE"], "--install", os.environ["WTC_BUILD_DIR"], "--prefix", str(prefix),
                    "--component", "python"], check=True, capture_output=True)
    site = prefix / os.environ["WTC_PYTHON_INSTALL_DIR"]
    assert (site / "wtc/__init__.py").exists()
    script = ("import sys, wtc; print(wtc.__file__); "
              "s = wtc.load_scene(sys.argv[1], duration=0.01); "
              "print(wtc.run(s, out=sys.argv[2], progress=False, plots=False)['steps'])")
    env = dict(os.environ, PYTHONPATH=str(site))
    done = subprocess.run([sys.executable, "-c", script, str(source_dir / "scenes/robot_straight.yaml"),
                           str(tmp_path / "run")], capture_output=True, text=True, env=env, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert lines[0].startswith(str(site)), lines
    assert lines[1] == "25"
    assert (tmp_path / "run/bodies.csv").exists()


def test_the_package_says_its_version():
    assert wtc.__version__.count(".") == 2 and all(part.isdigit() for part in wtc.__version__.split("."))


def test_run_takes_a_scene_files_path_and_refuses_what_is_neither(source_dir, tmp_path):
    # Issue 57 row 10: wtc.run("scene.yaml") raised a TypeError naming the internal _run; progress="yes" was taken.
    scene = source_dir / "tests/bad_input/scene.yaml"  # 10 ms of the robot at rest
    summary = wtc.run(scene, out=tmp_path / "a", progress=False, plots=False, replay=False)
    assert summary["scene"] == "bad_input" and summary["steps"] == 25
    with pytest.raises(TypeError, match=r"wtc.run: scene must be a wtc.Scene \(wtc.load_scene\) or a scene file's path, "
                                        r"not int"):
        wtc.run(3)
    with pytest.raises(TypeError, match=r"progress must be True, False, None or a callable\(fraction\), not 'yes'"):
        wtc.run(str(scene), out=tmp_path / "b", progress="yes")
    assert not (tmp_path / "b").exists()
    with pytest.raises(wtc.InvalidInputError, match="nothing.yaml"):
        wtc.run(tmp_path / "nothing.yaml")


def test_a_numpy_value_is_an_override_as_its_python_value(source_dir):
    np = pytest.importorskip("numpy")
    scene = wtc.load_scene(source_dir / "scenes/robot_ledge.yaml",
                           set={"ledge_height": np.float64(0.25), "vehicle.translation": np.array([0.0, 0.0, 0.01])})
    assert scene.parameters["ledge_height"] == 0.25
