"""What the replay-page tests share: headless Chromium's flags, the status the page writes, a screenshot.

The page (apps/wtc-sim/replay.html) writes what it drew as JSON into <div id="status">; Chromium's
--dump-dom gives it back after the virtual-time budget has let the page load and draw.
"""
import json
import os
import re
import subprocess

CHROMIUM_FLAGS = ["--no-sandbox", "--enable-unsafe-swiftshader", "--use-angle=swiftshader",
                  "--window-size=900,600", "--virtual-time-budget=4000", "--hide-scrollbars"]
CHROMIUM_TIMEOUT_S = 120


def page_status(chromium, page, query, fail):
    """The page's status for `query` (as ?t=0.5&play=0), parsed; `fail(message)` when it wrote none."""
    dom = subprocess.run([chromium, *CHROMIUM_FLAGS, "--dump-dom", f"file://{page}?{query}"], capture_output=True,
                         text=True, timeout=CHROMIUM_TIMEOUT_S).stdout
    match = re.search(r'<div id="status">([^<]*)</div>', dom)
    if not match or not match.group(1):
        fail(f"the page wrote no status for ?{query} (did its script run?)")
    return json.loads(match.group(1).replace("&quot;", '"'))


def screenshot(chromium, page, query, path, fail):
    """A screenshot of the page for `query`, written to `path`; `fail(message)` when Chromium wrote none."""
    subprocess.run([chromium, *CHROMIUM_FLAGS, f"--screenshot={path}", f"file://{page}?{query}"],
                   capture_output=True, timeout=CHROMIUM_TIMEOUT_S)
    if not os.path.exists(path):
        fail(f"no screenshot for ?{query}")
