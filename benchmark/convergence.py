#!/usr/bin/python3
"""Convergence of `tspline c1`'s fits on jittered grids of the unit square, beside scipy's
CloughTocher2DInterpolator on identical points when python3-scipy is installed.

For h = 1/8 ... 1/128 the data are the values of a test function at the points
(i h, j h) moved by a uniform jitter of up to h/4 in each coordinate (boundary points move
along the boundary only, so the convex hull is the unit square). The error is the largest
absolute error on a 200 x 200 grid strictly inside the square; the observed order between
two rows is log2(e_previous / e).

With --points random the same numbers of points are drawn uniformly (the four corners
included): the thin triangles along the hull that real scattered data have.

Usage: convergence.py [--tspline PATH] [--fits local,lsq,tangent] [--functions expsin,franke]
                      [--levels 8,16,32,64,128] [--points grid|random] [--plot FILE.png]
                      [--markdown]
Prints one table per function. Needs numpy; scipy and matplotlib are optional.
"""
import argparse
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

FUNCTIONS = {
    "expsin": ("exp(x) sin(2y)", lambda x, y: np.exp(x) * np.sin(2 * y)),
    "franke": ("Franke F1", lambda x, y: (
        0.75 * np.exp(-((9 * x - 2) ** 2 + (9 * y - 2) ** 2) / 4)
        + 0.75 * np.exp(-((9 * x + 1) ** 2) / 49 - (9 * y + 1) / 10)
        + 0.5 * np.exp(-((9 * x - 7) ** 2 + (9 * y - 3) ** 2) / 4)
        - 0.2 * np.exp(-(9 * x - 4) ** 2 - (9 * y - 7) ** 2))),
}


def jittered_grid(n, seed):
    """(n+1)^2 points: grid spacing 1/n, jitter up to h/4, boundary kept on the square."""
    rng = np.random.default_rng(seed)
    h = 1.0 / n
    i, j = np.meshgrid(np.arange(n + 1), np.arange(n + 1), indexing="ij")
    x = i.ravel() * h
    y = j.ravel() * h
    jx = rng.uniform(-h / 4, h / 4, x.size)
    jy = rng.uniform(-h / 4, h / 4, y.size)
    on_x = (i.ravel() == 0) | (i.ravel() == n)
    on_y = (j.ravel() == 0) | (j.ravel() == n)
    x = np.where(on_x, x, x + jx)
    y = np.where(on_y, y, y + jy)
    return np.column_stack([x, y])


def random_points(n, seed):
    """(n+1)^2 uniformly random points of the unit square with its four corners (so the hull
    is the square): thin triangles along the hull, as in real scattered data."""
    rng = np.random.default_rng(seed)
    points = rng.random(((n + 1) ** 2, 2))
    points[:4] = [[0, 0], [1, 0], [0, 1], [1, 1]]
    return points


def evaluation_grid(m=200):
    t = (np.arange(m) + 0.5) / m
    gx, gy = np.meshgrid(t, t, indexing="ij")
    return np.column_stack([gx.ravel(), gy.ravel()])


def fit_arguments(spec):
    """'local:5:largest' -> ('local', ['--degree', '5', '--degree-selection', 'largest']);
    a part 't=TAU' gives '--tension TAU' ('energy:t=2', 'adaptive:t=0')."""
    parts = spec.split(":")
    extra = []
    for part in [q for q in parts[1:] if q.startswith("t=")]:
        extra += ["--tension", part[2:]]
    parts = [q for q in parts if not q.startswith("t=")]
    if len(parts) > 1:
        extra += ["--degree", parts[1]]
    if len(parts) > 2:
        extra += ["--degree-selection", parts[2]]
    return parts[0], extra


def run_tspline(tspline, points, values, queries, fit, workdir, extra=()):
    data = os.path.join(workdir, "data.xyz")
    query = os.path.join(workdir, "query.xy")
    out = os.path.join(workdir, "values.txt")
    np.savetxt(data, np.column_stack([points, values]), fmt="%.17g")
    np.savetxt(query, queries, fmt="%.17g")
    subprocess.run([tspline, "c1", "--input", data, "--fit", fit, "--query", query,
                    "--values", out, *extra], check=True, stdout=subprocess.DEVNULL)
    return np.loadtxt(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--tspline", default=os.path.join("build", "src", "tspline", "tspline"))
    parser.add_argument("--fits", default="local,lsq,tangent")
    parser.add_argument("--functions", default="expsin,franke")
    parser.add_argument("--levels", default="8,16,32,64,128")
    parser.add_argument("--points", default="grid", choices=["grid", "random"],
                        help="jittered grids (default) or as many uniformly random points")
    parser.add_argument("--plot", default="")
    parser.add_argument("--markdown", action="store_true")
    args = parser.parse_args()
    fits = [f for f in args.fits.split(",") if f]
    levels = [int(n) for n in args.levels.split(",")]
    try:
        from scipy.interpolate import CloughTocher2DInterpolator
    except ImportError:
        CloughTocher2DInterpolator = None
        print("(scipy not installed: no comparison column)", file=sys.stderr)
    columns = fits + (["scipy CT"] if CloughTocher2DInterpolator else [])
    queries = evaluation_grid()
    curves = {}
    with tempfile.TemporaryDirectory() as workdir:
        for key in args.functions.split(","):
            name, f = FUNCTIONS[key]
            exact = f(queries[:, 0], queries[:, 1])
            errors = {c: [] for c in columns}
            for n in levels:
                points = (jittered_grid if args.points == "grid" else random_points)(n, seed=n)
                z = f(points[:, 0], points[:, 1])
                for fit in fits:
                    method, extra = fit_arguments(fit)
                    v = run_tspline(args.tspline, points, z, queries, method, workdir, extra)
                    errors[fit].append(float(np.nanmax(np.abs(v - exact))))
                if CloughTocher2DInterpolator:
                    v = CloughTocher2DInterpolator(points, z)(queries)
                    errors["scipy CT"].append(float(np.nanmax(np.abs(v - exact))))
            curves[name] = errors
            sep = " | " if args.markdown else "  "
            header = ["h", "N"] + [f"{c} (order)" for c in columns]
            print(f"\n{name}: max error on a 200x200 grid inside the hull")
            if args.markdown:
                print("| " + " | ".join(header) + " |")
                print("|" + "---|" * len(header))
            else:
                print(sep.join(header))
            for r, n in enumerate(levels):
                cells = [f"1/{n}", str((n + 1) ** 2)]
                for c in columns:
                    e = errors[c][r]
                    order = (f" ({math.log2(errors[c][r - 1] / e):.2f})"
                             if r > 0 and e > 0 else "")
                    cells.append(f"{e:.3e}{order}")
                print(("| " + " | ".join(cells) + " |") if args.markdown else sep.join(cells))
    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(1, len(curves), figsize=(5.5 * len(curves), 4.5))
        axes = np.atleast_1d(axes)
        hs = [1.0 / n for n in levels]
        for ax, (name, errors) in zip(axes, curves.items()):
            for c, e in errors.items():
                ax.loglog(hs, e, "o-", label=c)
            for p, style in ((2, ":"), (4, "--"), (6, "-.")):
                ref = [errors[columns[0]][0] * (h / hs[0]) ** p for h in hs]
                ax.loglog(hs, ref, "k" + style, lw=0.8, label=f"O(h^{p})")
            ax.set_xlabel("h")
            ax.set_ylabel("max error")
            ax.set_title(name)
            ax.grid(True, which="both", lw=0.3)
            ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(args.plot, dpi=110)
        print(f"\nplot: {args.plot}")


if __name__ == "__main__":
    main()
