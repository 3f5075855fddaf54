#!/usr/bin/env python3
"""Markdown tables from `wtc_bench_query`, `wtc_bench_wheel` or `wtc_bench_forces` JSON output.

    build/bench/wtc_bench_query --benchmark_repetitions=5 \
        --benchmark_report_aggregates_only=true --benchmark_format=json > bench.json
    python3 tools/bench_table.py bench.json

Prints two tables for the README:
  1. PointQuery: one row per shape/set; median ns/query of wtc (and wtc with
     max_distance), bullet, fcl, brute; the speed-ups bullet/wtc and fcl/wtc;
     the max signed-distance error against brute force (x piece size) and the
     failure counts wtc/bullet/fcl.
  2. PointQueryTolerance: ns/query, max distance error and max closest-point
     error per relative tolerance.
For `wtc_bench_wheel`, one table of the contact step, the indexes and the
build per terrain and size. For `wtc_bench_forces`, one table of the tyre
model per effect set (minimal, each effect alone, full): median ns/step of
WheelForces (contacts + forces) and WheelForcesOnly (forces alone), each with
its difference to minimal, then the contact counts and heap allocations.
Times are medians over repetitions (the `median` aggregate when present,
otherwise the median of the individual runs). Above the tables, the CPU the
times were measured on: the one the JSON records (tools/bench_tables.py's
JSON does), else `--cpu`, else this machine's (`lscpu`'s model name, or
/proc/cpuinfo's), said on stderr. Absolute times only compare on one CPU.
Standard library only.
"""
import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
from collections import defaultdict

METHODS = ["wtc", "wtc_maxdist", "wtc_gjk", "bullet", "fcl", "brute"]
SCALE_TO_NS = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}


def cpu_model():
    """This machine's CPU: `lscpu`'s "Model name", else /proc/cpuinfo's "model name"."""
    try:
        out = subprocess.run(["lscpu"], capture_output=True, text=True, timeout=30,
                             env={**os.environ, "LC_ALL": "C"}).stdout
        for line in out.splitlines():
            key, _, value = line.partition(":")
            if key.strip() == "Model name" and value.strip():
                return value.strip()
    except (OSError, subprocess.SubprocessError):
        pass
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def recorded_cpu(data):
    """The CPU a benchmark JSON says it ran on (tools/bench_tables.py records it), or None."""
    return (data.get("wtc") or {}).get("cpu")


def load_runs(data, time_key):
    """{run name: (median ns, counters of the run)}."""
    samples = defaultdict(list)
    medians = {}
    for b in data["benchmarks"]:
        name = b.get("run_name", b["name"])
        ns = b[time_key] * SCALE_TO_NS[b.get("time_unit", "ns")]
        if b.get("run_type") == "aggregate":
            if b.get("aggregate_name") == "median":
                medians[name] = (ns, b)
        else:
            samples[name].append((ns, b))
    runs = {name: (statistics.median(ns for ns, _ in s), s[0][1]) for name, s in samples.items()}
    runs.update(medians)  # the library's own median wins
    return runs


def fmt_ns(ns):
    return "–" if ns is None else (f"{ns:.1f}" if ns < 100 else f"{ns:.0f}")


def fmt_err(x):
    return "–" if x is None else ("0" if x == 0 else f"{x:.1e}")


