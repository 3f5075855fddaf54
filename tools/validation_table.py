#!/usr/bin/env python3
"""The validation pack's table (docs/validation.md), regenerated from a run of the tests it lists.

usage: tools/validation_table.py [--build build] [--all] [--only ID ...] [--json FILE] [--no-write]
       tools/validation_table.py --check [--build build]

Reads tests/validation/checks.yaml (one entry per check whose answer is derived outside the
code), runs each entry's tests - the gtest binaries of the build directory, one run per binary
with the entries' filters and --gtest_output=json - and collects per check its pass/fail and
what the tests measured: the properties they record (RecordProperty) or the rows of the table
the cross-engine test prints. Then rewrites the table in docs/validation.md between its
markers. Entries marked `slow: true` (minutes) run only with --all; without it their measured
cell is kept from the table as it was.

--check runs nothing but each binary's --gtest_list_tests: every entry has its fields, every
filter pattern names at least one test, every study program exists, and docs/validation.md's
table has the same checks with the same columns as the list (all but `measured`). The test
suite runs it (ctest -R validation).

Exit status: 0 when every check run passed (and, with --check, the list and the doc agree);
1 otherwise. Standard library and PyYAML only.
"""
import argparse
import datetime
import fnmatch
import json
import os
import re
import subprocess
import sys
import tempfile

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CHECKS = os.path.join(ROOT, "tests", "validation", "checks.yaml")
DOC = os.path.join(ROOT, "docs", "validation.md")
BEGIN = "<!-- validation-table:begin (tools/validation_table.py writes this part) -->"
END = "<!-- validation-table:end -->"
REQUIRED = ["id", "check", "formula", "source", "kind", "engines", "modes", "tolerance"]
KINDS = {"statics", "dynamics", "conservation", "numerics", "law", "geometry", "published"}
HEADER = ["#", "check", "formula", "source", "engines / modes", "measured", "tolerance", "test"]
MEASURED_COLUMN = HEADER.index("measured")
# gtest's own fields of a test in its JSON output; everything else is a recorded property.
GTEST_FIELDS = {"name", "file", "line", "status", "result", "timestamp", "time", "classname", "failures",
                "value_param", "type_param"}
ENGINE_NAMES = {"core": "core", "core_loop": "core Euler loop", "bullet": "Bullet", "ode": "ODE",
                "ode_quick": "ODE quickstep", "mujoco": "MuJoCo"}
# The cross-engine table's names of the engines (tests/cross_engine/engine_sim.cpp, engineName).
TABLE_ENGINES = {"Bullet": "bullet", "ODE dWorldStep": "ode", "ODE dWorldQuickStep": "ode_quick", "MuJoCo": "mujoco"}


def engine_modes(check):
    """{engine: the modes the check holds it to, or None for the check's modes}: an entry of `engines` is an
    engine's name, or `name:mode` for an engine held to one mode of the check's (MuJoCo's constraint mode,
    whose friction is its soft cone's, where the check's band is the rigid cone's)."""
    out = {}
    for entry in check["engines"]:
        name, _, mode = entry.partition(":")
        out.setdefault(name, None if not mode else [])
        if mode:
            out[name].append(mode)
    return out


def engines_label(check):
    return ", ".join(ENGINE_NAMES.get(name, name) + (f" ({', '.join(modes)})" if modes else "")
                     for name, modes in engine_modes(check).items())


def fail(message):
    sys.exit(f"validation_table.py: {message}")


def load_checks(path):
    with open(path) as f:
        checks = yaml.safe_load(f)
    if not isinstance(checks, list):
        fail(f"{path}: expected a list of checks")
    problems, seen = [], set()
    for i, c in enumerate(checks):
        where = f"{os.path.relpath(path, ROOT)}: entry {i + 1} ({c.get('id', '?')})"
        for key in REQUIRED:
            if key not in c:
                problems.append(f"{where}: no '{key}'")
        if ("test" in c) == ("command" in c):
            problems.append(f"{where}: give either 'test' (with 'binary') or 'command'")
        if "test" in c and "binary" not in c:
            problems.append(f"{where}: 'test' without 'binary'")
        if c.get("kind") not in KINDS:
            problems.append(f"{where}: kind '{c.get('kind')}' is not one of {sorted(KINDS)}")
        if c.get("id") in seen:
            problems.append(f"{where}: id '{c['id']}' given twice")
        seen.add(c.get("id"))
        m = c.get("measured")
        if m is not None and not (("record" in m) or ("table" in m and "table_test" in m)):
            problems.append(f"{where}: measured needs 'record' or 'table' with 'table_test'")
    return checks, problems


def binaries(check):
    b = check.get("binary", [])
    return b if isinstance(b, list) else [b]


