#!/usr/bin/env python3
"""What accuracy costs in time: a study's runs, error against wall time.

usage: plot_study.py STUDY_DIR

Reads STUDY_DIR/results.csv (written by wtc-study) and draws, per scenario,
each run's RMS position error against its wall time on log axes: colour by
engine, filled for force mode and hollow for constraint mode, squares for the
engines' own wheel contact (engine_cylinder, engine_sphere), a cross for a
run that failed its scene's criterion, and the Pareto front (runs no other
successful run beats on both) as a line. Errors below 1 micrometre (the
reference's own is zero) are drawn on the 1 micrometre line, the reference
as a star. Writes STUDY_DIR/pareto.png.
Exits 3 (and says so) when matplotlib is missing.
"""
import csv
import os
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("plot_study.py: matplotlib is not installed (apt install python3-matplotlib); no figure", file=sys.stderr)
    sys.exit(3)

COLOURS = {"bullet": "tab:blue", "ode": "tab:orange", "ode_quick": "tab:green"}
FLOOR_MM = 1e-3  # errors below a micrometre are drawn on this line


def main(study_dir):
    with open(os.path.join(study_dir, "results.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    scenarios = list(dict.fromkeys(r["scenario"] for r in rows))
    fig, axes = plt.subplots(1, len(scenarios), figsize=(6.5 * len(scenarios), 5.2), squeeze=False)
    for ax, scenario in zip(axes[0], scenarios):
        runs = [r for r in rows if r["scenario"] == scenario]
        floor = FLOOR_MM
        for r in runs:
            x = float(r["wall_time_s"])
            y = max(float(r["rms_position_error_m"]) * 1e3, floor)
            colour = COLOURS.get(r["engine"], "k")
            if r["reference"] == "1":
                ax.scatter(x, y, marker="*", color="k", s=90, zorder=3)
            elif r["success"] != "1":
                ax.scatter(x, y, marker="x", color=colour, s=28)
            else:
                face = colour if r["mode"] != "constraint" else "none"
                marker = "s" if r["mode"].startswith("engine") else "^" if r["mode"] == "implicit" else "o"
                ax.scatter(x, y, marker=marker, facecolors=face, edgecolors=colour, s=28)
        front = sorted((r for r in runs if r["on_front"] == "1"), key=lambda r: float(r["wall_time_s"]))
        ax.step([float(r["wall_time_s"]) for r in front],
                [max(float(r["rms_position_error_m"]) * 1e3, floor) for r in front],
                where="post", color="k", lw=1.0, label="Pareto front")
        for r in front:
            ax.annotate(r["label"], (float(r["wall_time_s"]), max(float(r["rms_position_error_m"]) * 1e3, floor)),
                        fontsize=6, xytext=(4, 3), textcoords="offset points")
        for engine, colour in COLOURS.items():
            ax.scatter([], [], color=colour, label=engine)
        ax.scatter([], [], facecolors="none", edgecolors="k", label="constraint mode (hollow)")
        ax.scatter([], [], marker="^", color="k", label="implicit mode (triangle)")
        ax.scatter([], [], marker="s", color="k", label="the engine's own wheel contact (square)")
        ax.scatter([], [], marker="x", color="k", label="failed the scene's criterion")
        ax.scatter([], [], marker="*", color="k", s=90, label="the reference (error 0)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("wall time of the run (s)")
        ax.set_ylabel("RMS position error against the reference (mm)")
        ax.set_title(scenario)
        ax.grid(True, which="both", lw=0.3)
        ax.legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    fig.savefig(os.path.join(study_dir, "pareto.png"), dpi=120)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