def point_query_table(runs):
    rows = defaultdict(dict)  # (shape, set) -> method -> (ns, counters)
    order = []
    for name, value in runs.items():
        parts = name.split("/")
        if len(parts) == 4 and parts[0] == "PointQuery" and parts[1] in METHODS:
            key = (parts[2], parts[3])
            if key not in rows:
                order.append(key)
            rows[key][parts[1]] = value
    lines = [
        "| shape/set | wtc ns | wtc max_distance ns | plain GJK ns | bullet ns | fcl ns | brute ns "
        "| bullet/wtc | fcl/wtc | wtc error | bullet error | fcl error | failures wtc/bullet/fcl |",
        "|---|" + "---:|" * 12,
    ]
    for shape, qset in order:
        r = rows[(shape, qset)]
        ns = {m: r[m][0] if m in r else None for m in METHODS}
        err = {m: r[m][1].get("max_error") if m in r else None for m in METHODS}
        fails = "/".join(str(int(r[m][1].get("failures", 0))) if m in r else "–"
                         for m in ("wtc", "bullet", "fcl"))
        ratio = lambda m: f"{ns[m] / ns['wtc']:.1f}×" if ns[m] and ns["wtc"] else "–"
        lines.append(
            f"| {shape}/{qset} | {fmt_ns(ns['wtc'])} | {fmt_ns(ns['wtc_maxdist'])} | {fmt_ns(ns['wtc_gjk'])} "
            f"| {fmt_ns(ns['bullet'])} | {fmt_ns(ns['fcl'])} | {fmt_ns(ns['brute'])} "
            f"| {ratio('bullet')} | {ratio('fcl')} | {fmt_err(err['wtc'])} "
            f"| {fmt_err(err['bullet'])} | {fmt_err(err['fcl'])} | {fails} |")
    return lines


def tolerance_table(runs):
    cells = defaultdict(dict)  # tolerance -> shape -> (ns, counters)
    shapes = []
    for name, value in runs.items():
        parts = name.split("/")
        if len(parts) == 3 and parts[0] == "PointQueryTolerance":
            if parts[1] not in shapes:
                shapes.append(parts[1])
            cells[parts[2]][parts[1]] = value
    if not cells:
        return []
    header = "| relative tolerance | " + " | ".join(f"{s} ns | {s} error | {s} point error" for s in shapes) + " |"
    lines = [header, "|---|" + "---:|" * (3 * len(shapes))]
    for tol in sorted(cells, key=float, reverse=True):
        row = []
        for s in shapes:
            ns, counters = cells[tol].get(s, (None, {}))
            row += [fmt_ns(ns), fmt_err(counters.get("max_error")), fmt_err(counters.get("max_point_error"))]
        lines.append(f"| {tol} | " + " | ".join(row) + " |")
    return lines


def wheel_table(runs):
    """WheelQuery/WheelIndex/WheelContacts/TerrainBuild of wtc_bench_wheel."""
    rows = defaultdict(dict)  # (terrain, pieces, motion) -> column -> (ns, counters)
    order = []
    for name, value in runs.items():
        parts = name.split("/")
        if parts[0] in ("WheelQuery", "WheelIndex") and len(parts) >= 4:
            key, column = (parts[2], int(parts[3]), parts[4] if len(parts) > 4 else "rolling"), f"{parts[0]}/{parts[1]}"
        elif parts[0] == "WheelContacts" and len(parts) >= 3:
            key, column = (parts[1], int(parts[2]), parts[3] if len(parts) > 3 else "rolling"), "contacts"
        elif parts[0] == "TerrainBuild" and len(parts) >= 3:  # .../iterations:1/manual_time
            for motion in ("rolling", "cold"):
                rows[(parts[1], int(parts[2]), motion)]["build"] = value
            continue
        else:
            continue
        if key not in order:
            order.append(key)
        rows[key][column] = value
    if not order:
        return []
    lines = ["| terrain | pieces | wheel | contact step ns | query wtc / fcl / bullet ns | index wtc / fcl / bullet ns "
             "| index fcl/wtc | index bullet/wtc | bytes/piece (pieces + index) | build ms |",
             "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|"]
    for key in sorted(order, key=lambda k: (k[0], k[2] != "rolling", k[1])):
        r = rows[key]
        ns = lambda c: r[c][0] if c in r else None
        trio = lambda family: " / ".join(fmt_ns(ns(f"{family}/{i}")) for i in ("wtc", "fcl", "bullet"))
        ratio = lambda i: (f"{ns(f'WheelIndex/{i}') / ns('WheelIndex/wtc'):.1f}×"
                           if ns(f"WheelIndex/{i}") and ns("WheelIndex/wtc") else "–")
        any_run = next((v for c, v in r.items() if c != "build"), None)
        memory = (f"{any_run[1]['piece_bytes']:.0f} + {any_run[1]['index_bytes']:.0f}"
                  if any_run and "piece_bytes" in any_run[1] else "–")
        build = f"{r['build'][0] / 1e6:.0f}" if "build" in r else "–"
        lines.append(f"| {key[0]} | {key[1]:,} | {key[2]} | {fmt_ns(ns('contacts'))} | {trio('WheelQuery')} "
                     f"| {trio('WheelIndex')} | {ratio('fcl')} | {ratio('bullet')} | {memory} | {build} |")
    return lines


