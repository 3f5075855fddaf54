"""WTC from Python: run scenes, write controllers, query terrains (docs/python.md).

    import wtc
    scene = wtc.load_scene("scenes/robot_ledge.yaml", engine="ode", mode="constraint",
                           set={"ledge_height": 0.15})
    summary = wtc.run(scene, out="runs/ledge")        # wtc-sim's outputs, the same bytes
    sim = wtc.Simulation(scene); sim.step(1000); sim.series()["position"]

Units are SI throughout (m, s, N, rad); see docs/python.md for each function.
"""
import os

from ._wtc import (Error, InvalidInputError, Scene, Sensors, Simulation as _Simulation, Terrain, __version__,
                   heightfield, load_terrain, soils, wheel_on_soil, write_dem)
from . import _wtc

__all__ = ["__version__", "Error", "InvalidInputError", "Scene", "Sensors", "Simulation", "Terrain", "heightfield", "load_scene",
           "load_terrain", "run", "soils", "wheel_on_soil", "write_dem"]


def _yaml_text(value):
    """An override's value as YAML text (what --set takes): numbers, booleans, strings, lists and tuples of them,
    NumPy arrays and NumPy numbers (as their Python values)."""
    if hasattr(value, "tolist") and callable(value.tolist):  # a NumPy array or scalar
        value = value.tolist()
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_yaml_text(v) for v in value) + "]"
    return str(value)


def load_scene(path, engine=None, mode=None, dt=None, duration=None, set=None):
    """Reads a scene file as wtc-sim does with --engine, --mode, --dt, --duration and --set.

    path: the scene file (scenes/*.yaml); engine: "bullet", "ode" or "ode_quick"; mode: "force", "constraint", "implicit",
    "engine_cylinder" or "engine_sphere"; dt: step (s); duration: simulated time (s); set: {key.path: value},
    each an override as --set key.path=value (a parameter's name, or a path into the document), in order.
    Raises wtc.InvalidInputError naming the file, line, column and key of what is wrong.
    """
    overrides = []
    if engine is not None:
        overrides.append(("engine", str(engine)))
    if mode is not None:
        overrides.append(("mode", str(mode)))
    if dt is not None:
        overrides.append(("dt", _yaml_text(float(dt))))
    if duration is not None:
        overrides.append(("duration", _yaml_text(float(duration))))
    for key, value in (set or {}).items():
        overrides.append((str(key), _yaml_text(value)))
    return _wtc._load_scene(str(path), overrides)


def run(scene, out=None, progress=True, plots=True, replay=True, controller=None):
    """Runs the scene whole and writes what wtc-sim writes, byte for byte the same series.

    scene: a wtc.Scene (wtc.load_scene), or a scene file's path (read as load_scene(path) reads it).
    out: the output directory (new or empty); None: runs/<scene>_<engine>_<mode>[_N] as wtc-sim.
    progress: True for wtc-sim's progress bar on stderr, False for none, or a callable(fraction).
    plots, replay: False skips the figures (--no-plots) or the replay page (--no-replay).
    controller: a Python controller (update(t, sensors) -> commands) instead of the scene's.
    Returns the summary as a dict (summary.json's figures, "out": the directory). The engine steps without the
    GIL. Ctrl-C ends the run as in wtc-sim (outputs written, summary interrupted) and then raises
    KeyboardInterrupt.
    """
    if isinstance(scene, (str, os.PathLike)):
        scene = load_scene(scene)
    if not isinstance(scene, Scene):
        raise TypeError(f"wtc.run: scene must be a wtc.Scene (wtc.load_scene) or a scene file's path, not "
                        f"{type(scene).__name__}")
    if not (isinstance(progress, bool) or progress is None or callable(progress)):
        raise TypeError(f"wtc.run: progress must be True, False, None or a callable(fraction), not {progress!r}")
    if controller is not None:
        scene = _wtc._with_controller(scene, controller)
    return _wtc._run(scene, None if out is None else str(out), progress, plots, replay)


class Simulation(_Simulation):
    """A scene stepped from Python: step(n), state(), wheel_forces(), drive_efforts(), series(), summary().

    controller: a Python controller instead of the scene's. record_every: keep every n-th step in series().
    """

    def __init__(self, scene, controller=None, record_every=1):
        if controller is not None:
            scene = _wtc._with_controller(scene, controller)
        super().__init__(scene, record_every)