def patterns(filter_text):
    return [p for p in filter_text.split(":") if p]


def matches(name, filter_text):
    return any(fnmatch.fnmatchcase(name, p) for p in patterns(filter_text))


# ---------------------------------------------------------------- running the tests


def list_tests(binary):
    out = subprocess.run([binary, "--gtest_list_tests"], capture_output=True, text=True, check=True).stdout
    names, suite = [], None
    for line in out.splitlines():
        if not line.strip():
            continue
        if not line.startswith(" "):
            suite = line.split("#")[0].strip()
        else:
            names.append(suite + line.split("#")[0].strip())
    return names


def run_binary(binary, filters):
    """Runs the tests matching any of `filters`; returns ({full name: test record}, stdout)."""
    with tempfile.TemporaryDirectory(prefix="wtc_validation_") as work:
        report = os.path.join(work, "report.json")
        command = [binary, "--gtest_filter=" + ":".join(filters), "--gtest_output=json:" + report, "--gtest_color=no"]
        print("validation_table.py: running " + " ".join(command), file=sys.stderr, flush=True)
        done = subprocess.run(command, capture_output=True, text=True)
        if not os.path.exists(report):
            fail(f"{binary} wrote no report (exit {done.returncode}):\n{done.stdout[-2000:]}{done.stderr[-2000:]}")
        with open(report) as f:
            data = json.load(f)
    tests = {}
    for suite in data.get("testsuites", []):
        for t in suite.get("testsuite", []):
            tests[suite["name"] + "." + t["name"]] = t
    return tests, done.stdout


def cross_engine_rows(stdout, scene):
    """Rows `| scene | mode | other engine | Bullet | ODE | relative difference |` of the cross-engine table."""
    rows = []
    for line in stdout.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 6 and cells[0] == scene:
            rows.append(cells)
    return rows


def compact_number(text):
    try:
        return f"{float(text):.6g}"
    except ValueError:
        return text


def number(text):
    """The number a recorded value starts with ('1.024286 mm' -> 1.024286), or None."""
    match = re.match(r"\s*([-+0-9.eE]+)", str(text))
    try:
        return float(match.group(1)) if match else None
    except ValueError:
        return None


def deviation(m, values):
    """The measured values' worst deviation from the expected value: relative, or absolute at 0."""
    values = [v for v in values if v is not None]
    if not values:
        return "nothing to compare with the expected value"
    expected = float(m["expected"])
    worst = max(values, key=lambda v: abs(v - expected))
    if expected == 0.0:
        return f"expected 0: largest {worst:.3g}"
    return f"expected {expected:.6g}: worst {100 * (worst - expected) / abs(expected):+.2g} % ({worst:.6g})"


def short_param(full_name, filter_text):
    """The part of a parameterized test's name that tells its instances apart."""
    if "/" in full_name.split(".", 1)[-1]:
        return full_name.rsplit("/", 1)[-1]
    return full_name.split(".", 1)[-1] if len(patterns(filter_text)) > 1 else ""


def measure(check, tests, stdout_by_binary):
    """(passed, total, failure text, measured text) of one check from its tests' results."""
    chosen = {n: t for n, t in tests.items() if matches(n, check["test"])}
    failures = [(n, t) for n, t in chosen.items() if t.get("failures") or t.get("result") not in ("COMPLETED", None)]
    text, values = [], []
    m = check.get("measured") or {}
    if m.get("record"):
        keys = m["record"]
        for name in sorted(chosen):
            props = {k: v for k, v in chosen[name].items() if k not in GTEST_FIELDS}
            if keys != "all":
                props = {k: v for k, v in props.items() if k in keys}
            if not props:
                continue
            label = short_param(name, check["test"])
            values += [number(v) for k, v in props.items() if k in m.get("expected_keys", props)]
            body = "; ".join(f"{k} {compact_number(v)}" for k, v in props.items())
            text.append(f"{label}: {body}" if label else body)
    if m.get("table"):
        rows = []
        for out in stdout_by_binary.values():
            rows += cross_engine_rows(out, m["table"])
        by_mode = {}
        held = engine_modes(check)
        for scene, mode, other, bullet, ode, _ in rows:
            engine = TABLE_ENGINES.get(other, other)
            if engine not in held or (held[engine] is not None and mode not in held[engine]):
                continue
            per_engine = by_mode.setdefault(mode, {})
            if "bullet" in held and "Bullet" not in per_engine:
                per_engine["Bullet"] = bullet
                values.append(number(bullet))
            values.append(number(ode))
            per_engine[ENGINE_NAMES[engine]] = ode
        unit = m.get("unit", "")
        for mode, per_engine in by_mode.items():
            text.append(f"{mode}: " + ", ".join(f"{k} {compact_number(v)}" for k, v in per_engine.items()) +
                        (f" {unit}" if unit else ""))
    if m.get("expected") is not None:
        text.append(deviation(m, values))
    failure_text = ""
    if failures:
        name, t = failures[0]
        message = (t.get("failures") or [{}])[0].get("failure", t.get("result", "?"))
        failure_text = f"{name}: " + " ".join(message.split())[:300]
    return len(chosen) - len(failures), len(chosen), failure_text, text


