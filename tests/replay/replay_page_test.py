#!/usr/bin/env python3
"""The replay page of a wtc-sim run, in headless Chromium (issue: see a run).

usage: replay_page_test.py WTC_SIM CHROMIUM SOURCE_DIR ARTIFACTS_DIR

1. A 2 s run of the robot on rough ground: the page loads without JavaScript errors and draws
   one object per body of the vehicle that has a shape.
2. Screenshots at the slider's two ends (camera fixed) differ around where the page says the
   vehicle is in each: the vehicle moved on the screen. They are kept in ARTIFACTS_DIR.
3. A 60 s run: the page, its data and three.js together stay under 5 MB.
"""
import json
import os
import subprocess
import sys
import tempfile

import matplotlib.image

import headless_page  # beside this file

PAGE_LIMIT_BYTES = 5_000_000  # the bound for a 60 s run of the robot
NEAR_PX = 40                  # "around the vehicle": a square of this half-width
MIN_CHANGED_FRACTION = 0.05   # of that square's pixels


def fail(message):
    print("replay_page_test: FAIL: " + message)
    sys.exit(1)


def run_scene(wtc_sim, source, out, duration):
    command = [wtc_sim, os.path.join(source, "scenes/robot_rough.yaml"), "--duration", str(duration), "--out", out,
               "--no-plots", "--quiet"]
    if subprocess.run(command).returncode not in (0, 1):
        fail("wtc-sim failed: " + " ".join(command))


def page_status(chromium, page, query):
    return headless_page.page_status(chromium, page, query, fail)


def screenshot(chromium, page, query, path):
    headless_page.screenshot(chromium, page, query, path, fail)
    return matplotlib.image.imread(path)[:, :, :3]


def changed_near(a, b, px):
    x, y = px
    h, w = a.shape[:2]
    xs, ys = slice(max(0, x - NEAR_PX), min(w, x + NEAR_PX)), slice(max(0, y - NEAR_PX), min(h, y + NEAR_PX))
    diff = (abs(a[ys, xs] - b[ys, xs]).sum(axis=2) > 0.05)
    return diff.mean() if diff.size else 0.0


def main():
    wtc_sim, chromium, source, artifacts = sys.argv[1:5]
    os.makedirs(artifacts, exist_ok=True)
    work = tempfile.mkdtemp(prefix="wtc_replay_test_")

    short = os.path.join(work, "short")
    run_scene(wtc_sim, source, short, 2)
    page = os.path.join(short, "replay.html")
    with open(os.path.join(short, "replay_data.js")) as f:
        data = json.loads(f.read().split("=", 1)[1].rstrip().rstrip(";"))
    expected = sum(1 for b in data["bodies"] if b["kind"] != "none")
    first = page_status(chromium, page, "t=0&play=0&follow=0")
    last = page_status(chromium, page, "t=1&play=0&follow=0")
    for status in (first, last):
        if status["errors"]:
            fail("JavaScript errors: " + "; ".join(status["errors"]))
        if status["bodies"] != expected:
            fail(f"{status['bodies']} bodies drawn, expected {expected}")
    print(f"replay_page_test: no JavaScript errors; {expected} bodies drawn; {first['frames']} frames")

    start = screenshot(chromium, page, "t=0&play=0&follow=0", os.path.join(artifacts, "replay_start.png"))
    end = screenshot(chromium, page, "t=1&play=0&follow=0", os.path.join(artifacts, "replay_end.png"))
    for name, px in (("start", first["vehicle_px"]), ("end", last["vehicle_px"])):
        fraction = changed_near(start, end, px)
        print(f"replay_page_test: around the vehicle's {name} position {px}: {fraction:.0%} of pixels changed")
        if fraction < MIN_CHANGED_FRACTION:
            fail(f"the screenshots do not differ around the vehicle's {name} position {px}")
    if first["vehicle_px"] == last["vehicle_px"]:
        fail("the vehicle did not move on the screen")

    long = os.path.join(work, "long")
    run_scene(wtc_sim, source, long, 60)
    size = sum(os.path.getsize(os.path.join(long, f))
               for f in ("replay.html", "replay_data.js", "three.min.js", "OrbitControls.js"))
    print(f"replay_page_test: a 60 s run's page: {size / 1e6:.2f} MB (bound {PAGE_LIMIT_BYTES / 1e6:.0f} MB)")
    if size >= PAGE_LIMIT_BYTES:
        fail(f"the page of a 60 s run takes {size} bytes")
    print("replay_page_test: PASS")


if __name__ == "__main__":
    main()
