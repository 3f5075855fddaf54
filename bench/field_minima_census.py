#!/usr/bin/env python3
"""What a rolling wheel's search on a fine field must find (issue 53, item 2).

The spacing bench's rolling wheel (bench/field_spacing_bench.cpp: its surface,
r_f 0.19 m, the deepest contact 2 mm deep, y = 0.5 m, x from 0.5 to 2.5 m),
counted here by brute force on every triangle near the wheel, per step:

- the triangles within the reach (their closest point nearer than r_f), the
  searched cells' triangles a contact can come from;
- the local minima of the distance, by the search's own rule (a triangle's
  closest point, compared with the triangles that hold it too, in the strict
  order (distance, row, column, half); src/contact/field_surface.hpp);
- the features (samples, edges, faces) that pass the first-order test of a
  minimum with no closed form: moving off the feature into any triangle that
  holds it brings nothing nearer, (q - o).u >= 0;
- the edges with the centre's foot inside them and within the reach, where
  a sweep that shares each edge's sums between its two samples would have
  more than a sign to test;
- the triangles no farther than the farthest minimum: the seam rule's
  shadows that could cut a contact;
- the cells with a triangle within the reach, and those of them that a bound
  per cell cannot clear: a minimum at q needs p = (q - O)_xy / (O_z - q_z)
  in the convex hull of the gradients of the triangles that hold q (on a
  face, p is its gradient), so a cell whose box of p (over its extent and
  heights) misses the box of the gradients of the 3 x 3 cells around it holds
  none. (Each minimum's cell is checked to be kept: the bound is a bound.)

The wheel's centre is placed as the bench places it (2 mm into the surface's
triangles), so the counts are the bench's up to its path's 1 mm steps.

    bench/field_minima_census.py [--cells 0.05,0.02,0.01] [--step 0.02]
"""
import argparse

import numpy as np

R = 0.19  # r_f (m)
DEPTH = 0.002  # the deepest contact's deflection (m)
REACH_CELLS_M = 0.21  # the patch of samples searched around the centre (m a side from it)
SLACK = 1e-9  # the first-order tests' margin, relative


def surface(x, y):
    """bench/field_spacing_bench.cpp's surface: bench_field.hpp's relief and a 4 mm roughness."""
    relief = 0.05 * np.sin(0.7 * x) * np.cos(0.9 * y) + 0.02 * np.sin(2.3 * x + 1.1 * y)
    return relief + 0.004 * np.sin(90.0 * x) * np.sin(0.9 * 90.0 * y)


def closest_on_triangles(p, a, b, c):
    """Ericson's closest point (Real-Time Collision Detection, 5.1.5) for n triangles at once:
    the points and the features (0 face, 1-3 vertex a-c, 4 edge ab, 5 bc, 6 ca)."""
    ab, ac, ap = b - a, c - a, p - a
    d1, d2 = (ab * ap).sum(1), (ac * ap).sum(1)
    bp = p - b
    d3, d4 = (ab * bp).sum(1), (ac * bp).sum(1)
    cp = p - c
    d5, d6 = (ab * cp).sum(1), (ac * cp).sum(1)
    vc, vb, va = d1 * d4 - d3 * d2, d5 * d2 - d1 * d6, d3 * d6 - d5 * d4
    q = np.zeros_like(a)
    feature = np.full(len(a), -1)

    def put(mask, value, code):
        mask = mask & (feature < 0)
        q[mask] = value[mask]
        feature[mask] = code

    with np.errstate(divide="ignore", invalid="ignore"):
        put((d1 <= 0) & (d2 <= 0), a, 1)
        put((d3 >= 0) & (d4 <= d3), b, 2)
        put((vc <= 0) & (d1 >= 0) & (d3 <= 0), a + (d1 / (d1 - d3))[:, None] * ab, 4)
        put((d6 >= 0) & (d5 <= d6), c, 3)
        put((vb <= 0) & (d2 >= 0) & (d6 <= 0), a + (d2 / (d2 - d6))[:, None] * ac, 6)
        put((va <= 0) & (d4 - d3 >= 0) & (d5 - d6 >= 0), b + ((d4 - d3) / ((d4 - d3) + (d5 - d6)))[:, None] * (c - b), 5)
        denom = 1.0 / (va + vb + vc)
        put(np.ones(len(a), bool), a + ab * (vb * denom)[:, None] + ac * (vc * denom)[:, None], 0)
    return q, feature


