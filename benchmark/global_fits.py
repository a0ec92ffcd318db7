#!/usr/bin/python3
"""Scaling of `tspline c1`'s global fits (issue 10, item 4): CPU time and peak memory of
`--fit energy`, `--fit energy --smoothing L`, `--fit lsq` and the default (adaptive) fit at
10^4 ... 10^6 scattered points, beside scipy's CloughTocher2DInterpolator on identical
points (when python3-scipy is installed).

The points are seeded uniform random points of the unit square with its four corners; the
values exp(x) sin(2y) (smooth) or the same plus N(0, 0.01^2) noise (noisy: the local
polynomials resolve nothing, so the adaptive fit's energy part covers every vertex). Each
run is a fresh process measured with wait4(): CPU = user + system time of the whole
process (reading the .npy, Delaunay, the fit, the C^1 check), peak = its largest resident
set; `fit s` is the report's fit_and_propagate stage (wall clock). scipy's CPU and peak are
those of a fresh python3 building the interpolator from the same arrays (Delaunay and
gradient estimation; importing numpy and scipy excluded from CPU, not from the peak).

usage: benchmark/global_fits.py [--tspline build/src/tspline/tspline] [--sizes 10000,100000]
       [--fits energy,lsq,default,smooth0.1] [--data smooth,noisy] [--markdown]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

SCIPY = r"""
import resource, sys, numpy as np
from scipy.interpolate import CloughTocher2DInterpolator
p = np.load(sys.argv[1]); z = np.load(sys.argv[2])
r = resource.getrusage(resource.RUSAGE_SELF)
before = r.ru_utime + r.ru_stime
CloughTocher2DInterpolator(p, z)
r = resource.getrusage(resource.RUSAGE_SELF)
print(r.ru_utime + r.ru_stime - before)
"""


def data(n, kind):
    rng = np.random.default_rng(20261210 + n)
    p = rng.random((n, 2))
    p[:4] = [[0, 0], [1, 0], [0, 1], [1, 1]]
    z = np.exp(p[:, 0]) * np.sin(2 * p[:, 1])
    if kind == "noisy":
        z = z + rng.normal(0, 0.01, n)
    return p, z


def run(command):
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(process.pid, 0)
    out = process.stdout.read().decode()
    err = process.stderr.read().decode()
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"{' '.join(command)} failed: {err.strip()}")
    return usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024, out


def fit_arguments(fit):
    if fit == "default":
        return []
    if fit.startswith("smooth"):
        return ["--fit", "energy", "--smoothing", fit[len("smooth"):]]
    return ["--fit", fit]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--tspline", default=os.path.join(here, "..", "build", "src", "tspline",
                                                          "tspline"))
    parser.add_argument("--sizes", default="10000,100000")
    parser.add_argument("--fits", default="energy,lsq,default,smooth0.1")
    parser.add_argument("--data", default="smooth,noisy")
    parser.add_argument("--markdown", action="store_true")
    args = parser.parse_args()
    try:
        import scipy  # noqa: F401
        have_scipy = True
    except ImportError:
        have_scipy = False
        print("(scipy not installed: no comparison column)", file=sys.stderr)
    print(f"{os.cpu_count()} cores; load average {os.getloadavg()[0]:.2f} at the start")
    header = ["N", "data", "fit", "CPU s", "fit s", "peak MB", "scipy CPU s", "scipy peak MB",
              "CPU / scipy"]
    rows = []
    for n in [int(s) for s in args.sizes.split(",")]:
        for kind in args.data.split(","):
            p, z = data(n, kind)
            with tempfile.TemporaryDirectory() as tmp:
                npy = os.path.join(tmp, "points.npy")
                np.save(npy, np.column_stack([p, z]))
                scipy_cpu = scipy_peak = None
                if have_scipy:
                    np.save(os.path.join(tmp, "p.npy"), p)
                    np.save(os.path.join(tmp, "z.npy"), z)
                    _, scipy_peak, out = run([sys.executable, "-c", SCIPY,
                                              os.path.join(tmp, "p.npy"),
                                              os.path.join(tmp, "z.npy")])
                    scipy_cpu = float(out)
                for fit in args.fits.split(","):
                    report = os.path.join(tmp, "r.json")
                    cpu, peak, _ = run([args.tspline, "c1", "--input", npy, "--report", report,
                                        *fit_arguments(fit)])
                    stage = json.load(open(report))["timings_seconds"]["fit_and_propagate"]
                    row = [n, kind, fit, f"{cpu:.2f}", f"{stage:.2f}", f"{peak:.0f}",
                           f"{scipy_cpu:.2f}" if scipy_cpu is not None else "-",
                           f"{scipy_peak:.0f}" if scipy_peak is not None else "-",
                           f"{cpu / scipy_cpu:.1f}" if scipy_cpu else "-"]
                    rows.append(row)
                    print(" | ".join(str(c) for c in row), file=sys.stderr, flush=True)
    if args.markdown:
        print("| " + " | ".join(header) + " |")
        print("|" + "---|" * len(header))
        for row in rows:
            print("| " + " | ".join(str(c) for c in row) + " |")
    else:
        widths = [max(len(str(r[i])) for r in rows + [header]) for i in range(len(header))]
        for row in [header] + rows:
            print("  ".join(str(c).rjust(w) for c, w in zip(row, widths)))


if __name__ == "__main__":
    main()
