#!/usr/bin/env python3
"""Every benchmark table of docs/performance.md, from one build, in one command.

    cmake --build build -j2 --target wtc_benchmarks
    python3 tools/bench_tables.py --build build

runs the benchmark programs one after another (each alone on the machine:
run it on a quiet one), keeps each one's JSON output in docs/bench/, and
writes each table into docs/performance.md between its markers

    <!-- bench:NAME -->
    ...
    <!-- /bench:NAME -->

with a line that says the date, the build's commit, the CPU it ran on
(`lscpu`'s model name, or /proc/cpuinfo's) and the command that made it:
absolute times compare only on one CPU (the same build measured about 1.7x
slower on an AMD EPYC than on an Intel Xeon), ratios within a table do.
`--only query,sim` runs some of them; `--from-json` rewrites the tables
from the JSON already in docs/bench/ without running anything. The
prose around the tables quotes some figures: read it again after a run.
Standard library only (the table layouts of query, wheel and forces are
tools/bench_table.py's).
"""
import argparse
import datetime
import json
import os
import re
import subprocess
import sys
from collections import defaultdict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench_table as bt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
AGGREGATES = ["--benchmark_report_aggregates_only=true"]


def fmt_us(ns):
    """ns as µs with three significant digits, or ns below 1 µs."""
    if ns is None:
        return "–"
    if ns < 1e3:
        return f"{ns:.0f} ns"
    us = ns / 1e3
    return f"{us:.2f} µs" if us < 10 else (f"{us:.1f} µs" if us < 100 else f"{us:.0f} µs")


def fmt_ms(ns):
    if ns is None:
        return "–"
    ms = ns / 1e6
    if ms >= 1e3:
        return f"{ms / 1e3:.1f} s"
    return f"{ms:.3f} ms" if ms < 0.1 else (f"{ms:.2f} ms" if ms < 10 else f"{ms:.0f} ms")


