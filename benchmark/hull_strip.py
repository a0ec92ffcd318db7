#!/usr/bin/python3
"""Next to the hull: `tspline c1` against scipy's CloughTocher2DInterpolator within a strip
along the sides of the unit square.

Random points of the unit square without its corners have a hull of long edges (0.1 to 0.8)
over slivers; a query next to a side falls in those slivers, which only the hull vertices'
data reach. The data are the terrain-like function of benchmark/tile_simulation.cpp (five
octaves of waves up to 58 radians per unit and two ridges, range about [-0.58, 2.41]) and
exp(x) sin(2y); the check points are 50000 random points within `--width` of each side
(those inside the hull). Prints the largest and RMS error and the value range of each fit
and of scipy CT (optional, Debian's python3-scipy) on the same points.

Usage: hull_strip.py [--tspline PATH] [--n 20000,100000] [--fits adaptive] [--width 1e-3]
"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np

from convergence import fit_arguments


def terrain(x, y):
    z, amplitude, frequency = 0.0, 1.0, 3.0
    for k in range(5):
        a = 0.7 * k + 0.3
        z = z + amplitude * np.sin(frequency * (np.cos(a) * x + np.sin(a) * y) + k)
        amplitude *= 0.5
        frequency *= 2.1
    return (z + 0.5 * np.abs(np.sin(7.0 * (0.8 * x + 0.6 * y))) +
            0.3 * np.abs(np.sin(11.0 * (0.3 * x - 0.95 * y))))


FUNCTIONS = {"terrain": terrain, "expsin": lambda x, y: np.exp(x) * np.sin(2 * y)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--tspline", default=os.path.join("build", "src", "tspline", "tspline"))
    parser.add_argument("--n", default="20000,100000")
    parser.add_argument("--fits", default="adaptive")
    parser.add_argument("--functions", default="terrain,expsin")
    parser.add_argument("--width", type=float, default=1e-3)
    args = parser.parse_args()
    try:
        from scipy.interpolate import CloughTocher2DInterpolator
    except ImportError:
        CloughTocher2DInterpolator = None
        print("(scipy not installed: no comparison)", file=sys.stderr)
    rng = np.random.default_rng(3)
    t, s = rng.random(50000), rng.random(50000) * args.width
    queries = np.concatenate([np.c_[t, s], np.c_[t, 1 - s], np.c_[s, t], np.c_[1 - s, t]])
    print(f"within {args.width:g} of the sides: largest error (RMS) [value range]")
    print("function  N  method  largest  RMS  values  data")
    with tempfile.TemporaryDirectory() as work:
        data, query, out = (os.path.join(work, name) for name in ("d.xyz", "q.xy", "v.txt"))
        np.savetxt(query, queries, fmt="%.17g")
        for name in args.functions.split(","):
            f = FUNCTIONS[name]
            truth = f(queries[:, 0], queries[:, 1])
            for n in [int(a) for a in args.n.split(",")]:
                points = np.random.default_rng(n).random((n, 2))
                z = f(points[:, 0], points[:, 1])
                np.savetxt(data, np.c_[points, z], fmt="%.17g")
                results = []
                for fit in args.fits.split(","):
                    method, extra = fit_arguments(fit)
                    subprocess.run([args.tspline, "c1", "--input", data, "--fit", method,
                                    "--query", query, "--values", out, *extra], check=True,
                                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                    results.append((fit, np.loadtxt(out)))
                if CloughTocher2DInterpolator:
                    results.append(("scipy CT", CloughTocher2DInterpolator(points, z)(queries)))
                inside = np.all([~np.isnan(v) for _, v in results], axis=0)
                for method, v in results:
                    e = np.abs(v - truth)[inside]
                    print(f"{name}  {n}  {method}  {e.max():.3g}  {np.sqrt(np.mean(e**2)):.3g}  "
                          f"[{v[inside].min():.3f}, {v[inside].max():.3f}]  "
                          f"[{z.min():.3f}, {z.max():.3f}]")


if __name__ == "__main__":
    main()
