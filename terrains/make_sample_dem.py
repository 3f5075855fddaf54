#!/usr/bin/env python3
"""Writes samples/sample_dem.tif, the GeoTIFF DEM of sample_dem.yaml and scenes/rover_dem.yaml.

A synthetic survey of a 10 m x 5 m patch at 2 cm cells (501 x 251 samples), as a lidar or photogrammetry
DEM would come: north-up, float32 metres, EPSG:32633 (UTM zone 33N) with its south-west sample at
easting 512000.00, northing 800000.00 (a made-up place), DEFLATE-compressed. Heights (m):
- a 2 % rise to the east and three long waves (1-2 cm, wavelengths 2.3 to 6 m);
- two craters: a bowl of depth 6 and 4 cm inside a raised rim (Gaussian ring, 2.5 and 1.5 cm high),
  radii 0.9 and 0.6 m;
- 40 rocks: half-ellipsoids 1.5-5 cm tall (half a 0.1 m wheel at most), 6-15 cm across, at random places;
- sample noise of +-2 mm (a scanner's), all rounded to 1 mm;
- a no-data patch (a scanner's shadow behind the larger crater's rim, 0.5 m x 0.3 m) written as NaN,
  which WTC reads as holes.
The rover's path (scenes/rover_dem.yaml, along y = 2.5 m) crosses the smaller crater's rim and
several rocks and passes the shadow 1 m to its side. Deterministic: Python's random.Random(seed)
draws every random number (the same stream on every platform since Python 3.2), NumPy only adds them up.

Usage (from the build tree, whose Python package writes the GeoTIFF through GDAL):
    PYTHONPATH=build/python python3 terrains/make_sample_dem.py terrains/samples/sample_dem.tif
"""
import math
import random
import sys

import numpy as np

import wtc

SPACING = 0.02                   # m
COLS, ROWS = 501, 251            # samples: 10 m x 5 m
SOUTH_WEST = (512000.0, 800000.0)  # m, UTM zone 33N
EPSG = 32633
SEED = 20261129


def heights():
    rng = random.Random(SEED)
    y, x = np.mgrid[0:ROWS, 0:COLS] * SPACING  # row 0 is the south edge
    h = 0.02 * x
    h += 0.020 * np.sin(2 * np.pi * x / 6.0 + 0.3) * np.sin(2 * np.pi * y / 4.7)
    h += 0.012 * np.sin(2 * np.pi * (x + 0.5 * y) / 3.1 + 1.2)
    h += 0.010 * np.cos(2 * np.pi * (x - y) / 2.3)
    for cx, cy, radius, depth, rim in [(4.2, 2.1, 0.6, 0.04, 0.015), (7.3, 3.9, 0.9, 0.06, 0.025)]:
        d = np.hypot(x - cx, y - cy)
        h -= depth * np.clip(1.0 - (d / radius) ** 2, 0.0, None)
        h += rim * np.exp(-(((d - radius) / (0.2 * radius)) ** 2))
    for _ in range(40):
        cx, cy = rng.uniform(0.5, 9.5), rng.uniform(0.3, 4.7)
        a, b, tall = rng.uniform(0.03, 0.075), rng.uniform(0.03, 0.075), rng.uniform(0.015, 0.05)
        q = 1.0 - ((x - cx) / a) ** 2 - ((y - cy) / b) ** 2
        h = np.maximum(h, np.where(q > 0, h + tall * np.sqrt(np.clip(q, 0.0, None)), h))
    noise = np.array([[rng.uniform(-0.002, 0.002) for _ in range(COLS)] for _ in range(ROWS)])
    h = np.round(h + noise, 3)
    shadow = (np.abs(x - 8.45) < 0.25) & (np.abs(y - 3.9) < 0.15)
    h[shadow] = np.nan
    return h


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    wtc.write_dem(sys.argv[1], heights(), SPACING, south_west=SOUTH_WEST, epsg=EPSG)