def census(spacing, x):
    y = 0.5
    n = int(np.ceil(REACH_CELLS_M / spacing))
    c0, r0, m = int(np.floor(x / spacing)) - n, int(np.floor(y / spacing)) - n, 2 * n + 2
    cols, rows = np.meshgrid(np.arange(c0, c0 + m + 1), np.arange(r0, r0 + m + 1))
    p = np.stack([cols * spacing, rows * spacing, surface(cols * spacing, rows * spacing)], -1)  # samples
    a, b0, c, b1 = p[:-1, :-1].reshape(-1, 3), p[:-1, 1:].reshape(-1, 3), p[1:, 1:].reshape(-1, 3), p[1:, :-1].reshape(-1, 3)
    # The centre 2 mm into the nearest triangle (a few Newton steps along z).
    z = surface(x, y) + R - DEPTH
    for _ in range(10):
        o = np.array([x, y, z])
        q0, f0 = closest_on_triangles(o, a, b0, c)  # half 0: (p00, p01, p11)
        q1, f1 = closest_on_triangles(o, a, c, b1)  # half 1: (p00, p11, p10)
        d0, d1 = np.linalg.norm(q0 - o, axis=1), np.linalg.norm(q1 - o, axis=1)
        miss = (R - DEPTH) - min(d0.min(), d1.min())
        z += miss
        if abs(miss) < 1e-12:
            break
    dist = np.stack([d0.reshape(m, m), d1.reshape(m, m)], -1)
    feat = np.stack([f0.reshape(m, m), f1.reshape(m, m)], -1)

    def d_of(i, j, t):
        return dist[i, j, t] if 0 <= i < m and 0 <= j < m else np.inf

    minima = []
    for i, j, t in zip(*np.nonzero(dist < R)):
        key, f = (dist[i, j, t], i, j, t), feat[i, j, t]
        if f == 0:
            rivals = []
        elif f >= 4:  # across the edge
            rivals = [[(i - 1, j, 1), (i, j + 1, 1), (i, j, 1)], [(i, j, 0), (i + 1, j, 0), (i, j - 1, 0)]][t][f - 4:f - 3]
        else:  # around the vertex
            si, sj = [[(i, j), (i, j + 1), (i + 1, j + 1)], [(i, j), (i + 1, j + 1), (i + 1, j)]][t][f - 1]
            rivals = [(si, sj, 0), (si, sj, 1), (si, sj - 1, 0), (si - 1, sj - 1, 0), (si - 1, sj - 1, 1), (si - 1, sj, 1)]
        if not any(n != (i, j, t) and (d_of(*n), *n) < key for n in rivals):
            minima.append(key)

    def away(w, u):
        return w @ u >= -SLACK * np.linalg.norm(w) * np.linalg.norm(u)

    candidates = edges_inside = 0
    for i in range(1, m):
        for j in range(1, m):
            v = p[i, j]
            w = v - o
            around = [p[i, j + 1], p[i + 1, j + 1], p[i + 1, j], p[i, j - 1], p[i - 1, j - 1], p[i - 1, j]]
            if w @ w < R * R and all(away(w, s - v) for s in around):
                candidates += 1
            # The edges from it, with their faces' third corners.
            for end, third1, third2 in ((p[i, j + 1], p[i + 1, j + 1], p[i - 1, j]),
                                        (p[i + 1, j], p[i + 1, j + 1], p[i, j - 1]),
                                        (p[i + 1, j + 1], p[i, j + 1], p[i + 1, j])):
                e = end - v
                t = -(w @ e) / (e @ e)
                qe = w + t * e
                if not (0.0 < t < 1.0 and qe @ qe < R * R):
                    continue
                edges_inside += 1
                if away(qe, third1 - v) and away(qe, third2 - v):
                    candidates += 1
    faces = int(((feat == 0) & (dist < R)).sum())  # a face's closest point is its foot: a minimum
    farthest = max(k[0] for k in minima)
    within, kept = gradient_box_cells(p, o, dist, spacing, [(k[1], k[2]) for k in minima])
    return (int((dist < R).sum()), len(minima), candidates + faces, edges_inside, int((dist <= farthest).sum()),
            within, kept)