def run_command(check, build):
    program = os.path.join(build, check["command"])
    print(f"validation_table.py: running {program}", file=sys.stderr, flush=True)
    done = subprocess.run([program], capture_output=True, text=True)
    rows = [line for line in done.stdout.splitlines() if line.startswith("| ") and not line.startswith("| scene")]
    ok = sum(1 for r in rows if r.rstrip().endswith("| yes |"))
    growth = []
    for r in rows:
        cells = [c.strip() for c in r.strip().strip("|").split("|")]
        if len(cells) >= 4:
            try:
                growth.append(float(cells[3]))
            except ValueError:
                pass
    text = [f"{ok} of {len(rows)} runs within the limits"]
    if growth:
        text.append(f"largest growth after step 1 {max(growth):.3g} J")
    failure_text = "" if done.returncode == 0 else f"exit status {done.returncode}"
    return (len(rows) if done.returncode == 0 else ok), len(rows), failure_text, text


# ---------------------------------------------------------------- the table


def cell(text):
    return str(text).replace("|", "\\|").replace("\n", " ")


def static_cells(c):
    engines = engines_label(c)
    modes = ", ".join(c["modes"]) if c["modes"] != ["none"] else "one model step" if c["engines"] == ["core"] else ""
    where = engines + (f"; {modes}" if modes else "")
    if "command" in c:
        test = f"`{c['command']}`"
    else:
        test = "<br>".join(f"`{p}`" for p in patterns(c["test"]))
    if c.get("slow"):
        test += " (slow: `--all`)"
    return [c["id"], c["check"], c["formula"], c["source"], where, None, c["tolerance"], test]


def row(cells):
    return "| " + " | ".join(cell(x) for x in cells) + " |"


def parse_table(text):
    """{id: [cells]} of the table between the markers (cells unescaped)."""
    rows = {}
    if BEGIN not in text or END not in text:
        return rows
    body = text.split(BEGIN, 1)[1].split(END, 1)[0]
    for line in body.splitlines():
        if not line.startswith("| ") or line.startswith("| #") or line.startswith("|---"):
            continue
        cells = [c.strip().replace("\\|", "|") for c in re.split(r"(?<!\\)\|", line.strip())[1:-1]]
        if len(cells) == len(HEADER):
            rows[cells[0]] = cells
    return rows


def measured_cell(result):
    passed, total, failure_text, text = result
    status = f"pass {passed}/{total}" if not failure_text else f"**FAIL** {total - passed}/{total}: {failure_text}"
    return status + ("; " + "; ".join(text) if text else "")


def render(checks, results, old_rows, stamp):
    lines = [BEGIN, "", stamp, "", row(HEADER), "|" + "---|" * len(HEADER)]
    for c in checks:
        cells = static_cells(c)
        if c["id"] in results:
            cells[MEASURED_COLUMN] = measured_cell(results[c["id"]])
        elif c["id"] in old_rows:
            cells[MEASURED_COLUMN] = old_rows[c["id"]][MEASURED_COLUMN]
        else:
            cells[MEASURED_COLUMN] = "not run yet (`--all`)" if c.get("slow") else "not run"
        lines.append(row(cells))
    lines += ["", END]
    return "\n".join(lines)


def git_commit():
    try:
        return subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                              check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


# ---------------------------------------------------------------- main


