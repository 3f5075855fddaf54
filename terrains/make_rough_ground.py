#!/usr/bin/env python3
"""Writes rough_ground_heights.csv, the heightfield of rough_ground.yaml.

30 m x 30 m at 0.5 m spacing (61 x 61 samples). Heights (m) are three long
waves (amplitudes 2, 1.5 and 1 cm, wavelengths 3.7 to 9 m: slow pitch and
roll of a tug's wheelbase) plus uniform noise of +-0.6 cm per sample (the
cell-scale roughness a 0.3 m wheel feels), rounded to 0.1 mm. The peak-to-
peak range is about 9 cm. Deterministic: Python's random.Random(seed) gives
the same stream on every platform and version since Python 3.2.

Usage: python3 make_rough_ground.py > rough_ground_heights.csv
"""
import math
import random

SAMPLES = 61  # per side
SPACING = 0.5  # m
SEED = 20240611

rng = random.Random(SEED)
print("# rough_ground_heights.csv: written by make_rough_ground.py (seed %d)." % SEED)
print("# %d x %d heights (m), spacing %.1f m; first line = north edge (largest y)." % (SAMPLES, SAMPLES, SPACING))
rows = []
for r in range(SAMPLES):
    row = []
    for c in range(SAMPLES):
        x, y = c * SPACING, r * SPACING
        h = (0.020 * math.sin(2 * math.pi * x / 9.0 + 0.4) * math.sin(2 * math.pi * y / 7.3)
             + 0.015 * math.sin(2 * math.pi * (x + 0.6 * y) / 5.1 + 1.1)
             + 0.010 * math.cos(2 * math.pi * (x - y) / 3.7)
             + rng.uniform(-0.006, 0.006))
        row.append("%.4f" % h)
    rows.append(",".join(row))
# File order is north first: grid row SAMPLES - 1 is the first line.
for line in reversed(rows):
    print(line)
