#!/usr/bin/env python3
"""The replay page draws the ruts of soil that remembers (issue 55, item 1), in headless Chromium.

usage: replay_soil_test.py WTC_SIM CHROMIUM SOURCE_DIR

A 3 s run of the rover on sand (scenes/rover_sand.yaml: a 2 cm soil region, bulldozing). The page's data keeps
the ground's memory every 0.25 s: each node once, at its place on the soil grid within the region and on the
slab's top, and per snapshot the nodes whose sinkage changed. The ruts are as deep as the rover sinks (the
summary's wheels sink 20-40 mm on this sand) and the bulldozed berms rise; the summary's touched nodes are
all drawn. The page loads without JavaScript errors, shows no ruts at the first frame and every node at the
last, and some but not all part-way.
"""
import json
import os
import sys

import headless_page  # beside this file

SPACING_MM = 20                # the scene's soil region
REGION_MM = (-5000, -2000, 5000, 2000)
SINKAGE_UNIT_MM = 0.1          # the data's sinkage unit
RUT_MM = (15.0, 60.0)          # the deepest node: within the wheels' sinkage on this sand, and a rut's chord sag
SNAPSHOT_S = 0.25              # include/wtc/sim/sim_constants.hpp, kReplaySoilPeriodS


def fail(message):
    print("replay_soil_test: FAIL: " + message)
    sys.exit(1)


def main():
    wtc_sim, chromium, source = sys.argv[1:4]
    out, data = headless_page.run_with_replay(wtc_sim, os.path.join(source, "scenes/rover_sand.yaml"), 3,
                                              "wtc_replay_soil_", fail)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)

    soil = data.get("soil")
    if soil is None:
        fail("the page's data has no soil")
    if soil["spacing"] != SPACING_MM:
        fail(f"spacing {soil['spacing']} mm, the region's is {SPACING_MM}")
    nodes = len(soil["nodes"]) // 3
    if nodes != summary["soil_memory_touched_nodes"]:
        fail(f"{nodes} nodes drawn, the run touched {summary['soil_memory_touched_nodes']}")
    for k in range(nodes):
        x, y, z = soil["nodes"][3 * k: 3 * k + 3]
        if (x - REGION_MM[0]) % SPACING_MM or (y - REGION_MM[1]) % SPACING_MM:
            fail(f"node {k} at ({x}, {y}) mm is off the region's grid")
        if not (REGION_MM[0] <= x <= REGION_MM[2] and REGION_MM[1] <= y <= REGION_MM[3]) or z != 0:
            fail(f"node {k} at ({x}, {y}, {z}) mm is outside the region or off the slab's top (z = 0)")

    frames, last_frame, final = len(data["times"]), -1, {}
    for number, update in enumerate(soil["updates"]):
        frame = update[0]
        if not last_frame < frame < frames:
            fail(f"snapshot frames out of order or range: {frame} after {last_frame} of {frames}")
        gap_s = (data["times"][frame] - (data["times"][last_frame] if last_frame >= 0 else 0)) / 1000
        # Each at the first frame at or past its time (frames 1 / fps apart); the end's whenever the run ends.
        if last_frame >= 0 and number + 1 < len(soil["updates"]) and gap_s < SNAPSHOT_S - 1 / data["fps"] - 1e-6:
            fail(f"snapshots {gap_s} s apart, less than {SNAPSHOT_S} s less a frame")
        last_frame = frame
        for k in range(1, len(update), 2):
            if not 0 <= update[k] < nodes:
                fail(f"a snapshot names node {update[k]} of {nodes}")
            final[update[k]] = update[k + 1]
    if len(final) != nodes:
        fail(f"{len(final)} of {nodes} nodes were ever given a sinkage")
    deepest = max(final.values()) * SINKAGE_UNIT_MM
    if not RUT_MM[0] <= deepest <= RUT_MM[1]:
        fail(f"the deepest rut is {deepest} mm, outside {RUT_MM} mm")
    if min(final.values()) >= 0:
        fail("no node rose: the scene bulldozes (flow factor 0.5)")

    page = os.path.join(out, "replay.html")
    shown = {}
    for t in ("0", "0.5", "1"):
        status = headless_page.page_status(chromium, page, f"t={t}&play=0&follow=0", fail)
        if status["errors"]:
            fail(f"JavaScript errors at t={t}: " + "; ".join(status["errors"]))
        shown[t] = status["soil_nodes"]
    if shown["0"] != 0 or shown["1"] != nodes or not 0 < shown["0.5"] < nodes:
        fail(f"nodes shown at the start, half-way and the end: {shown}, expected 0, some, {nodes}")
    print(f"replay_soil_test: {nodes} nodes in {len(soil['updates'])} snapshots, the deepest rut {deepest:.1f} mm, "
          f"the highest berm {-min(final.values()) * SINKAGE_UNIT_MM:.1f} mm; shown {shown}; PASS")


if __name__ == "__main__":
    main()