def fmt_cells(n):
    """10⁴, 2·10⁴, or n itself."""
    exponent = len(str(n)) - 1
    lead, power = divmod(n, 10**exponent)
    if power:
        return f"{n:,}"
    superscript = str(exponent).translate(str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹"))
    return ("" if lead == 1 else f"{lead}·") + f"10{superscript}"


def index_runs(runs):
    """{tuple of the name's parts without iterations/min_time/real_time: (ns, counters)}."""
    out = {}
    for name, value in runs.items():
        parts = tuple(p for p in name.split("/")
                      if not p.startswith(("iterations:", "min_time:", "repeats:")) and p not in ("real_time",
                                                                                                "manual_time"))
        out[parts] = value
    return out


def compact_tables(runs):
    """Build/Contacts (heightfield) and MeshBuild/MeshContacts (mesh) of wtc_bench_compact."""
    r = index_runs(runs)
    ns = lambda *k: r[k][0] if k in r else None
    counter = lambda key, *k: r[k][1].get(key) if k in r else None

    def sizes(family):
        return sorted({int(k[2]) for k in r if k[0] == family and k[1] == "compact"})

    field = ["| cells | bytes per cell: compact / stored prisms / Bullet / FCL | build: compact / prisms / Bullet / FCL "
             "| contact step rolling: compact / prisms | contact step cold: compact / prisms "
             "| cylinder contacts rolling / cold: Bullet · FCL |", "|---:|---:|---:|---:|---:|---:|"]
    for n in sizes("Build"):
        s = str(n)
        byte = lambda m: counter("bytes_per_cell", "Build", m, s, s)
        build = lambda m: ns("Build", m, s, s)
        steps = lambda motion, *methods: " / ".join(fmt_us(ns("Contacts", m, s, motion, s)) for m in methods)
        field.append(
            f"| {fmt_cells(n)} | " + " / ".join("–" if byte(m) is None else f"{byte(m):.2f}" if byte(m) < 100
                                                else f"{byte(m):.0f}" for m in ("compact", "prisms", "bullet", "fcl"))
            + " | " + " / ".join(fmt_ms(build(m)) for m in ("compact", "prisms", "bullet", "fcl"))
            + f" | {steps('rolling', 'compact', 'prisms')} | {steps('cold', 'compact', 'prisms')}"
            + f" | {steps('rolling', 'bullet')} / {steps('cold', 'bullet')}"
            + f" · {steps('rolling', 'fcl')} / {steps('cold', 'fcl')} |")
    mesh = ["| cells (triangles) | bytes a triangle: compact (triangles + vertices, index) / stored / Bullet | build: compact / stored / Bullet "
            "| contact step rolling: compact / stored | contact step cold: compact / stored "
            "| cylinder contacts rolling / cold: Bullet |", "|---:|---:|---:|---:|---:|---:|"]
    for n in sizes("MeshBuild"):
        s = str(n)
        byte = lambda m: counter("bytes_per_triangle", "MeshBuild", m, s, s)
        index = counter("index_bytes_per_triangle", "MeshBuild", "compact", s, s)
        steps = lambda motion, *methods: " / ".join(fmt_us(ns("MeshContacts", m, s, motion, s)) for m in methods)
        fmt_b = lambda b: "–" if b is None else f"{b:.1f}" if b < 100 else f"{b:.0f}"
        mesh.append(
            f"| {fmt_cells(n)} ({fmt_cells(2 * n)}) | {fmt_b(byte('compact'))} "
            f"({fmt_b(None if index is None else byte('compact') - index)}, {fmt_b(index)}) / "
            f"{fmt_b(byte('prisms'))} / {fmt_b(byte('bullet'))} | "
            + " / ".join(fmt_ms(ns("MeshBuild", m, s, s)) for m in ("compact", "prisms", "bullet"))
            + f" | {steps('rolling', 'compact', 'prisms')} | {steps('cold', 'compact', 'prisms')}"
            + f" | {steps('rolling', 'bullet')} / {steps('cold', 'bullet')} |")
    return field, mesh


def engine_step_table(runs):
    """BulletStep/OdeStep of wtc_bench_bullet and wtc_bench_ode: one engine step of the wheel scene."""
    r = index_runs(runs)
    lines = ["| engine | the engine's own wheel contact | WTC, force mode | WTC, constraint mode |", "|---|---:|---:|---:|"]
    for family, label in (("BulletStep", "Bullet (`stepSimulation`)"), ("OdeStep", "ODE (`dWorldQuickStep`)")):
        native = r.get((family, "native"), (None,))[0]
        if native is None:
            continue
        cell = lambda m: ("–" if (family, m) not in r else
                          f"{fmt_us(r[(family, m)][0])} ({native / r[(family, m)][0]:.1f}× less)")
        lines.append(f"| {label} | {fmt_us(native)} | {cell('wtc_force')} | {cell('wtc_constraint')} |")
    return lines


def sim_table(runs):
    """robot_rough/robot_floor of wtc_bench_sim: a whole step of the robot against its contact-free floor."""
    r = index_runs(runs)
    labels = {"bullet": "Bullet (`btMultiBody`)", "ode": "ODE (`dWorldStep`)",
              "ode_quick": "ODE (`dWorldQuickStep`, 50 iterations)"}
    lines = ["| engine | WTC force mode | WTC constraint mode | WTC implicit mode | engine's cylinders "
             "| engine's spheres | contact-free floor |", "|---|---:|---:|---:|---:|---:|---:|"]
    for engine, label in labels.items():
        floor = r.get(("robot_floor", engine))
        if floor is None:
            continue

        def cell(mode, share):
            key = ("robot_rough", engine, mode)
            if key not in r:
                return "–"
            ns, counters = r[key]
            inside = f", {counters['wtc_share']:.0%} in WTC" if share and "wtc_share" in counters else ""
            return f"{fmt_us(ns)} ({ns / floor[0]:.2f}×{inside})"

        factor = floor[1].get("real_time_factor")
        lines.append(f"| {label} | {cell('force', True)} | {cell('constraint', True)} | {cell('implicit', True)} "
                     f"| {cell('engine_cylinder', False)} | {cell('engine_sphere', False)} "
                     f"| {fmt_us(floor[0])}" + (f" ({factor:.0f}× real time)" if factor else "") + " |")
    return lines


# name: (programs with their arguments, time column, {doc block: table lines}
# of the runs). The arguments are the ones the docs give; `wheel` and
# `compact` are single runs (their 10^6..10^8-piece builds take minutes).
BENCHES = {
    "query": ([["wtc_bench_query", "--benchmark_repetitions=3", *AGGREGATES]], "cpu",
              lambda runs: {"query": bt.point_query_table(runs)}),
    "wheel": ([["wtc_bench_wheel"]], "cpu", lambda runs: {"wheel": bt.wheel_table(runs)}),
    "compact": ([["wtc_bench_compact"]], "cpu",
                lambda runs: dict(zip(("compact", "compact_mesh"), compact_tables(runs)))),
    "forces": ([["wtc_bench_forces", "--benchmark_repetitions=5", *AGGREGATES]], "cpu",
               lambda runs: {"forces": bt.forces_table(runs)}),
    "engine_step": ([["wtc_bench_bullet", "--benchmark_repetitions=3", *AGGREGATES],
                     ["wtc_bench_ode", "--benchmark_repetitions=3", *AGGREGATES]], "cpu",
                    lambda runs: {"engine_step": engine_step_table(runs)}),
    "sim": ([["wtc_bench_sim", "--benchmark_repetitions=3", *AGGREGATES]], "real",
            lambda runs: {"sim": sim_table(runs)}),
}


def git(*args):
    return subprocess.run(["git", "-C", ROOT, *args], capture_output=True, text=True).stdout.strip()


def run_bench(build, name, programs, json_dir):
    """Runs the programs, merges their benchmarks into one JSON document, keeps it in json_dir."""
    merged = None
    for program in programs:
        path = os.path.join(build, "bench", program[0])
        if not os.path.exists(path):
            sys.exit(f"bench_tables.py: {path} is missing: build it first "
                     f"(cmake --build {build} -j2 --target {program[0]})")
        print(f"[{datetime.datetime.now():%H:%M:%S}] {name}: {' '.join(program)}", file=sys.stderr, flush=True)
        out = subprocess.run([path, *program[1:], "--benchmark_format=json"], capture_output=True, text=True)
        if out.returncode != 0:
            sys.exit(f"bench_tables.py: {program[0]} failed (exit {out.returncode}):\n{out.stderr[-2000:]}")
        data = json.loads(out.stdout)
        if merged is None:
            merged = data
        else:
            merged["benchmarks"] += data["benchmarks"]
    # Changes to the docs (this program writes them) do not change the build.
    dirty = bool(git("status", "--porcelain", "--", ".", ":!docs", ":!*.md"))
    merged["wtc"] = {"commit": git("rev-parse", "--short", "HEAD"), "dirty": dirty,
                     "date": datetime.date.today().isoformat(), "cpu": bt.cpu_model(), "cores": os.cpu_count(),
                     "commands": [" ".join(["build/bench/" + p[0], *p[1:]]) for p in programs]}
    with open(os.path.join(json_dir, f"{name}.json"), "w") as f:
        json.dump(merged, f, indent=1)
    return merged


def block(name, bench, data, table):
    meta = data["wtc"]
    commit = meta["commit"] + (" with uncommitted changes" if meta.get("dirty") else "")
    cpu = bt.recorded_cpu(data)
    cpu = f"CPU: {cpu}" if cpu else "CPU not recorded"
    cores = f", {meta['cores']} cores" if meta.get("cores") else ""
    stamp = (f"*{meta['date']}, build `{commit}`, {cpu}{cores}; "
             f"`python3 tools/bench_tables.py --only {bench}` ran "
             + "; ".join(f"`{c}`" for c in meta["commands"]) + f"; JSON in `docs/bench/{bench}.json`.*")
    body = "\n".join(table)
    return f"<!-- bench:{name} -->\n{stamp}\n\n{body}\n<!-- /bench:{name} -->"


def block_pattern(name):
    return re.compile(rf"<!-- bench:{name} -->.*?<!-- /bench:{name} -->", re.S)


def write_blocks(doc_path, blocks):
    with open(doc_path) as f:
        text = f.read()
    for name, content in blocks.items():
        if not block_pattern(name).search(text):
            sys.exit(f"bench_tables.py: {doc_path} has no <!-- bench:{name} --> ... <!-- /bench:{name} --> block")
        text = block_pattern(name).sub(lambda _: content, text)
    with open(doc_path, "w") as f:
        f.write(text)


def check_blocks(doc_path, blocks):
    """Whether each table in the doc is the one its JSON gives (no table edited by hand, none stale)."""
    with open(doc_path) as f:
        text = f.read()
    wrong = []
    for name, content in blocks.items():
        found = block_pattern(name).search(text)
        if not found:
            wrong.append(f"{doc_path}: no <!-- bench:{name} --> block")
        elif found.group(0) != content:
            wrong.append(f"{doc_path}: the table in <!-- bench:{name} --> is not what docs/bench/*.json gives "
                         f"(edited by hand, or the JSON changed): run python3 tools/bench_tables.py --from-json")
    for line in wrong:
        print(line, file=sys.stderr)
    return not wrong


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"), help="the build directory (default: build)")
    parser.add_argument("--only", help="comma-separated: " + ", ".join(BENCHES))
    parser.add_argument("--from-json", action="store_true", help="tables from docs/bench/*.json, nothing run")
    parser.add_argument("--check", action="store_true",
                        help="only check that the doc's tables are what docs/bench/*.json gives (exit 1 if not)")
    parser.add_argument("--doc", default=os.path.join(ROOT, "docs", "performance.md"))
    args = parser.parse_args()
    names = args.only.split(",") if args.only else list(BENCHES)
    unknown = [n for n in names if n not in BENCHES]
    if unknown:
        sys.exit(f"bench_tables.py: --only: unknown {', '.join(unknown)} (known: {', '.join(BENCHES)})")
    json_dir = os.path.join(ROOT, "docs", "bench")
    os.makedirs(json_dir, exist_ok=True)
    blocks = {}
    for name in names:
        programs, time, tables = BENCHES[name]
        if args.from_json or args.check:
            path = os.path.join(json_dir, f"{name}.json")
            if not os.path.exists(path):
                sys.exit(f"bench_tables.py: {path} is missing: run python3 tools/bench_tables.py --only {name}")
            with open(path) as f:
                data = json.load(f)
        else:
            data = run_bench(args.build, name, programs, json_dir)
        for block_name, table in tables(bt.load_runs(data, f"{time}_time")).items():
            blocks[block_name] = block(block_name, name, data, table)
    if args.check:
        sys.exit(0 if check_blocks(args.doc, blocks) else 1)
    write_blocks(args.doc, blocks)


if __name__ == "__main__":
    main()