def gradient_box_cells(p, o, dist, spacing, minima_cells):
    """The inner cells with a triangle within the reach, and those of them whose box of required
    gradients (q - O)_xy / (O_z - q_z) meets the box of their 3 x 3 cells' triangle gradients."""
    h, m = p[..., 2], dist.shape[0]
    gx0, gy0 = (h[:-1, 1:] - h[:-1, :-1]) / spacing, (h[1:, 1:] - h[:-1, 1:]) / spacing  # (p00, p01, p11)
    gx1, gy1 = (h[1:, 1:] - h[1:, :-1]) / spacing, (h[1:, :-1] - h[:-1, :-1]) / spacing  # (p00, p11, p10)

    def ring(v, pick):  # over each inner cell's 3 x 3 cells
        out = v[1:-1, 1:-1]
        for di in (-1, 0, 1):
            for dj in (-1, 0, 1):
                out = pick(out, v[1 + di:m - 1 + di, 1 + dj:m - 1 + dj])
        return out

    g = [ring(np.minimum(gx0, gx1), np.minimum), ring(np.maximum(gx0, gx1), np.maximum),
         ring(np.minimum(gy0, gy1), np.minimum), ring(np.maximum(gy0, gy1), np.maximum)]
    corners = np.stack([h[:-1, :-1], h[:-1, 1:], h[1:, 1:], h[1:, :-1]], -1)[1:-1, 1:-1]
    below = [o[2] - corners.max(-1), o[2] - corners.min(-1)]  # O_z - q_z over the cell, both > 0
    kept = np.ones_like(below[0], bool)
    for axis, (lo, hi) in enumerate(((g[0], g[1]), (g[2], g[3]))):
        near = p[1:-2, 1:-2, axis] - o[axis]
        ends = np.stack([e / b for e in (near, near + spacing) for b in below], -1)
        kept &= (ends.min(-1) <= hi) & (ends.max(-1) >= lo)
    within = (dist[1:-1, 1:-1] < R).any(-1)
    for i, j in minima_cells:
        assert 1 <= i < m - 1 and 1 <= j < m - 1 and kept[i - 1, j - 1], "a minimum's cell was cleared"
    return int(within.sum()), int((within & kept).sum())


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cells", default="0.05,0.02,0.01", help="cell sizes (m)")
    parser.add_argument("--step", type=float, default=0.02, help="the census's step along the path (m)")
    args = parser.parse_args()
    print("| cell | triangles within the reach | local minima | features passing the test "
          "| edges with the foot inside | triangles no farther than the farthest minimum "
          "| cells within the reach | cells the gradient box keeps |")
    print("|---|---|---|---|---|---|---|---|")
    for spacing in (float(s) for s in args.cells.split(",")):
        rows = np.array([census(spacing, x) for x in np.arange(0.5, 2.5, args.step)], float)
        mean = rows.mean(0)
        print(f"| {spacing * 100:g} cm | {mean[0]:.1f} | {mean[1]:.2f} | {mean[2]:.2f} | {mean[3]:.2f} | {mean[4]:.1f} "
              f"| {mean[5]:.1f} | {mean[6]:.1f} |")


if __name__ == "__main__":
    main()
