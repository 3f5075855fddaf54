#!/usr/bin/env python3
"""Point queries and wheel contacts on a terrain, many at once from NumPy arrays.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/terrain_queries.py [--quick]

1. The rough ground of scenario 3 (terrains/rough_ground.yaml): the ground's height under a 0.1 m grid, from
   the signed distance of points 0.2 m above its top (terrain.query: distance, normal, piece per point), and the
   steepest slope the normals show.
2. A wheel (r_f = 0.3 m, w = 0.2 m, the tug's) rolled along a line at 1 cm spacing, its centre 1 cm below the
   height found: every pose's contacts (terrain.wheel_contacts), their deflections and pieces.
3. A heightfield built from an array (wtc.heightfield): a 2 m wave, and the query of its crest.
--quick: a coarser grid (the test suite's).
"""
import argparse
import pathlib

import numpy as np

import wtc


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="a 0.5 m grid (the test suite's)")
    args = parser.parse_args()
    root = pathlib.Path(__file__).resolve().parents[2]
    terrain = wtc.load_terrain(root / "terrains/rough_ground.yaml")
    low, high = np.array(terrain.bounds[0]), np.array(terrain.bounds[1])
    print(f"rough_ground.yaml: {terrain.piece_count} pieces, box {low} .. {high} m")

    # 1. Heights under a grid: a point above the ground at z0, its distance d and normal n give the ground at
    # z0 - d / n_z (exact on a plane; the ground is one within a cell).
    spacing = 0.5 if args.quick else 0.1
    xs = np.arange(-14.0, 14.0, spacing)
    gx, gy = np.meshgrid(xs, xs)
    z0 = high[2] + 0.2
    points = np.column_stack([gx.ravel(), gy.ravel(), np.full(gx.size, z0)])
    distances, normals, pieces = terrain.query(points, max_distance=1.0)
    heights = z0 - distances / normals[:, 2]
    slope = np.degrees(np.arccos(normals[:, 2]))
    print(f"{len(points)} queries: ground from {heights.min():.3f} to {heights.max():.3f} m, "
          f"steepest {slope.max():.1f} deg, {len(np.unique(pieces))} pieces met")

    # 2. A wheel along y = 2 m, 1 cm into the ground.
    x = np.arange(-10.0, 10.0, 0.05 if args.quick else 0.01)
    above = np.column_stack([x, np.full_like(x, 2.0), np.full_like(x, z0)])
    d, n, _ = terrain.query(above, max_distance=1.0)
    ground = z0 - d / n[:, 2]
    centres = np.column_stack([x, np.full_like(x, 2.0), ground + 0.3 - 0.01])
    contacts = terrain.wheel_contacts(centres, np.array([[0.0, 1.0, 0.0]]), radius=0.3, width=0.2)
    per_pose = np.bincount(contacts["index"], minlength=len(x))
    print(f"{len(x)} wheel poses: {len(contacts['index'])} contacts, {per_pose.min()} to {per_pose.max()} per pose, "
          f"deflection {contacts['deflection'].min() * 1e3:.1f} to {contacts['deflection'].max() * 1e3:.1f} mm")

    # 3. A heightfield from an array.
    u = np.linspace(0.0, 4.0, 41)
    wave = np.tile(0.1 * np.sin(np.pi * u / 2.0), (11, 1))
    hill = wtc.heightfield(wave, spacing_x=0.1, spacing_y=0.1, origin=(0.0, 0.0, 0.0))
    d, n, p = hill.query(np.array([[1.0, 0.5, 0.5]]))
    print(f"heightfield {wave.shape}: {hill.piece_count} pieces; 0.5 m above the crest the ground is {d[0]:.4f} m "
          f"away, normal {np.round(n[0], 6)}")


if __name__ == "__main__":
    main()
