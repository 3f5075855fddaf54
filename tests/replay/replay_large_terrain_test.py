#!/usr/bin/env python3
"""The replay page of a run on a large terrain (issue 35, row 4), in headless Chromium.

usage: replay_large_terrain_test.py WTC_SIM CHROMIUM SOURCE_DIR ARTIFACTS_DIR

1. A 1 s run of the robot on a 1500 x 1500-cell compact heightfield (made here, 2.25 MB of PGM; drawn
   whole it made a 1.2 GB replay_data.js): its page draws at most kReplayTerrainMaxTriangles
   (include/wtc/sim/sim_constants.hpp) of terrain, only within kReplayTerrainMarginM of the path, says so,
   stays under 5 MB with three.js, and loads in Chromium without errors, terrain and vehicle drawn
   (a screenshot, kept in ARTIFACTS_DIR).
2. The replay turned off per run: `--no-replay`, and a scene's `output: {replay: false}` (through
   --set): no replay.html, no replay_data.js.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

import matplotlib.image
import numpy

import headless_page  # beside this file

SAMPLES = 1501            # 1500 x 1500 cells
SPACING_M = 0.05          # 75 m x 75 m
PAGE_LIMIT_BYTES = 5_000_000
BACKGROUND = numpy.array([0xdf, 0xe6, 0xec]) / 255.0  # the page's clear colour
MIN_DRAWN_FRACTION = 0.5  # of the screenshot's lower half: terrain (or vehicle), not background
RUN_TIMEOUT_S = 300


def fail(message):
    print("replay_large_terrain_test: FAIL: " + message)
    sys.exit(1)


def constant(source, name):
    """A number of include/wtc/sim/sim_constants.hpp, so that the test and the code cannot drift apart."""
    with open(os.path.join(source, "include/wtc/sim/sim_constants.hpp")) as f:
        match = re.search(name + r" = ([0-9.']+);", f.read())
    if not match:
        fail(f"no {name} in include/wtc/sim/sim_constants.hpp")
    return float(match.group(1).replace("'", ""))


def write_scene(source, work):
    """A 1500 x 1500-cell compact heightfield of gentle waves, and robot_straight on it."""
    i = numpy.arange(SAMPLES)
    gray = (127 + 60 * numpy.sin(i[:, None] * 0.05) * numpy.cos(i[None, :] * 0.037)).astype(numpy.uint8)
    with open(os.path.join(work, "large.pgm"), "wb") as f:
        f.write(b"P5\n%d %d\n255\n" % (SAMPLES, SAMPLES))
        f.write(gray.tobytes())
    with open(os.path.join(work, "large.yaml"), "w") as f:
        f.write("description: 1500 x 1500 cells at 5 cm, compact.\n"
                "materials: {soil: {mu_max: 0.8, s1: 0.1, s2: 0.0, rolling_resistance: 0.018}}\n"
                "pieces:\n"
                f"  - {{type: heightfield, material: soil, file: large.pgm, spacing: {SPACING_M}, "
                "height_scale: 0.001, translation: [-37.5, -37.5, -0.2], storage: compact}\n")
    with open(os.path.join(source, "scenes/robot_straight.yaml")) as f:
        scene = f.read()
    scene = scene.replace("terrain: ../terrains/flat.yaml", "terrain: large.yaml")
    scene = scene.replace("../vehicles/", os.path.join(source, "vehicles") + "/")
    if "terrain: large.yaml" not in scene:
        fail("scenes/robot_straight.yaml no longer names ../terrains/flat.yaml: update this test")
    path = os.path.join(work, "scene.yaml")
    with open(path, "w") as f:
        f.write(scene)
    return path


def run(wtc_sim, scene, out, *extra):
    command = [wtc_sim, scene, "--duration", "1", "--out", out, "--no-plots", "--quiet", *extra]
    try:
        code = subprocess.run(command, timeout=RUN_TIMEOUT_S).returncode
    except subprocess.TimeoutExpired:
        fail(f"wtc-sim took over {RUN_TIMEOUT_S} s: " + " ".join(command))
    if code not in (0, 1):
        fail(f"wtc-sim exited {code}: " + " ".join(command))


def main():
    wtc_sim, chromium, source, artifacts = sys.argv[1:5]
    os.makedirs(artifacts, exist_ok=True)
    work = tempfile.mkdtemp(prefix="wtc_replay_large_")
    scene = write_scene(source, work)
    budget = constant(source, "kReplayTerrainMaxTriangles")
    margin = constant(source, "kReplayTerrainMarginM")

    out = os.path.join(work, "run")
    run(wtc_sim, scene, out)
    with open(os.path.join(out, "replay_data.js")) as f:
        data = json.loads(f.read().split("=", 1)[1].rstrip().rstrip(";"))
    triangles = len(data["terrain"]["indices"]) // 3
    size = sum(os.path.getsize(os.path.join(out, f))
               for f in ("replay.html", "replay_data.js", "three.min.js", "OrbitControls.js"))
    print(f"replay_large_terrain_test: {triangles} terrain triangles (budget {budget:.0f}), "
          f"page {size / 1e6:.2f} MB (bound {PAGE_LIMIT_BYTES / 1e6:.0f} MB), note '{data['terrain']['note']}'")
    if not 0 < triangles <= budget:
        fail(f"{triangles} terrain triangles, expected 1 ... {budget:.0f}")
    if size >= PAGE_LIMIT_BYTES:
        fail(f"the page takes {size} bytes")
    if not data["terrain"]["note"].startswith(f"terrain within {margin:g} m of the path"):
        fail("the page does not say that it draws only part of the terrain: " + repr(data["terrain"]["note"]))
    # Only around the path: every vertex within the margin of some body's position (x, y).
    poses = numpy.array(data["poses"]).reshape(-1, 7)[:, :2] / 1000.0
    vertices = numpy.array(data["terrain"]["positions"]).reshape(-1, 3)[:, :2] / 1000.0
    low, high = poses.min(axis=0) - margin - 1e-3, poses.max(axis=0) + margin + 1e-3
    if ((vertices < low) | (vertices > high)).any():
        fail(f"terrain drawn beyond {margin:g} m of the path")
    if (vertices.min(axis=0) > poses.min(axis=0)).any() or (vertices.max(axis=0) < poses.max(axis=0)).any():
        fail("the terrain drawn does not cover the path")

    page = os.path.join(out, "replay.html")
    status = headless_page.page_status(chromium, page, "t=0.5&play=0", fail)
    if status["errors"]:
        fail("JavaScript errors: " + "; ".join(status["errors"]))
    if status["terrain_triangles"] != triangles or status["bodies"] < 1:
        fail(f"the page drew {status['terrain_triangles']} terrain triangles and {status['bodies']} bodies")
    shot = os.path.join(artifacts, "replay_large_terrain.png")
    headless_page.screenshot(chromium, page, "t=0.5&play=0", shot, fail)
    pixels = matplotlib.image.imread(shot)[:, :, :3]
    lower = pixels[pixels.shape[0] // 2:]
    drawn = (abs(lower - BACKGROUND).sum(axis=2) > 0.05).mean()
    print(f"replay_large_terrain_test: {drawn:.0%} of the screenshot's lower half drawn ({shot})")
    if drawn < MIN_DRAWN_FRACTION:
        fail("the screenshot shows no terrain")

    for extra, name in ((["--no-replay"], "--no-replay"), (["--set", "output.replay=false"], "output.replay false")):
        off = os.path.join(work, "off_" + extra[-1].replace("=", "_").lstrip("-"))
        run(wtc_sim, scene, off, *extra)
        left = [f for f in ("replay.html", "replay_data.js") if os.path.exists(os.path.join(off, f))]
        if left or not os.path.exists(os.path.join(off, "summary.json")):
            fail(f"with {name}: {left or 'no summary.json'}")
    print("replay_large_terrain_test: --no-replay and output.replay: false write no page")
    shutil.rmtree(work)
    print("replay_large_terrain_test: PASS")


if __name__ == "__main__":
    main()
