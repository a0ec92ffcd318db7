#!/usr/bin/python3
"""Evaluation speed: tspline.C1Interpolator against scipy's CloughTocher2DInterpolator on
identical data and identical queries (issue 12: at least 10 M points/s for spatially ordered
queries on 2 cores, and faster than scipy in any order).

Both interpolants are built from the same N seeded random points of [0, 1]^2 (values
exp(x) sin(2y)); Q queries uniform on [-0.02, 1.02]^2 (a few percent outside the hull) are
evaluated

  random   in the order drawn;
  sorted   sorted along a Hilbert curve of 2^10 x 2^10 cells (spatially ordered, as the
           nodes of a grid or sorted lidar returns are);
  grid     the nodes of a sqrt(Q) x sqrt(Q) grid, row by row (what `tspline eval --grid`
           evaluates);

each timed as the best of R calls (the build is not timed), and printed in million points
per second with the ratio tspline/scipy. Both libraries evaluate the same points, so the
ratio is an identical-input comparison; tspline uses all cores for large calls, scipy one.

usage: PYTHONPATH=build/python benchmark/evaluation_vs_scipy.py [--points N] [--queries Q]
       [--repeats R]        (defaults: N = 100000, Q = 1000000, R = 3)
"""
import argparse
import time

import numpy as np

import tspline

try:
    from scipy.interpolate import CloughTocher2DInterpolator
except ImportError:  # scipy is an optional comparator
    CloughTocher2DInterpolator = None


def hilbert_key(x, y, order=10):
    """Index along a Hilbert curve of 2^order x 2^order cells of [0, 1]^2 (vectorised)."""
    n = 1 << order
    xi = np.clip((x * n).astype(np.int64), 0, n - 1)
    yi = np.clip((y * n).astype(np.int64), 0, n - 1)
    key = np.zeros_like(xi)
    s = n >> 1
    while s > 0:
        rx = (xi & s) > 0
        ry = (yi & s) > 0
        key += s * s * ((3 * rx) ^ ry)
        # rotate the quadrant
        flip = ~ry & rx
        xi = np.where(flip, s - 1 - xi, xi)
        yi = np.where(flip, s - 1 - yi, yi)
        swap = ~ry
        xi, yi = np.where(swap, yi, xi), np.where(swap, xi, yi)
        s >>= 1
    return key


def best_rate(f, q, repeats):
    best = float("inf")
    for _ in range(repeats):
        t = time.perf_counter()
        f(q)
        best = min(best, time.perf_counter() - t)
    return len(q) / best / 1e6


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=100000)
    parser.add_argument("--queries", type=int, default=1000000)
    parser.add_argument("--repeats", type=int, default=3)
    a = parser.parse_args()
    rng = np.random.default_rng(20261202)
    p = rng.random((a.points, 2))
    z = np.exp(p[:, 0]) * np.sin(2 * p[:, 1])
    q = rng.uniform(-0.02, 1.02, (a.queries, 2))
    side = int(round(np.sqrt(a.queries)))
    g = np.linspace(-0.02, 1.02, side)
    gx, gy = np.meshgrid(g, g)
    orders = {
        "random": q,
        "sorted": q[np.argsort(hilbert_key((q[:, 0] + 0.02) / 1.04, (q[:, 1] + 0.02) / 1.04))],
        "grid": np.column_stack([gx.ravel(), gy.ravel()]),
    }
    ours = tspline.C1Interpolator(p, z)
    theirs = CloughTocher2DInterpolator(p, z) if CloughTocher2DInterpolator else None
    print(f"{a.points} points, {a.queries} queries, best of {a.repeats} (M points/s)")
    print(f"{'order':8} {'tspline':>9} {'scipy CT':>9} {'ratio':>7}")
    for name, queries in orders.items():
        mine = best_rate(ours, queries, a.repeats)
        if theirs is None:
            print(f"{name:8} {mine:9.2f} {'-':>9} {'-':>7}")
            continue
        other = best_rate(theirs, queries, a.repeats)
        print(f"{name:8} {mine:9.2f} {other:9.2f} {mine / other:7.2f}")


if __name__ == "__main__":
    main()
