#!/usr/bin/env python3
"""wtc-sim as a user's shell sees it: bad command lines are refused before anything runs, a run
never reuses an earlier run's directory, and an interrupted or killed run leaves whole CSV rows
and a summary that says it did not finish.

usage: wtc_sim_cli_test.py WTC_SIM SOURCE_DIR
"""
import csv
import json
import os
import signal
import subprocess
import sys
import tempfile
import time

FAILURES = []


def check(condition, message):
    print(("ok   " if condition else "FAIL ") + message)
    if not condition:
        FAILURES.append(message)


def main():
    wtc_sim, source = sys.argv[1:3]
    scene = os.path.join(source, "scenes/robot_rough.yaml")
    work = tempfile.mkdtemp(prefix="wtc_sim_cli_")
    os.chdir(work)

    # Bad command lines: exit 2 with the problem named, nothing written.
    for args, expected in ((["--set", "dt=-1"], "dt: must be > 0 s"),
                           (["--set", "no_such_key=1"], "unknown key 'no_such_key'"),
                           (["--engine", "physx"], "unknown engine 'physx'"),
                           (["--set", "garbage"], "expected key.path=value")):
        r = subprocess.run([wtc_sim, scene, *args, "--out", "bad", "--no-plots"], capture_output=True, text=True)
        check(r.returncode == 2 and expected in r.stderr, f"{' '.join(args)} refused, naming '{expected}'")
    # A small step given on the command line reaches the scene exactly (it
    # was once printed with six decimals: 1e-7 became 0 and was refused).
    r = subprocess.run([wtc_sim, scene, "--dt", "2.5e-7", "--duration", "1e-6", "--out", "tiny_step", "--no-plots",
                        "--quiet"], capture_output=True, text=True)
    with open(os.path.join("tiny_step", "summary.json")) as f:
        tiny = json.load(f)
    check(r.returncode in (0, 1) and tiny["dt"] == 2.5e-7 and tiny["steps"] == 4, "--dt 2.5e-7 runs 4 steps of 2.5e-7 s")
    # A step too large for the explicit tyre spring is said on stderr as it
    # happens (once per wheel, with its numbers), even with --quiet.
    r = subprocess.run([wtc_sim, scene, "--dt", "0.01", "--duration", "0.05", "--out", "big_step", "--no-plots",
                        "--quiet"], capture_output=True, text=True)
    said = [line for line in r.stderr.splitlines() if "largest stable step" in line and "first at this step" in line]
    check(len(said) == 6, f"--dt 0.01: one stderr line per wheel on its first unstable step (got {len(said)})")
    r = subprocess.run([wtc_sim, os.path.join(work, "missing.yaml")], capture_output=True, text=True)
    check(r.returncode == 2 and "missing.yaml" in r.stderr and "not found" in r.stderr, "a missing scene file is named")
    check(not os.path.exists("bad"), "nothing is written for a refused command line")

    # Never an earlier run's directory: default names count up; --out must be new or empty.
    for _ in range(2):
        r = subprocess.run([wtc_sim, scene, "--duration", "0.05", "--no-plots", "--quiet"])
        check(r.returncode in (0, 1), "a short run ends (0: success, 1: its criterion failed)")
    check(os.path.isdir("runs/robot_rough_bullet_force") and os.path.isdir("runs/robot_rough_bullet_force_2"),
          "a second run goes to runs/robot_rough_bullet_force_2")
    r = subprocess.run([wtc_sim, scene, "--duration", "0.05", "--out", "runs/robot_rough_bullet_force", "--no-plots"],
                       capture_output=True, text=True)
    check(r.returncode == 2 and "exists and is not empty" in r.stderr, "--out onto an earlier run is refused")

    # Interrupted (SIGINT) and killed (SIGKILL) runs.
    for sig, status in ((signal.SIGINT, "interrupted"), (signal.SIGKILL, "running")):
        out = f"cut_{sig.name}"
        p = subprocess.Popen([wtc_sim, scene, "--duration", "600", "--out", out, "--no-plots", "--quiet"])
        time.sleep(2.0)
        p.send_signal(sig)
        p.wait()
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        check(summary["status"] == status and summary["interrupted"] and not summary["success"],
              f"after {sig.name} summary.json says status '{status}', interrupted, not a success")
        for name in ("bodies", "drives", "wheels"):
            with open(os.path.join(out, name + ".csv")) as f:
                text = f.read()
            rows = list(csv.reader(text.splitlines()))
            if sig == signal.SIGKILL and not text.endswith("\n"):
                # Each row is written and flushed whole, but Linux may stop a
                # write at a page boundary when a kill lands in it: only the
                # last row can be cut (the plotting script skips it).
                rows.pop()
            check(len(rows) > 2 and all(len(r) == len(rows[0]) for r in rows)
                  and (sig == signal.SIGKILL or text.endswith("\n")),
                  f"after {sig.name} {name}.csv holds {len(rows) - 1} whole rows")
    if FAILURES:
        sys.exit(f"{len(FAILURES)} checks failed")


if __name__ == "__main__":
    main()
