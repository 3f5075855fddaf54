"""examples/python/*.py run, quickly (--quick), and say what they did."""
import subprocess
import sys

import pytest


def run_example(source_dir, tmp_path, name, *options):
    done = subprocess.run([sys.executable, str(source_dir / "examples/python" / name), "--quick", *options],
                          capture_output=True, text=True, cwd=tmp_path, timeout=300)
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_ledge_climb_runs_both_engines_and_draws_the_pitch(source_dir, tmp_path):
    out = run_example(source_dir, tmp_path, "ledge_climb.py", "--out", str(tmp_path / "pitch.png"))
    assert "bullet: 1.00 s" in out and "ode: 1.00 s" in out
    assert (tmp_path / "pitch.png").stat().st_size > 10000


def test_my_controller_runs_the_towed_path_with_the_python_controller(source_dir, tmp_path):
    out = run_example(source_dir, tmp_path, "my_controller.py", "--out", str(tmp_path / "run"))
    assert "towed_path with a Python path controller" in out
    assert (tmp_path / "run/bodies.csv").exists()


def test_terrain_queries_queries_and_finds_contacts(source_dir, tmp_path):
    out = run_example(source_dir, tmp_path, "terrain_queries.py")
    assert "3136 queries" in out and "400 wheel poses" in out
    assert "0.4000 m away" in out


@pytest.mark.parametrize("name", ["ledge_climb.py", "my_controller.py", "terrain_queries.py"])
def test_each_example_says_how_to_run_it(source_dir, name):
    text = (source_dir / "examples/python" / name).read_text()
    assert "PYTHONPATH=build/python /usr/bin/python3 examples/python/" + name in text
    assert "--quick" in text
