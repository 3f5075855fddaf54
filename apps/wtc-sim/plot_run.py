#!/usr/bin/env python3
"""Figures of one wtc-sim run, from the CSV series in its directory.

usage: plot_run.py RUN_DIR [--prismatic NAME,NAME...]

Draws what the source plots: the vehicle's path (top view) and its wheels'
heights (side view), the root bodies' pitch and roll, the drives' efforts
and saturation, the wheels' normal and traction forces, and the hitch force
for the towed system. Exits 3 (and says so) when matplotlib is missing.

Each axis holds one unit: angles (deg) apart from slider travel (m), torques
(N m) apart from slider forces (N). Which drives are on sliding joints
comes from the run's summary.json (each drive's "joint"); --prismatic names
them instead, for a run written before summary.json said. A left and a right body of a pair
(front_left_wheel, front_right_wheel) share a colour: left solid, right
dashed; other lines get a colour and a dash each; legends stand beside the
axes.
"""
import csv
import json
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


def plot_all(ax, x, series, colours):
    """Lines of `series` (name -> values) on `ax`, each told apart: a left and a right body of a pair
    (front_left_wheel, front_right_wheel) share a colour, left solid, right dashed; other lines that
    would lie on one another (two sliders at the same travel) get their own colour and dash."""
    unpaired = 0
    for name, values in series:
        pair = name.replace("left", "").replace("right", "")
        if pair not in colours:
            colours[pair] = "C%d" % (len(colours) % 10)
        if "left" in name or "right" in name:
            style = "--" if "right" in name else "-"
        else:
            style = ("-", "--", "-.", ":")[unpaired % 4]
            unpaired += 1
        ax.plot(x, values, label=name, color=colours[pair], linestyle=style)


def legend(ax):
    """Beside the axes, not over the lines."""
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)


def save(fig, run_dir, name):
    fig.tight_layout()
    fig.savefig(os.path.join(run_dir, name), dpi=110)
    plt.close(fig)