def fmt_delta(ns):
    return "–" if ns is None else (f"{ns:+.1f}" if abs(ns) < 100 else f"{ns:+.0f}")


def forces_table(runs):
    """WheelForces/WheelForcesOnly of wtc_bench_forces: one row per effect set."""
    families = ("WheelForces", "WheelForcesOnly")
    rows = defaultdict(dict)  # effects -> family -> (ns, counters)
    order = []
    for name, value in runs.items():
        parts = name.split("/")
        if len(parts) == 2 and parts[0] in families:
            if parts[1] not in order:
                order.append(parts[1])
            rows[parts[1]][parts[0]] = value
    if not order:
        return []
    order.sort(key=lambda e: (e == "full", e != "minimal"))  # minimal, single effects in run order, full
    ns = lambda e, family: rows[e][family][0] if family in rows[e] else None
    counter = lambda e, family, key: rows[e][family][1].get(key) if family in rows[e] else None

    def delta(e, family):
        if e == "minimal" or ns(e, family) is None or ns("minimal", family) is None:
            return "–"
        return fmt_delta(ns(e, family) - ns("minimal", family))

    def allocs(e):
        counts = [counter(e, f, "allocs_per_step") for f in families]
        return " / ".join("–" if c is None else f"{c:.1f}" for c in counts)

    lines = ["| effects | step ns | step − minimal ns | forces only ns | forces only − minimal ns "
             "| contacts/step | steps with ≥ 2 contacts | heap allocs/step (step / forces only) |",
             "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for e in order:
        contacts = counter(e, "WheelForces", "contacts_per_step")
        multi = counter(e, "WheelForces", "multi_contact_fraction")
        lines.append(f"| {e} | {fmt_ns(ns(e, 'WheelForces'))} | {delta(e, 'WheelForces')} "
                     f"| {fmt_ns(ns(e, 'WheelForcesOnly'))} | {delta(e, 'WheelForcesOnly')} "
                     f"| {'–' if contacts is None else f'{contacts:.2f}'} "
                     f"| {'–' if multi is None else f'{multi:.0%}'} | {allocs(e)} |")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("json", nargs="?", help="benchmark JSON (default: stdin)")
    parser.add_argument("--time", choices=["cpu", "real"], default="cpu",
                        help="time column to report (default: cpu)")
    parser.add_argument("--cpu", help="the CPU the JSON was measured on, when the JSON does not name it "
                                      "(default: this machine's, lscpu's model name)")
    args = parser.parse_args()
    with (open(args.json) if args.json else sys.stdin) as f:
        data = json.load(f)
    cpu = recorded_cpu(data) or args.cpu
    if not cpu:
        cpu = cpu_model()
        print(f"bench_table.py: the JSON names no CPU; printing this machine's ({cpu}): "
              f"give --cpu if it was measured on another", file=sys.stderr)
    print(f"*CPU: {cpu}*\n")
    runs = load_runs(data, f"{args.time}_time")
    wheel, forces = wheel_table(runs), forces_table(runs)
    if wheel or forces:
        print("\n\n".join("\n".join(table) for table in (wheel, forces) if table))
        return
    print("\n".join(point_query_table(runs)))
    tolerance = tolerance_table(runs)
    if tolerance:
        print("\nplain GJK on the mixed set by relative tolerance; errors x piece size, "
              "error: signed distance, point error: closest point (outside points)\n")
        print("\n".join(tolerance))


if __name__ == "__main__":
    main()
