#!/usr/bin/python3
"""Times scipy's CloughTocher2DInterpolator (Qhull Delaunay + C^1 cubic Clough-Tocher with
estimated gradients) on the points of benchmark/bench_scattered.cpp (same 64-bit LCG).
Needs Debian's python3-scipy. Usage: compare_scipy.py [N ...]"""
import sys
import time

import numpy as np
from scipy.interpolate import CloughTocher2DInterpolator
from scipy.spatial import Delaunay

MASK = (1 << 64) - 1


def points(n):
    state = 20261122
    out = np.empty((n, 2))
    for i in range(n):
        for c in range(2):
            state = (state * 6364136223846793005 + 1442695040888963407) & MASK
            out[i, c] = (state >> 11) * (1.0 / 9007199254740992.0)
    return out


for n in [int(a) for a in sys.argv[1:]] or [100000, 1000000]:
    p = points(n)
    z = np.sin(6 * p[:, 0]) * np.cos(5 * p[:, 1])
    t0 = time.perf_counter()
    tri = Delaunay(p)
    t1 = time.perf_counter()
    CloughTocher2DInterpolator(tri, z)
    t2 = time.perf_counter()
    print(f"n={n}: scipy Delaunay {1e3 * (t1 - t0):.0f} ms, Clough-Tocher build "
          f"{1e3 * (t2 - t1):.0f} ms, triangles {len(tri.simplices)}")
