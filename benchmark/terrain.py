#!/usr/bin/python3
"""Real terrain: `tspline c1` against scipy's CloughTocher2DInterpolator on identical points.

The elevation model is matplotlib's sample DEM `jacksboro_fault_dem.npz` (344 x 403 cells of
3 arc-seconds, 236 m to 1076 m; Debian package python3-matplotlib), never used to tune the
package. N cells are drawn at random (seeded), their centres in metres are the data sites;
every other cell centre inside the convex hull of the sites is a check point. Prints RMS
and max error for each fit and for scipy CT.

Usage: terrain.py [--tspline PATH] [--n 500,2000,10000] [--fits local,local:5,lsq] [--dem F]
"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np

from convergence import fit_arguments

DEM = "/usr/share/matplotlib/mpl-data/sample_data/jacksboro_fault_dem.npz"


def load(path):
    d = np.load(path)
    z = d["elevation"].astype(float)
    rows, cols = z.shape
    lat = np.radians(0.5 * (float(d["ymin"]) + float(d["ymax"])))
    metres_x = float(d["dx"]) * 111320.0 * np.cos(lat)
    metres_y = float(d["dy"]) * 110574.0
    j, i = np.meshgrid(np.arange(cols), np.arange(rows))
    xy = np.column_stack([j.ravel() * metres_x, i.ravel() * metres_y])
    return xy, z.ravel()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--tspline", default=os.path.join("build", "src", "tspline", "tspline"))
    parser.add_argument("--n", default="500,2000,10000")
    parser.add_argument("--fits", default="local,local:5,lsq")
    parser.add_argument("--dem", default=DEM)
    parser.add_argument("--markdown", action="store_true")
    args = parser.parse_args()
    if not os.path.exists(args.dem):
        sys.exit(f"terrain.py: {args.dem} not found (Debian package python3-matplotlib)")
    xy, z = load(args.dem)
    try:
        from scipy.interpolate import CloughTocher2DInterpolator
        from scipy.spatial import Delaunay
    except ImportError:
        CloughTocher2DInterpolator = None
    print(f"DEM: {len(z)} cells, relief {z.min():.0f} m .. {z.max():.0f} m")
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for n in [int(a) for a in args.n.split(",")]:
            rng = np.random.default_rng(1000 + n)
            pick = rng.choice(len(z), size=n, replace=False)
            sites, values = xy[pick], z[pick]
            rest = np.setdiff1d(np.arange(len(z)), pick)
            if CloughTocher2DInterpolator:
                inside = Delaunay(sites).find_simplex(xy[rest]) >= 0
                check = rest[inside]
            else:
                check = rest
            data = os.path.join(work, "d.xyz")
            query = os.path.join(work, "q.xy")
            out = os.path.join(work, "v.txt")
            np.savetxt(data, np.column_stack([sites, values]), fmt="%.17g")
            np.savetxt(query, xy[check], fmt="%.17g")
            for fit in args.fits.split(","):
                name = fit
                fit, extra = fit_arguments(fit)
                subprocess.run([args.tspline, "c1", "--input", data, "--fit", fit, "--query",
                                query, "--values", out, *extra], check=True,
                               stdout=subprocess.DEVNULL)
                v = np.loadtxt(out)
                e = np.abs(v - z[check])
                ok = ~np.isnan(e)
                rows.append((n, name, np.sqrt(np.mean(e[ok] ** 2)), e[ok].max(), v[ok].min(),
                             v[ok].max(), int((~ok).sum())))
            if CloughTocher2DInterpolator:
                v = CloughTocher2DInterpolator(sites, values)(xy[check])
                e = np.abs(v - z[check])
                ok = ~np.isnan(e)
                rows.append((n, "scipy CT", np.sqrt(np.mean(e[ok] ** 2)), e[ok].max(),
                             v[ok].min(), v[ok].max(), int((~ok).sum())))
    header = ["N", "method", "RMS error (m)", "max error (m)", "min value", "max value", "NaN"]
    if args.markdown:
        print("| " + " | ".join(header) + " |\n|" + "---|" * len(header))
    else:
        print("  ".join(header))
    for r in rows:
        cells = [str(r[0]), r[1], f"{r[2]:.2f}", f"{r[3]:.1f}", f"{r[4]:.0f}", f"{r[5]:.0f}",
                 str(r[6])]
        print(("| " + " | ".join(cells) + " |") if args.markdown else "  ".join(cells))


if __name__ == "__main__":
    main()
