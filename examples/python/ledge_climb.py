#!/usr/bin/env python3
"""The six-wheel robot's ledge climb (scenes/robot_ledge.yaml) in Bullet and ODE, the sections' pitch plotted.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/ledge_climb.py [--height 0.65] [--mode force]
        [--out ledge_climb_pitch.png] [--quick]

Each engine runs the scene step by step (wtc.Simulation), its series kept at the scene's 100 rows per second; the
pitch of the middle section and of the front and rear carriers (the angle of each body's x axis above the
horizontal, deg) is drawn against time for both engines in one figure. --quick: 1 s of the climb (the test
suite's).
"""
import argparse
import math
import pathlib

import numpy as np

import wtc

SECTIONS = ["middle", "front_carrier", "rear_carrier"]


def pitch_deg(quaternion):
    """The body x axis' angle above the horizontal (deg), from (w, x, y, z) quaternions shaped (..., 4)."""
    w, x, y, z = np.moveaxis(quaternion, -1, 0)
    # The x axis' world z component: R[2, 0] = 2 (x z - w y).
    return np.degrees(np.arcsin(np.clip(2.0 * (x * z - w * y), -1.0, 1.0)))


def climb(engine, height, mode, duration):
    root = pathlib.Path(__file__).resolve().parents[2]
    scene = wtc.load_scene(root / "scenes/robot_ledge.yaml", engine=engine, mode=mode, duration=duration,
                           set={"ledge_height": height})
    sim = wtc.Simulation(scene, record_every=round(1.0 / (100.0 * scene.dt)))
    sim.step(round(scene.duration / scene.dt))
    series = sim.series()
    bodies = scene.bodies
    pitch = {s: pitch_deg(series["quaternion"][:, bodies.index(s), :]) for s in SECTIONS}
    top = series["position"][-1, [bodies.index(w) for w in scene.wheels], 2].min()
    return series["time"], pitch, top


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--height", type=float, default=0.65, help="ledge height (m)")
    parser.add_argument("--mode", default="force", help="force or constraint")
    parser.add_argument("--duration", type=float, help="simulated time (s; the scene's 25 s by default)")
    parser.add_argument("--out", default="ledge_climb_pitch.png", help="the figure (PNG)")
    parser.add_argument("--quick", action="store_true", help="1 s of the climb (the test suite's)")
    args = parser.parse_args()
    duration = 1.0 if args.quick else args.duration
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(len(SECTIONS), 1, sharex=True, figsize=(8, 7))
    for engine, style in [("bullet", "-"), ("ode", "--")]:
        time, pitch, lowest_wheel = climb(engine, args.height, args.mode, duration)
        for ax, section in zip(axes, SECTIONS):
            ax.plot(time, pitch[section], style, label=engine)
            ax.set_ylabel(f"{section}\npitch (deg)")
        print(f"{engine}: {time[-1]:.2f} s, lowest wheel centre at {lowest_wheel:.3f} m; peak pitch "
              + ", ".join(f"{s} {np.abs(pitch[s]).max():.1f} deg" for s in SECTIONS))
    axes[0].legend()
    axes[0].set_title(f"robot_ledge, {args.height} m ledge, {args.mode} mode")
    axes[-1].set_xlabel("t (s)")
    figure.tight_layout()
    figure.savefig(args.out, dpi=100)
    print(f"figure: {args.out}")


if __name__ == "__main__":
    main()
