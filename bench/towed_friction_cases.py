#!/usr/bin/env python3
"""The towed system up the 2 deg incline at the source's three friction cases, side by side.

usage: bench/towed_friction_cases.py [--engine bullet|ode|ode_quick] [--mode force|constraint]
                                     [--wtc-sim build/apps/wtc-sim] [--out docs/figures]

Runs scenes/towed_incline.yaml once per case (--set friction_case=N), then draws, overlaid
for the three cases, the tug's centre-of-mass path, the drive-wheel torques and the wheels'
friction forces (towed_cases_*.png in --out), and prints a Markdown table: peak and mean
drive torque, peak slip of the drive wheels after the first second, tracking error, hitch force, success.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

CASES = {1: (0.45, 0.75), 2: (0.30, 0.50), 3: (0.21, 0.35)}
SETTLED_S = 1.0  # the first second is the start from rest (slip ratios at walking pace mean little)
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return {h: [float(r[i]) for r in rows[1:]] for i, h in enumerate(rows[0])}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--engine", default="bullet")
    parser.add_argument("--mode", default="force")
    parser.add_argument("--wtc-sim", default=os.path.join(ROOT, "build/apps/wtc-sim"))
    parser.add_argument("--out", default=os.path.join(ROOT, "docs/figures"))
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    work = tempfile.mkdtemp(prefix="wtc_towed_cases_")
    runs = {}
    for case in CASES:
        out = os.path.join(work, f"case{case}")
        command = [args.wtc_sim, os.path.join(ROOT, "scenes/towed_incline.yaml"), "--engine", args.engine,
                   "--mode", args.mode, "--set", f"friction_case={case}", "--out", out, "--no-plots", "--quiet"]
        if subprocess.run(command).returncode not in (0, 1):  # 1: ran, criterion failed
            sys.exit(f"towed_friction_cases.py: {' '.join(command)} failed")
        runs[case] = {name: read(os.path.join(out, name + ".csv")) for name in ("bodies", "drives", "wheels", "hitch")}
        with open(os.path.join(out, "summary.json")) as f:
            runs[case]["summary"] = json.load(f)

    label = {c: f"case {c}: {d:.2f} / {s:.2f}" for c, (d, s) in CASES.items()}
    fig, (along, side) = plt.subplots(1, 2, figsize=(11, 4))
    for c, r in runs.items():
        b = r["bodies"]
        along.plot(b["t_s"], [x - b["tug.x_m"][0] for x in b["tug.x_m"]], label=label[c])
        side.plot([x - b["tug.x_m"][0] for x in b["tug.x_m"]], [z - b["tug.z_m"][0] for z in b["tug.z_m"]],
                  label=label[c])
    along.set(xlabel="t (s)", ylabel="tug centre of mass, x - x0 (m)", title="progress up the slope")
    side.set(xlabel="x - x0 (m)", ylabel="z - z0 (m)", title="tug centre-of-mass path (side view)")
    along.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "towed_cases_path.png"), dpi=110)

    fig, ax = plt.subplots(figsize=(8, 4))
    for c, r in runs.items():
        d = r["drives"]
        ax.plot(d["t_s"], d["tug_left_wheel.effort"], label=label[c] + ", left")
        ax.plot(d["t_s"], d["tug_right_wheel.effort"], "--", label=label[c] + ", right")
    ax.axhline(2500, color="k", lw=0.8, ls=":")
    ax.set(xlabel="t (s)", ylabel="drive torque (N m)", title="drive-wheel torques (limit 2500 N m)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "towed_cases_torques.png"), dpi=110)

    fig, axes = plt.subplots(1, 2, figsize=(11, 4), sharey=False)
    for c, r in runs.items():
        w = r["wheels"]
        traction = [math.hypot(x, y) for x, y in zip(w["tug_left_wheel.fx_N"], w["tug_left_wheel.fy_N"])]
        axes[0].plot(w["t_s"], traction, label=label[c])
        main = [math.hypot(x, y) for x, y in zip(w["main_left_wheel.fx_N"], w["main_left_wheel.fy_N"])]
        axes[1].plot(w["t_s"], main, label=label[c])
    axes[0].set(xlabel="t (s)", ylabel="horizontal ground force (N)", title="tug's left drive wheel")
    axes[1].set(xlabel="t (s)", ylabel="horizontal ground force (N)", title="towed body's left main wheel")
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "towed_cases_friction.png"), dpi=110)

    print(f"{args.engine}, {args.mode} mode, 0.4 ms, 5 s:\n")
    print("| case: dynamic / static | peak torque (N m) | mean torque (N m) | peak slip after 1 s, drive wheels | "
          "max / RMS tracking error (m) | hitch force peak / mean (N) | distance (m) | holds the path |")
    print("|---|---:|---:|---:|---:|---:|---:|---|")
    for c, r in runs.items():
        s = r["summary"]
        drives = s["drives"]
        peak = max(drives[w]["peak_effort"] for w in ("tug_left_wheel", "tug_right_wheel"))
        mean = 0.5 * (drives["tug_left_wheel"]["mean_effort"] + drives["tug_right_wheel"]["mean_effort"])
        w = r["wheels"]
        slip = max(v for t, a, b in zip(w["t_s"], w["tug_left_wheel.max_slip"], w["tug_right_wheel.max_slip"])
                   if t >= SETTLED_S for v in (a, b))
        dynamic, static = CASES[c]
        slip_text = f"{slip:.3f}" if slip < 10 else f"spins in place ({slip:.0f})"
        print(f"| {c}: {dynamic:.2f} / {static:.2f} | {peak:.0f} | {mean:.0f} | {slip_text} | "
              f"{s['max_tracking_error_m']:.3f} / {s['rms_tracking_error_m']:.3f} | "
              f"{s['hitch_force_peak_N']:.0f} / {s['hitch_force_mean_x_N']:.0f} | {s['distance_m']:.2f} | "
              f"{'yes' if s['success'] else 'no: ' + '; '.join(w for w in s['warnings'] if 'path' in w)} |")


if __name__ == "__main__":
    main()
