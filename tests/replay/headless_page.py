"""What the replay-page tests share: headless Chromium's flags, the status the page writes, a screenshot.

The page (apps/wtc-sim/replay.html) writes what it drew as JSON into <div id="status">; Chromium's
--dump-dom gives it back after the virtual-time budget has let the page load and draw.

Chromium runs in a process group of its own. A headless Chromium with a virtual-time budget now and then
never exits (seen once with --screenshot on a loaded machine: still running 24 minutes later, its zygote
and renderers with it), so on a timeout the whole group is killed and the call is tried once more.
"""
import json
import os
import re
import signal
import subprocess
import tempfile

CHROMIUM_FLAGS = ["--no-sandbox", "--enable-unsafe-swiftshader", "--use-angle=swiftshader",
                  "--window-size=900,600", "--virtual-time-budget=4000", "--hide-scrollbars"]
CHROMIUM_TIMEOUT_S = 120
CHROMIUM_ATTEMPTS = 2


def run_with_replay(wtc_sim, scene, duration, prefix, fail):
    """Runs `scene` for `duration` s with its replay; returns its output directory and the page's data."""
    out = os.path.join(tempfile.mkdtemp(prefix=prefix), "run")
    command = [wtc_sim, scene, "--duration", str(duration), "--out", out, "--no-plots", "--quiet"]
    if subprocess.run(command).returncode not in (0, 1):
        fail("wtc-sim failed: " + " ".join(command))
    with open(os.path.join(out, "replay_data.js")) as f:
        return out, json.loads(f.read().split("=", 1)[1].rstrip().rstrip(";"))


def run_chromium(chromium, args):
    """Chromium's standard output for `args`, or None when every attempt timed out."""
    for _ in range(CHROMIUM_ATTEMPTS):
        process = subprocess.Popen([chromium, *CHROMIUM_FLAGS, *args], stdout=subprocess.PIPE,
                                   stderr=subprocess.DEVNULL, text=True, start_new_session=True)
        try:
            out, _ = process.communicate(timeout=CHROMIUM_TIMEOUT_S)
            return out
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.communicate()
    return None


def page_status(chromium, page, query, fail):
    """The page's status for `query` (as ?t=0.5&play=0), parsed; `fail(message)` when it wrote none."""
    dom = run_chromium(chromium, ["--dump-dom", f"file://{page}?{query}"])
    if dom is None:
        fail(f"Chromium did not finish for ?{query} in {CHROMIUM_ATTEMPTS} attempts of {CHROMIUM_TIMEOUT_S} s")
    match = re.search(r'<div id="status">([^<]*)</div>', dom)
    if not match or not match.group(1):
        fail(f"the page wrote no status for ?{query} (did its script run?)")
    return json.loads(match.group(1).replace("&quot;", '"'))


def screenshot(chromium, page, query, path, fail):
    """A screenshot of the page for `query`, written to `path`; `fail(message)` when Chromium wrote none."""
    if os.path.exists(path):
        os.remove(path)
    if run_chromium(chromium, [f"--screenshot={path}", f"file://{page}?{query}"]) is None:
        fail(f"Chromium did not finish the screenshot for ?{query} in {CHROMIUM_ATTEMPTS} attempts of "
             f"{CHROMIUM_TIMEOUT_S} s")
    if not os.path.exists(path):
        fail(f"no screenshot for ?{query}")
