#!/usr/bin/env python3
"""The Python batch queries against the same queries called point by point from C++, in one run.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_batch_query_bench.py [--points 1000000] [--repeats 5]

Terrain: terrains/rough_ground.yaml (a 61 x 61 heightfield, 7200 prisms, and rocks). Points: uniform over the
terrain's box, from 0.3 m below its top to 0.4 m above (inside pieces, near them, beyond reach), reach 0.5 m.
  python: terrain.query(points) from a NumPy array (the array read, three arrays made and filled, the loop in C++)
  C++:    the same function (python/src/terrain_query.hpp: queryTerrain) called per point in a C++ loop over a
          std::vector (Terrain._cpp_query_seconds, the points copied before the clock starts)
Each is timed --repeats times, alternating; the ratio python rate / C++ rate is given from the best of each and as
the median of the repeats' own ratios (each pair timed back to back: the steadier figure on a loaded machine).
The wheel contacts (terrain.wheel_contacts) are timed once for their rate. docs/python.md quotes the output.
"""
import argparse
import pathlib
import time

import numpy as np

import wtc


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--points", type=int, default=1_000_000)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--reach", type=float, default=0.5)
    args = parser.parse_args()
    root = pathlib.Path(__file__).resolve().parents[1]
    terrain = wtc.load_terrain(root / "terrains/rough_ground.yaml")
    rng = np.random.default_rng(7)
    low, high = np.array(terrain.bounds[0]), np.array(terrain.bounds[1])
    points = rng.uniform(low, high, size=(args.points, 3))
    points[:, 2] = rng.uniform(high[2] - 0.3, high[2] + 0.4, size=args.points)

    python_best = cpp_best = float("inf")
    pair_ratios = []
    for _ in range(args.repeats):
        start = time.perf_counter()
        distances, normals, pieces = terrain.query(points, max_distance=args.reach)
        python_seconds = time.perf_counter() - start
        cpp_seconds = terrain._cpp_query_seconds(points, max_distance=args.reach)
        python_best, cpp_best = min(python_best, python_seconds), min(cpp_best, cpp_seconds)
        pair_ratios.append(cpp_seconds / python_seconds)
    n = args.points
    print(f"terrain: rough_ground.yaml, {terrain.piece_count} pieces; {n} points, reach {args.reach} m; "
          f"best of {args.repeats}")
    print(f"python terrain.query: {n / python_best / 1e6:.3f} M queries/s ({python_best * 1e9 / n:.0f} ns each)")
    print(f"C++ per point:        {n / cpp_best / 1e6:.3f} M queries/s ({cpp_best * 1e9 / n:.0f} ns each)")
    print(f"ratio python / C++:   {cpp_best / python_best:.3f} (best of each), {np.median(pair_ratios):.3f} (median of "
          f"the pairs: {', '.join(f'{r:.3f}' for r in pair_ratios)})")
    print(f"(within reach: {np.isfinite(distances).mean():.2%} of the points)")

    axles = np.tile([0.0, 1.0, 0.0], (n // 10, 1))
    centres = points[: n // 10].copy()
    start = time.perf_counter()
    contacts = terrain.wheel_contacts(centres, axles, radius=0.3, width=0.2)
    seconds = time.perf_counter() - start
    print(f"python terrain.wheel_contacts: {len(centres) / seconds / 1e6:.3f} M poses/s, "
          f"{len(contacts['index'])} contacts")


if __name__ == "__main__":
    main()
