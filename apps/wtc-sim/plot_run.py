#!/usr/bin/env python3
"""Figures of one wtc-sim run, from the CSV series in its directory.

usage: plot_run.py RUN_DIR

Draws what the source plots: the vehicle's path (top view) and its wheels'
heights (side view), the root bodies' pitch and roll, the drives' efforts
and saturation, the wheels' normal and traction forces, and the hitch force
for the towed system. Exits 3 (and says so) when matplotlib is missing.
"""
import csv
import math
import os
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("plot_run.py: matplotlib is not installed (apt install python3-matplotlib); no figures", file=sys.stderr)
    sys.exit(3)


def read(path):
    """Columns of a CSV file as lists of floats, by header name."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, data = rows[0], [r for r in rows[1:] if len(r) == len(rows[0])]
    return {h: [float(r[i]) for r in data] for i, h in enumerate(header)}


def names(columns, suffix):
    return [c[: -len(suffix)] for c in columns if c.endswith(suffix)]


def pitch_roll_deg(qw, qx, qy, qz):
    # The body z axis's tilt about the body y (pitch) and x (roll) axes.
    pitch = math.asin(max(-1.0, min(1.0, 2.0 * (qw * qy - qz * qx))))
    roll = math.atan2(2.0 * (qw * qx + qy * qz), 1.0 - 2.0 * (qx * qx + qy * qy))
    return math.degrees(pitch), math.degrees(roll)


def save(fig, run_dir, name):
    fig.tight_layout()
    fig.savefig(os.path.join(run_dir, name), dpi=110)
    plt.close(fig)


def main(run_dir):
    bodies = read(os.path.join(run_dir, "bodies.csv"))
    drives = read(os.path.join(run_dir, "drives.csv"))
    wheels = read(os.path.join(run_dir, "wheels.csv"))
    t = bodies["t_s"]
    body_names = names(bodies, ".x_m")
    wheel_names = names(wheels, ".fz_N")
    roots = [b for b in body_names if b not in wheel_names and not any(
        b + "." + s in drives for s in ("position",))]

    fig, (top, side) = plt.subplots(1, 2, figsize=(11, 4.2))
    for b in roots:
        top.plot(bodies[b + ".x_m"], bodies[b + ".y_m"], label=b)
    top.set(xlabel="x (m)", ylabel="y (m)", title="path of the bodies (top view)")
    top.axis("equal")
    top.legend(fontsize=7)
    for w in wheel_names:
        if "left" in w or len(wheel_names) <= 6:
            side.plot(bodies[w + ".x_m"], bodies[w + ".z_m"], label=w)
    side.set(xlabel="x (m)", ylabel="z (m)", title="wheel centres (side view)")
    side.legend(fontsize=7)
    save(fig, run_dir, "trajectories.png")

    fig, ax = plt.subplots(figsize=(8, 4))
    for b in roots:
        pr = [pitch_roll_deg(*q) for q in zip(*(bodies[b + "." + c] for c in ("qw", "qx", "qy", "qz")))]
        ax.plot(t, [p for p, _ in pr], label=b + " pitch")
        ax.plot(t, [r for _, r in pr], "--", label=b + " roll")
    for d in names(drives, ".position"):
        if d not in wheel_names:
            ax.plot(drives["t_s"], [math.degrees(v) if "carrier" in d else v for v in drives[d + ".position"]],
                    ":", label=d + (" (deg)" if "carrier" in d else " (m)"))
    ax.set(xlabel="t (s)", ylabel="angle (deg)", title="attitude and joint positions")
    ax.legend(fontsize=7)
    save(fig, run_dir, "angles.png")

    drive_names = names(drives, ".effort")
    if drive_names:
        fig, ax = plt.subplots(figsize=(8, 4))
        for d in drive_names:
            ax.plot(drives["t_s"], drives[d + ".effort"], label=d)
        ax.set(xlabel="t (s)", ylabel="effort (N m or N)", title="drive efforts")
        ax.legend(fontsize=7)
        save(fig, run_dir, "efforts.png")

    fig, (normal, traction) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    for w in wheel_names:
        normal.plot(wheels["t_s"], wheels[w + ".fz_N"], label=w)
        traction.plot(wheels["t_s"], [math.hypot(x, y) for x, y in zip(wheels[w + ".fx_N"], wheels[w + ".fy_N"])],
                      label=w)
    normal.set(ylabel="vertical force (N)", title="ground forces on the wheels")
    traction.set(xlabel="t (s)", ylabel="horizontal force (N)")
    normal.legend(fontsize=7)
    save(fig, run_dir, "contact_forces.png")

    hitch_path = os.path.join(run_dir, "hitch.csv")
    if os.path.exists(hitch_path):
        hitch = read(hitch_path)
        fig, ax = plt.subplots(figsize=(8, 4))
        for c in ("px_N", "py_N", "pz_N"):
            ax.plot(hitch["t_s"], hitch[c], label=c)
        ax.set(xlabel="t (s)", ylabel="force (N, tug axes)", title="hitch force")
        ax.legend(fontsize=7)
        save(fig, run_dir, "hitch.png")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    main(sys.argv[1])
