#!/usr/bin/env python3
"""wtc-sim as a user's shell sees it: bad command lines are refused before anything runs (exit 2),
a run never reuses an earlier run's directory nor removes what it did not write, a failed run says
why, and an interrupted or killed run leaves whole CSV rows and a summary that says it did not
finish. And wtc-study's command line: exit 2 for its errors, a bad plan refused before any run.

usage: wtc_sim_cli_test.py WTC_SIM SOURCE_DIR WTC_STUDY
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


def run(args, **kw):
    return subprocess.run(args, capture_output=True, text=True, **kw)


def command_lines(wtc_sim, wtc_study, source):
    """Exit 2 for a command-line error (CLI11's own codes are 104-109), 0 for --help and --version."""
    scene = os.path.join(source, "scenes/robot_straight.yaml")
    for args, expected in (([], "scene is required"),
                           ([scene, "--bogus"], "--bogus"),
                           ([scene, "--dt", "abc"], "Could not convert: --dt = abc")):
        r = run([wtc_sim, *args])
        check(r.returncode == 2 and expected in r.stderr, f"wtc-sim {' '.join(args[1:])}: exit 2 naming '{expected}'"
              f" (got {r.returncode})")
    for program, name in ((wtc_sim, "wtc-sim"), (wtc_study, "wtc-study")):
        r = run([program, "--version"])
        check(r.returncode == 0 and r.stdout.startswith(name + " 0.") and "(build " in r.stdout,
              f"{name} --version: exit 0, the version and the build ({r.stdout.strip()})")
        r = run([program, "--help"])
        check(r.returncode == 0 and "Usage" in r.stdout, f"{name} --help: exit 0")
    study = os.path.join(source, "tests/study/tiny_study.yaml")
    for args, expected in (([], "A subcommand is required"),
                           (["run", study, "--workers", "0"], "--workers 0: must be at least 1"),
                           (["run", study, "--workers", "x"], "--workers"),
                           (["gather"], "study is required")):
        r = run([wtc_study, *args])
        check(r.returncode == 2 and expected in r.stderr and "not in range" not in r.stderr,
              f"wtc-study {' '.join(args[:1] + args[2:])}: exit 2 naming '{expected}' (got {r.returncode})")


def bad_studies(wtc_study, source):
    """A sweep value a scene refuses: refused before any run, naming its place; no jobs written."""
    with open("bad_study.yaml", "w") as f:
        f.write("name: bad\nbase: {engine: bullet, mode: force, dt: 0.0004}\n"
                f"scenarios: {{t: {{scene: {source}/scenes/towed_incline.yaml, set: {{duration: 0.4}}}}}}\n"
                "reference: {dt: 0.0002}\nsweeps:\n  step: {dt: [0.0004, -1]}\n")
    for sub in ("jobs", "run"):
        r = run([wtc_study, sub, "bad_study.yaml", "--out", "bad_study_" + sub, "--no-plots"])
        check(r.returncode == 2 and "bad_study.yaml:6:" in r.stderr and "sweeps.step.dt: value -1" in r.stderr
              and "dt: must be > 0 s" in r.stderr, f"wtc-study {sub}: a bad sweep value is named by its place")
        check(not os.path.exists(os.path.join("bad_study_" + sub, "jobs.txt"))
              and not os.path.exists(os.path.join("bad_study_" + sub, "runs")),
              f"wtc-study {sub}: nothing written for a bad plan")
    with open("empty_study.yaml", "w") as f:
        f.write("name: e\nbase: {engine: bullet, mode: force, dt: 0.0004}\nscenarios: {}\nreference: {}\n"
                "sweeps: {}\n")
    r = run([wtc_study, "run", "empty_study.yaml", "--out", "empty_study"])
    check(r.returncode == 2 and "scenarios: none" in r.stderr, "wtc-study: a study without scenarios is refused")


def names_and_steps(wtc_sim, source):
    """A scene name cannot write outside the output folder; a step must divide the duration."""
    scene = os.path.join(source, "scenes/robot_straight.yaml")
    os.makedirs("deep/er", exist_ok=True)
    for name in ("../../escape", "a/b", ".hidden"):
        r = run([wtc_sim, scene, "--set", "name=" + name, "--duration", "0.1", "--no-plots", "--quiet"],
                cwd="deep/er")
        check(r.returncode == 2 and "name: '" + name + "'" in r.stderr, f"name {name} refused, exit 2")
    check(not os.path.exists("escape_bullet_force") and not os.path.exists("deep/er/runs"),
          "nothing written for a refused name")
    for args, expected in ((["--duration", "0.2", "--dt", "10"], "the step is longer than the duration"),
                           (["--duration", "0.25", "--dt", "0.1"], "the nearest durations that are: 0.2 s and 0.3 s")):
        r = run([wtc_sim, scene, *args, "--out", "steps", "--no-plots"])
        check(r.returncode == 2 and expected in r.stderr, f"{' '.join(args)}: exit 2 naming '{expected}'")
    check(not os.path.exists("steps"), "nothing written for a refused step")


def skip_done(wtc_sim, source):
    """--skip-done removes only what a run of its own wrote, and refuses any other non-empty directory."""
    scene = os.path.join(source, "scenes/towed_path.yaml")
    base = [wtc_sim, scene, "--duration", "0.2", "--skip-done", "--quiet"]
    # Case (the issue's): a user's file in --out survives, and the run is refused.
    os.makedirs("scratch")
    with open("scratch/notes.txt", "w") as f:
        f.write("precious\n")
    r = run(base + ["--out", "scratch"])
    check(r.returncode == 2 and "nothing else" in r.stderr and os.listdir("scratch") == ["notes.txt"],
          "--skip-done into a user's directory: refused, notes.txt kept, nothing added")
    # Case: a run of its own that ended is skipped; one of other settings is refused.
    r = run(base + ["--out", "own"])
    check(r.returncode in (0, 1) and os.path.exists("own/.wtc-run"), "a run writes its marker .wtc-run")
    made = sorted(os.listdir("own"))
    before = os.stat("own/summary.json").st_mtime_ns
    r = run(base + ["--out", "own"])
    check(r.returncode == 0 and os.stat("own/summary.json").st_mtime_ns == before,
          "--skip-done: a finished run of the same settings is skipped")
    r = run(base[:3] + ["0.4"] + base[4:] + ["--out", "own"])
    check(r.returncode == 2 and "other settings" in r.stderr and sorted(os.listdir("own")) == made,
          "--skip-done onto a run of other settings: refused, nothing removed")
    # Case: an unfinished run of its own (every file a run writes, figures too) is made anew.
    with open("own/summary.json") as f:
        summary = json.load(f)
    summary["status"] = "running"
    with open("own/summary.json", "w") as f:
        json.dump(summary, f)
    r = run(base + ["--out", "own"])
    with open("own/summary.json") as f:
        check(r.returncode in (0, 1) and json.load(f)["status"] == "completed" and sorted(os.listdir("own")) == made,
              f"--skip-done redoes an unfinished run of its own ({len(made)} files: {', '.join(made)})")
    # Case: the same, with a file of the user's beside it: refused, both kept.
    summary["status"] = "running"
    with open("own/summary.json", "w") as f:
        json.dump(summary, f)
    with open("own/mine.txt", "w") as f:
        f.write("mine\n")
    r = run(base + ["--out", "own"])
    check(r.returncode == 2 and "'mine.txt', which wtc-sim did not write" in r.stderr
          and sorted(os.listdir("own")) == sorted(made + ["mine.txt"]),
          "--skip-done onto an unfinished run beside a user's file: refused, nothing removed")


def failed_runs(wtc_sim, source):
    """A failed run says which criterion it missed, on screen and in summary.json."""
    scene = os.path.join(source, "scenes/robot_straight.yaml")
    r = run([wtc_sim, scene, "--set", "controller.schedules.0.points=[[0,0],[2,3]]", "--duration", "2",
             "--out", "slow", "--no-plots"])
    with open("slow/summary.json") as f:
        summary = json.load(f)
    failed = summary["failed_criteria"]
    check(r.returncode == 1 and ": FAILED" in r.stdout and "  failed: min_distance: " in r.stdout
          and "(limit 3 m)" in r.stdout, "a failed run's headline is followed by the criterion it missed")
    check(len(failed) == 1 and failed[0]["criterion"] == "min_distance" and failed[0]["limit"] == 3
          and failed[0]["measured"] == summary["distance_m"] and failed[0]["unit"] == "m",
          "summary.json's failed_criteria: min_distance, its limit and the distance")


def main():
    wtc_sim, source, wtc_study = sys.argv[1:4]
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
    command_lines(wtc_sim, wtc_study, source)
    bad_studies(wtc_study, source)
    names_and_steps(wtc_sim, source)
    skip_done(wtc_sim, source)
    failed_runs(wtc_sim, source)

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
        p = subprocess.Popen([wtc_sim, scene, "--duration", "600", "--out", out, "--no-plots"],
                             stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
        # Signalled once the run has begun (its summary.json says "running") and has run a while: a fixed
        # wait was too short under the sanitizers on a loaded machine (no summary.json yet at 2 s).
        deadline = time.monotonic() + 120.0
        while not os.path.exists(os.path.join(out, "summary.json")) and p.poll() is None \
                and time.monotonic() < deadline:
            time.sleep(0.1)
        time.sleep(1.0)
        p.send_signal(sig)
        stdout = p.communicate()[0]
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        check(summary["status"] == status and summary["interrupted"] and not summary["success"]
              and summary["failed_criteria"][0]["criterion"] == "interrupted",
              f"after {sig.name} summary.json says status '{status}', interrupted, not a success, and why")
        if sig == signal.SIGINT:
            check(": INTERRUPTED at t = " in stdout and "FAILED" not in stdout
                  and "  failed: interrupted: " in stdout, "an interrupted run's headline says INTERRUPTED at t")
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
