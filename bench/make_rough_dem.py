#!/usr/bin/env python3
"""Writes the 1 cm GeoTIFF of bench/rough_spacing_scene.sh: one continuous rough surface, 16 m x 6 m.

Heights (m): rough_ground's three long waves (2, 1.5 and 1 cm, wavelengths 3.7-9 m) plus six
sines of 0.15-0.8 m wavelength and 3-8 mm amplitude in fixed directions (the roughness a 0.19 m
wheel feels), continuous, so that a coarser spacing samples the same surface (step 50 keeps every
50th sample: 50 cm). No noise: what differs between spacings is the sampling alone.

Usage: PYTHONPATH=build/python python3 bench/make_rough_dem.py OUT.tif
"""
import sys

import numpy as np

import wtc

SPACING = 0.01      # m
COLS, ROWS = 1601, 601
# (amplitude m, wavelength m, direction deg, phase rad): fixed, no random draws.
RIPPLES = [(0.008, 0.80, 10, 0.3), (0.006, 0.55, 75, 1.9), (0.005, 0.37, 140, 4.0),
           (0.004, 0.26, 35, 2.2), (0.003, 0.19, 100, 5.1), (0.003, 0.15, 160, 0.7)]

y, x = np.mgrid[0:ROWS, 0:COLS] * SPACING
h = (0.020 * np.sin(2 * np.pi * x / 9.0 + 0.4) * np.sin(2 * np.pi * y / 7.3)
     + 0.015 * np.sin(2 * np.pi * (x + 0.6 * y) / 5.1 + 1.1)
     + 0.010 * np.cos(2 * np.pi * (x - y) / 3.7))
for amplitude, wavelength, degrees, phase in RIPPLES:
    d = np.radians(degrees)
    h += amplitude * np.sin(2 * np.pi * (x * np.cos(d) + y * np.sin(d)) / wavelength + phase)
wtc.write_dem(sys.argv[1], h, SPACING, epsg=32633, south_west=(500000.0, 600000.0))
