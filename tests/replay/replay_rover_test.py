#!/usr/bin/env python3
"""The replay page draws a URDF vehicle's collision shapes (issue 37, item 5), in headless Chromium.

usage: replay_rover_test.py WTC_SIM CHROMIUM SOURCE_DIR

A 1 s run of the rocker-bogie rover (vehicles/rocker_bogie_rover.yaml, from URDF): its chassis is a compound of
its mesh's convex hull and the mast's box, each rocker a compound of two boxes. The page's data holds them (the
hull as triangles), and the page loads without JavaScript errors and draws one mesh per part: a compound's parts,
a wheel's tread and spoke, a plain shape.
"""
import os
import sys

import headless_page  # beside this file



def fail(message):
    print("replay_rover_test: FAIL: " + message)
    sys.exit(1)


def main():
    wtc_sim, chromium, source = sys.argv[1:4]
    out, data = headless_page.run_with_replay(wtc_sim, os.path.join(source, "scenes/rover_flat.yaml"), 1,
                                              "wtc_replay_rover_", fail)
    bodies = {b["name"]: b for b in data["bodies"]}

    chassis = bodies["chassis"]
    if chassis["kind"] != "compound" or sorted(p["kind"] for p in chassis["parts"]) != ["box", "hull"]:
        fail(f"the chassis is not a compound of its hull and the mast's box: {chassis}")
    hull = next(p for p in chassis["parts"] if p["kind"] == "hull")
    # rover_body.stl: a 0.50 x 0.30 x 0.15 m box with its four long edges chamfered: 16 vertices.
    vertices = len(hull["positions"]) // 3
    xs = hull["positions"][0::3]
    if vertices != 16 or max(xs) - min(xs) != 500 or len(hull["indices"]) % 3:
        fail(f"the hull has {vertices} vertices and spans {max(xs) - min(xs)} mm in x (expected 16, 500 mm)")
    for side in ("left_rocker", "right_rocker"):
        if bodies[side]["kind"] != "compound" or [p["kind"] for p in bodies[side]["parts"]] != ["box", "box"]:
            fail(f"{side} is not a compound of two boxes: {bodies[side]}")

    expected = sum(len(b["parts"]) if b["kind"] == "compound" else 2 if b["kind"] == "wheel" else
                   0 if b["kind"] == "none" else 1 for b in data["bodies"])
    page = os.path.join(out, "replay.html")
    status = headless_page.page_status(chromium, page, "t=0&play=0&follow=0", fail)
    if status["errors"]:
        fail("JavaScript errors: " + "; ".join(status["errors"]))
    if status["shapes"] != expected:
        fail(f"{status['shapes']} meshes drawn, expected {expected}")
    print(f"replay_rover_test: {status['bodies']} bodies, {status['shapes']} meshes drawn; a hull of {vertices} "
          f"vertices; PASS")


if __name__ == "__main__":
    main()