def main(run_dir, prismatic=None):
    bodies = read(os.path.join(run_dir, "bodies.csv"))
    drives = read(os.path.join(run_dir, "drives.csv"))
    wheels = read(os.path.join(run_dir, "wheels.csv"))
    t = bodies["t_s"]
    body_names = names(bodies, ".x_m")
    wheel_names = names(wheels, ".fz_N")
    drive_names = names(drives, ".effort")
    if prismatic is None:
        # Each drive's joint as the run wrote it (summary.json), not guessed from its name.
        with open(os.path.join(run_dir, "summary.json")) as f:
            summary_drives = json.load(f).get("drives", {})
        unknown = [d for d in drive_names if "joint" not in summary_drives.get(d, {})]
        if unknown:
            print(f"plot_run.py: summary.json names no joint for {', '.join(unknown)} (a run from before "
                  "2026-11-29?): drawn as revolute; give --prismatic", file=sys.stderr)
        prismatic = [d for d in drive_names if summary_drives.get(d, {}).get("joint") == "prismatic"]
    roots = [b for b in body_names if b not in wheel_names and b not in drive_names]
    colours = {}

    fig, (top, side) = plt.subplots(1, 2, figsize=(13, 4.2))
    for b in roots:
        top.plot(bodies[b + ".x_m"], bodies[b + ".y_m"], label=b)
    top.set(xlabel="x (m)", ylabel="y (m)", title="path of the bodies (top view)")
    top.axis("equal")
    legend(top)
    for w in wheel_names:
        plot_all(side, bodies[w + ".x_m"], [(w, bodies[w + ".z_m"])], colours)
    side.set(xlabel="x (m)", ylabel="z (m)", title="wheel centres (side view)")
    legend(side)
    save(fig, run_dir, "trajectories.png")

    # One unit per axis: the roots' attitude and the joints' angles (deg), the sliders' travel (m).
    turning = [d for d in names(drives, ".position") if d not in wheel_names and d not in prismatic]
    sliding = [d for d in names(drives, ".position") if d in prismatic]
    panels = 1 + bool(turning) + bool(sliding)
    fig, axes = plt.subplots(panels, 1, figsize=(10, 1.2 + 2.6 * panels), sharex=True, squeeze=False)
    axes = list(axes[:, 0])
    attitude = axes.pop(0)
    for b in roots:
        pr = [pitch_roll_deg(*q) for q in zip(*(bodies[b + "." + c] for c in ("qw", "qx", "qy", "qz")))]
        attitude.plot(t, [p for p, _ in pr], label=b + " pitch")
        attitude.plot(t, [r for _, r in pr], "--", label=b + " roll")
    attitude.set(ylabel="attitude (deg)", title="attitude and joint positions")
    legend(attitude)
    if turning:
        ax = axes.pop(0)
        plot_all(ax, drives["t_s"], [(d, [math.degrees(v) for v in drives[d + ".position"]]) for d in turning],
                 colours)
        ax.set(ylabel="joint angle (deg)")
        legend(ax)
    if sliding:
        ax = axes.pop(0)
        plot_all(ax, drives["t_s"], [(d, drives[d + ".position"]) for d in sliding], colours)
        ax.set(ylabel="slider travel (m)")
        legend(ax)
    fig.axes[-1].set(xlabel="t (s)")
    save(fig, run_dir, "angles.png")

    if drive_names:
        # One unit and one scale per axis: the wheels' torques, the other joints' (a carrier's reach
        # 1500 N m, a wheel's 50), the sliders' forces.
        groups = [(g, unit) for g, unit in (
            ([d for d in drive_names if d in wheel_names], "wheel torque (N m)"),
            ([d for d in drive_names if d not in wheel_names and d not in prismatic], "joint torque (N m)"),
            ([d for d in drive_names if d in prismatic], "slider force (N)")) if g]
        fig, axes = plt.subplots(len(groups), 1, figsize=(10, 1.2 + 2.6 * len(groups)), sharex=True, squeeze=False)
        for ax, (group, unit) in zip(axes[:, 0], groups):
            plot_all(ax, drives["t_s"], [(d, drives[d + ".effort"]) for d in group], colours)
            ax.set(ylabel=unit)
            legend(ax)
        axes[0, 0].set(title="drive efforts")
        axes[-1, 0].set(xlabel="t (s)")
        save(fig, run_dir, "efforts.png")

    fig, (normal, traction) = plt.subplots(2, 1, figsize=(10, 6), sharex=True)
    plot_all(normal, wheels["t_s"], [(w, wheels[w + ".fz_N"]) for w in wheel_names], colours)
    plot_all(traction, wheels["t_s"],
             [(w, [math.hypot(x, y) for x, y in zip(wheels[w + ".fx_N"], wheels[w + ".fy_N"])]) for w in wheel_names],
             colours)
    normal.set(ylabel="vertical force (N)", title="ground forces on the wheels")
    traction.set(xlabel="t (s)", ylabel="horizontal force (N)")
    legend(normal)
    save(fig, run_dir, "contact_forces.png")

    hitch_path = os.path.join(run_dir, "hitch.csv")
    if os.path.exists(hitch_path):
        hitch = read(hitch_path)
        fig, ax = plt.subplots(figsize=(10, 4))
        for c in ("px_N", "py_N", "pz_N"):
            ax.plot(hitch["t_s"], hitch[c], label=c)
        ax.set(xlabel="t (s)", ylabel="force (N, tug axes)", title="hitch force")
        legend(ax)
        save(fig, run_dir, "hitch.png")


if __name__ == "__main__":
    args = sys.argv[1:]
    prismatic = None
    if len(args) == 3 and args[1] == "--prismatic":
        prismatic = [n for n in args[2].split(",") if n]
        args = args[:1]
    if len(args) != 1:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    main(args[0], prismatic)
