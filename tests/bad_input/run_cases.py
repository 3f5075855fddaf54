#!/usr/bin/env python3
"""Runs every bad-input case of docs/bad-input.md: one table, one loop.

The table between the markers `<!-- cases: begin -->` and `<!-- cases: end -->`
is the case list itself: each row's command is run as a user would type it from
the repository's root (with wtc-sim, wtc-study and wtc-mobility on PATH, through bash, in a
scratch directory that links the repository's folders, so that nothing is
written into the tree), and its exit status and the message excerpt on stderr
are checked. A row whose status is `pending: row N` (a fix made on another
branch) is skipped and said; --run-pending runs those too (for the lead, after
merging). The file also checks that every file in tests/bad_input is used by a
case, and that every test the library table names exists, so that the document
and the behaviour cannot drift apart.

usage: run_cases.py --wtc-sim PATH --wtc-study PATH --wtc-mobility PATH --source DIR [--run-pending] [--only ID]
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile

CASES_BEGIN = "<!-- cases: begin -->"
CASES_END = "<!-- cases: end -->"
LIBRARY_BEGIN = "<!-- library: begin -->"
LIBRARY_END = "<!-- library: end -->"
# The repository's folders a command may name (linked into the scratch directory).
LINKED = ("scenes", "terrains", "vehicles", "tests", "fuzz", "bench")
TIMEOUT_S = 120
CASES_DIR = os.path.join("tests", "bad_input")


def cells(line):
    """The cells of a markdown table row; `\\|` is a `|` inside a cell."""
    parts = re.split(r"(?<!\\)\|", line.strip().strip("|"))
    return [p.strip().replace("\\|", "|") for p in parts]


def code(cell):
    """A cell's text without the backticks around it."""
    return cell[1:-1] if len(cell) >= 2 and cell[0] == "`" and cell[-1] == "`" else cell


def table(text, begin, end):
    """The rows (lists of cells) of the table between two markers, header excluded."""
    if begin not in text or end not in text:
        sys.exit(f"docs/bad-input.md: markers {begin} ... {end} not found")
    lines = [l for l in text.split(begin, 1)[1].split(end, 1)[0].splitlines() if l.strip().startswith("|")]
    header = cells(lines[0])
    rows = [cells(l) for l in lines[2:]]  # lines[1] is the |---| separator
    for row in rows:
        if len(row) != len(header):
            sys.exit(f"docs/bad-input.md: row with {len(row)} cells, the header has {len(header)}: {row}")
    return header, rows


def scratch(source):
    """A directory holding links to the repository's folders: commands run there."""
    work = tempfile.mkdtemp(prefix="wtc_bad_input_")
    for name in LINKED:
        os.symlink(os.path.join(source, name), os.path.join(work, name))
    return work


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--wtc-sim", required=True)
    parser.add_argument("--wtc-study", required=True)
    parser.add_argument("--wtc-mobility", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--run-pending", action="store_true")
    parser.add_argument("--only", help="run the case of this id only")
    args = parser.parse_args()
    source = os.path.abspath(args.source)
    with open(os.path.join(source, "docs", "bad-input.md")) as f:
        text = f.read()
    failures = []

    header, rows = table(text, CASES_BEGIN, CASES_END)
    expected_header = ["case", "input", "bad form", "reproduce", "exit", "message excerpt (stderr)", "status"]
    if [h.split(" (from")[0] for h in header] != expected_header:
        sys.exit(f"docs/bad-input.md: case table header {header}, expected {expected_header}")
    ids = [r[0] for r in rows]
    duplicates = sorted({i for i in ids if ids.count(i) > 1})
    if duplicates:
        failures.append(f"case ids used twice: {duplicates}")

    env = dict(os.environ)
    programs = (args.wtc_sim, args.wtc_study, args.wtc_mobility)
    env["PATH"] = os.pathsep.join([os.path.dirname(os.path.abspath(p)) for p in programs] + [env.get("PATH", "")])
    work = scratch(source)
    ran = skipped = 0
    for case, _, _, command, exit_text, excerpt, status in rows:
        if args.only and case != args.only:
            continue
        command, excerpt = code(command), code(excerpt)
        pending = status.startswith("pending")
        if pending and not args.run_pending:
            print(f"skip {case} ({status}: enable it after merging that fix)")
            skipped += 1
            continue
        if not (status == "checked" or pending):
            failures.append(f"{case}: status '{status}' (expected 'checked' or 'pending: row N')")
            continue
        try:
            r = subprocess.run(["bash", "-c", command], cwd=work, env=env, input="", capture_output=True, text=True,
                               timeout=TIMEOUT_S)
            code_seen, stderr = r.returncode, r.stderr
        except subprocess.TimeoutExpired:
            code_seen, stderr = None, f"(no end after {TIMEOUT_S} s)"
        ran += 1
        ok = code_seen == int(exit_text) and excerpt in stderr
        print(("ok   " if ok else "FAIL ") + f"{case}: {command}")
        if not ok:
            failures.append(f"{case}: `{command}`\n    expected exit {exit_text} and stderr containing: {excerpt}\n"
                            f"    got exit {code_seen}, stderr:\n      " + stderr.strip().replace("\n", "\n      "))

    if not args.only:
        # Every file of tests/bad_input is some case's (or another case file's).
        folder = os.path.join(source, CASES_DIR)
        own = {"run_cases.py", "CMakeLists.txt"}
        files = {}
        for name in sorted(set(os.listdir(folder)) - own):
            with open(os.path.join(folder, name), errors="replace") as f:
                files[name] = f.read()
        for name in files:
            if name not in text and not any(name in t for other, t in files.items() if other != name):
                failures.append(f"{CASES_DIR}/{name} is used by no case of docs/bad-input.md")
        # Every test the library table names exists.
        sources = ""
        for root, _, files in os.walk(os.path.join(source, "tests")):
            for n in files:
                if n.endswith((".cpp", ".txt", ".py")):
                    with open(os.path.join(root, n), errors="replace") as f:
                        sources += f.read()
        _, library = table(text, LIBRARY_BEGIN, LIBRARY_END)
        for row in library:
            for name in filter(None, (n.strip() for n in row[-1].split(","))):
                suite, _, test = name.partition(".")
                found = re.search(r"TEST(_F|_P)?\(\s*" + re.escape(suite) + r",\s*" + re.escape(test) + r"\)",
                                  sources) or f"NAME {name}" in sources
                if not found:
                    failures.append(f"library table: test {name} not found in tests/")

    for name in LINKED:  # the links first: nothing of the repository is removed through them
        os.unlink(os.path.join(work, name))
    shutil.rmtree(work)

    print(f"{ran} cases run, {skipped} pending skipped, {len(failures)} failures")
    for f in failures:
        print("FAIL " + f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