def check_only(checks, build, doc_path, no_commands=False):
    problems = []
    listed = {}
    for c in checks:
        if "command" in c:
            if not no_commands and not os.path.isfile(os.path.join(build, c["command"])):
                problems.append(f"{c['id']}: {c['command']} is not built in {build}")
            continue
        names = []
        for b in binaries(c):
            path = os.path.join(build, b)
            if not os.path.isfile(path):
                problems.append(f"{c['id']}: {b} is not built in {build}")
                continue
            if path not in listed:
                listed[path] = list_tests(path)
            names += listed[path]
        for p in patterns(c["test"]):
            if not any(fnmatch.fnmatchcase(n, p) for n in names):
                problems.append(f"{c['id']}: no test matches '{p}' in {', '.join(binaries(c))}")
        m = c.get("measured") or {}
        if m.get("table_test") and not any(matches(n, m["table_test"]) for n in names):
            problems.append(f"{c['id']}: no test matches its table_test '{m['table_test']}'")
    with open(doc_path) as f:
        old = parse_table(f.read())
    ids = [c["id"] for c in checks]
    for i in ids:
        if i not in old:
            problems.append(f"{os.path.relpath(doc_path, ROOT)}: no row for '{i}' (run tools/validation_table.py)")
    for i in old:
        if i not in ids:
            problems.append(f"{os.path.relpath(doc_path, ROOT)}: row '{i}' is not in checks.yaml")
    for c in checks:
        if c["id"] not in old:
            continue
        want = static_cells(c)
        have = old[c["id"]]
        for k, (w, h) in enumerate(zip(want, have)):
            if k != MEASURED_COLUMN and str(w).replace("\n", " ") != h:
                problems.append(f"{os.path.relpath(doc_path, ROOT)}: row '{c['id']}', column '{HEADER[k]}' differs "
                                f"from checks.yaml (run tools/validation_table.py)")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"), help="the build directory (default: build)")
    parser.add_argument("--all", action="store_true", help="run the slow checks too (minutes)")
    parser.add_argument("--only", nargs="+", metavar="ID", help="run these checks only")
    parser.add_argument("--check", action="store_true", help="check the list and the doc, run nothing")
    parser.add_argument("--no-commands", action="store_true",
                        help="with --check: do not ask for the study programs (a build without benchmarks)")
    parser.add_argument("--checks", default=CHECKS, help=argparse.SUPPRESS)
    parser.add_argument("--doc", default=DOC, help=argparse.SUPPRESS)
    parser.add_argument("--json", metavar="FILE", help="also write the results as JSON")
    parser.add_argument("--no-write", action="store_true", help="print the table instead of writing the doc")
    args = parser.parse_args()
    build = os.path.abspath(args.build)
    checks, problems = load_checks(args.checks)
    if problems:
        fail("\n  ".join(["the list of checks is malformed:"] + problems))
    if args.check:
        problems = check_only(checks, build, args.doc, args.no_commands)
        for p in problems:
            print(f"validation_table.py: {p}", file=sys.stderr)
        print(f"validation_table.py: {len(checks)} checks, {len(problems)} problems")
        return 1 if problems else 0

    selected = [c for c in checks if (args.all or not c.get("slow")) and (not args.only or c["id"] in args.only)]
    if args.only:
        unknown = set(args.only) - {c["id"] for c in checks}
        if unknown:
            fail(f"unknown check ids: {', '.join(sorted(unknown))}")
    by_binary = {}
    for c in selected:
        for b in binaries(c):
            filters = by_binary.setdefault(b, [])
            filters += patterns(c["test"])
            if (c.get("measured") or {}).get("table_test"):
                filters.append(c["measured"]["table_test"])
    tests, stdout = {}, {}
    for b, filters in by_binary.items():
        path = os.path.join(build, b)
        if not os.path.isfile(path):
            fail(f"{path} is not built (cmake --build {os.path.relpath(build, ROOT)} -j2)")
        found, out = run_binary(path, sorted(set(filters)))
        tests.update(found)
        stdout[b] = out
    results = {}
    for c in selected:
        if "command" in c:
            results[c["id"]] = run_command(c, build)
        else:
            results[c["id"]] = measure(c, tests, {b: stdout[b] for b in binaries(c)})
            if results[c["id"]][1] == 0:
                results[c["id"]] = (0, 0, "no test ran (the filter matches nothing)", [])

    with open(args.doc) as f:
        doc = f.read()
    old_rows = parse_table(doc)
    ran = "every check" if args.all and not args.only else ("the checks " + ", ".join(args.only) if args.only else
                                                            "every check but the slow ones, whose cells are from the last `--all` run")
    stamp = (f"Measured {datetime.date.today().isoformat()} at commit {git_commit()} by "
             f"`tools/validation_table.py{' --all' if args.all else ''}` ({ran}).")
    table = render(checks, results, old_rows, stamp)
    if args.no_write:
        print(table)
    elif BEGIN in doc and END in doc:
        before, rest = doc.split(BEGIN, 1)
        after = rest.split(END, 1)[1]
        with open(args.doc, "w") as f:
            f.write(before + table + after)
    else:
        fail(f"{args.doc} has no markers '{BEGIN}' ... '{END}'")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({k: {"passed": v[0], "total": v[1], "failure": v[2], "measured": v[3]} for k, v in results.items()},
                      f, indent=1)
    failed = [k for k, v in results.items() if v[2]]
    print(f"validation_table.py: {len(results)} checks run, {len(failed)} failed" +
          (": " + ", ".join(failed) if failed else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
