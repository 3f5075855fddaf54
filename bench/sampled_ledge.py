#!/usr/bin/env python3
"""The robot's ledge climb on a sampled ledge against the same climb on a mesh
of the same surface (issue 53, item 3).

For each ledge height (0.60 m for 18 s, 0.65 m for 25 s), cell (5, 2, 1 cm),
engine and mode it serves, two runs of
scenes/robot_ledge.yaml that differ only in the ground: the ledge sampled into
a compact heightfield of that cell (the engines' bodies meet the engine's own
heightfield shape, WTC's wheels the field's triangles), and
terrains/ledge_sampled_<height>_<cell>cm.obj, the same surface as one mesh
with no cells. The difference is the middle body's RMS position difference
over the run, as the accuracy study measures a run against its reference
(src/study/study_results.cpp). Writes <out>/sampled_ledge.md and .json.
With --storage stored the sampled ledge is stored prisms instead (a piece a
prism, every engine's bodies meeting the prisms one by one).

    bench/sampled_ledge.py --build build --out /tmp/sampled_ledge [--workers 2] [--storage stored]
        [--engines ode] [--cells 0.02,0.01]
"""
import argparse
import concurrent.futures
import json
import pathlib
import subprocess
import sys

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parent.parent
HEIGHTS = {"0.60": 18.0, "0.65": 25.0}  # ledge height -> simulated seconds (the study's, the scene's)
CELLS = {"0.05": 5, "0.02": 2, "0.01": 1}  # m -> cm
MODES = {"bullet": ["force", "constraint", "implicit"], "ode": ["force", "constraint", "implicit"],
         "mujoco": ["force", "constraint"]}  # the modes each engine serves
# Every mode's climb passes within a centimetre of its own mesh climb (issue 53, item 3).
BOUND_MM = 10.0


def ground(height, cell, kind):
    if kind in ("field", "prisms"):
        storage = ", storage: compact" if kind == "field" else ""
        return (f"{{type: ledge, material: asphalt_concrete, height: {height}, approach_length: 4.0, "
                f"top_length: 4.0, width: 4.0, thickness: 0.5, heightfield_spacing: {cell}{storage}}}")
    obj = ROOT / "terrains" / f"ledge_sampled_{height}_{CELLS[cell]}cm.obj"
    return f"{{type: mesh, file: {obj}, material: asphalt_concrete, thickness: 0.5}}"


def run(build, out, height, cell, engine, mode, kind):
    d = out / f"{height}_{CELLS[cell]}cm_{engine}_{mode}_{kind}"
    if not (d / "summary.json").exists():
        subprocess.run([str(build / "apps" / "wtc-sim"), str(ROOT / "scenes" / "robot_ledge.yaml"), "--engine", engine,
                        "--mode", mode, "--set", f"duration={HEIGHTS[height]}", "--set", f"ledge_height={height}",
                        "--set", f"terrain.pieces.0={ground(height, cell, kind)}", "--out", str(d), "--quiet",
                        "--no-plots", "--no-replay"], check=True, capture_output=True)
    summary = json.loads((d / "summary.json").read_text())
    bodies = np.genfromtxt(d / "bodies.csv", delimiter=",", names=True)
    return summary, bodies


def rms_mm(a, b):
    """The middle body's RMS position difference (mm), b read at a's times."""
    t_end = min(a["t_s"][-1], b["t_s"][-1])
    keep = a["t_s"] <= t_end
    diff = [a[c][keep] - np.interp(a["t_s"][keep], b["t_s"], b[c]) for c in ("middlex_m", "middley_m", "middlez_m")]
    return 1e3 * float(np.sqrt(np.mean(sum(x * x for x in diff))))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--build", default="build", type=pathlib.Path)
    p.add_argument("--out", required=True, type=pathlib.Path)
    p.add_argument("--workers", default=2, type=int)
    p.add_argument("--storage", default="compact", choices=("compact", "stored"),
                   help="the sampled ledge as a compact field (default) or as stored prisms")
    p.add_argument("--engines", default=",".join(MODES), help="comma-separated (default: every engine)")
    p.add_argument("--cells", default=",".join(CELLS), help="comma-separated cells (m), of " + ",".join(CELLS))
    args = p.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    field = "field" if args.storage == "compact" else "prisms"
    engines, cells = args.engines.split(","), args.cells.split(",")
    for name, chosen, known in (("engine", engines, MODES), ("cell", cells, CELLS)):
        unknown = [x for x in chosen if x not in known]
        if unknown:
            p.error(f"unknown {name} {unknown[0]!r} (known: {', '.join(known)})")
    cases = [(h, c, e, m) for h in HEIGHTS for c in cells for e in engines for m in MODES[e]]
    with concurrent.futures.ThreadPoolExecutor(args.workers) as pool:
        futures = {(case, kind): pool.submit(run, args.build, args.out, *case, kind)
                   for case in cases for kind in (field, "mesh")}
        results = {key: f.result() for key, f in futures.items()}
    rows, failed = [], 0
    for case in cases:
        (fs, fb), (ms, mb) = results[(case, field)], results[(case, "mesh")]
        row = dict(zip(("height_m", "cell_m", "engine", "mode"), case), field_climbed=bool(fs["success"]),
                   mesh_climbed=bool(ms["success"]), rms_mm=rms_mm(fb, mb), field_rtf=fs["real_time_factor"],
                   mesh_rtf=ms["real_time_factor"], field_wtc_share=fs["wtc_share"])
        row["ok"] = row["field_climbed"] and row["mesh_climbed"] and row["rms_mm"] <= BOUND_MM
        failed += not row["ok"]
        rows.append(row)
    (args.out / "sampled_ledge.json").write_text(json.dumps(rows, indent=1))
    lines = [f"| ledge | cell | engine | mode | {field} climbs | mesh climbs | RMS {field} - mesh (mm) | "
             f"x real time, {field} / mesh |", "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['height_m']} m | {CELLS[r['cell_m']]} cm | {r['engine']} | {r['mode']} | "
                     f"{'yes' if r['field_climbed'] else 'no'} | {'yes' if r['mesh_climbed'] else 'no'} | "
                     f"{r['rms_mm']:.2f} | {r['field_rtf']:.1f} / {r['mesh_rtf']:.1f} |")
    (args.out / "sampled_ledge.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    print(f"{len(rows) - failed} of {len(rows)} within {BOUND_MM} mm with both climbing")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
