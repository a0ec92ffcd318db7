#!/usr/bin/python3
"""Python module vs command line on the same scattered data (issue 15: a 10^6-point
interpolant built from Python takes no more than 10% longer than the CLI).

The same N seeded random points of [0, 1]^2 (values exp(x) sin(2y)) are saved once as .npy.
Each repeat then times, in alternating order (paired, so that a noisy machine hits both):

  python  the build tspline.C1Interpolator(points, values) in this process (the data already
          in numpy arrays, as a Python user has them), wall time;
  cli     the whole process `tspline c1 --input points.npy --report R.json`, wall time
          (reading the .npy, the build, and the C^1 check the CLI always runs);
  cpu     the same two in CPU time (user + system): on a shared machine less sensitive to
          what else runs than the wall time;
  cli_build  the CLI's own build stages from R.json: read_and_triangulate +
          degenerate_frame_fix + fit_and_propagate (what the Python call does, plus reading).

and prints the medians and the ratios python/cli (wall and CPU) and python/cli_build (each
the median of the per-repeat ratios).

usage: PYTHONPATH=build/python benchmark/python_vs_cli.py [--cli build/src/tspline/tspline]
       [--repeats 5] [N ...]          (default N: 1000000)
"""
import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import tspline


def data(n):
    rng = np.random.default_rng(20261127)
    p = rng.random((n, 2))
    return p, np.exp(p[:, 0]) * np.sin(2 * p[:, 1])


def time_python(p, z):
    t, c = time.perf_counter(), time.process_time()
    f = tspline.C1Interpolator(p, z)
    seconds, cpu = time.perf_counter() - t, time.process_time() - c
    return seconds, cpu, f.info["faces"]


def time_cli(cli, npy, report):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t = time.perf_counter()
    r = subprocess.run([cli, "c1", "--input", npy, "--report", report], capture_output=True,
                       text=True)
    seconds = time.perf_counter() - t
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    if r.returncode != 0:
        sys.exit(f"tspline c1 failed: {r.stderr.strip()}")
    timings = json.load(open(report))["timings_seconds"]
    build = sum(timings[k] for k in ("read_and_triangulate", "degenerate_frame_fix",
                                     "fit_and_propagate"))
    return seconds, cpu, build


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cli", default=os.path.join(here, "..", "build", "src", "tspline",
                                                      "tspline"))
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("sizes", nargs="*", type=int, default=[1000000])
    args = parser.parse_args()
    print(f"tspline {tspline.__version__}; {os.cpu_count()} cores; load average "
          f"{os.getloadavg()[0]:.2f}")
    for n in args.sizes:
        p, z = data(n)
        with tempfile.TemporaryDirectory() as tmp:
            npy, report = os.path.join(tmp, "points.npy"), os.path.join(tmp, "r.json")
            np.save(npy, np.column_stack([p, z]))
            rows = []
            for k in range(args.repeats):
                # alternate which goes first: drifts in the machine's load hit both
                if k % 2 == 0:
                    py, py_cpu, faces = time_python(p, z)
                    cli, cli_cpu, build = time_cli(args.cli, npy, report)
                else:
                    cli, cli_cpu, build = time_cli(args.cli, npy, report)
                    py, py_cpu, faces = time_python(p, z)
                rows.append((py, cli, build, py_cpu, cli_cpu))
                print(f"  n={n} repeat {k + 1}: python {py:.3f} s (cpu {py_cpu:.3f}), cli "
                      f"{cli:.3f} s (cpu {cli_cpu:.3f}; build stages {build:.3f} s)", flush=True)
        py, cli, build, py_cpu, cli_cpu = (statistics.median(c) for c in zip(*rows))
        ratio = statistics.median(r[0] / r[1] for r in rows)
        ratio_build = statistics.median(r[0] / r[2] for r in rows)
        ratio_cpu = statistics.median(r[3] / r[4] for r in rows)
        print(f"n={n} ({faces} triangles), medians of {args.repeats}: python {py:.3f} s "
              f"(cpu {py_cpu:.3f} s), cli {cli:.3f} s (cpu {cli_cpu:.3f} s), cli build stages "
              f"{build:.3f} s")
        print(f"  wall: python / cli = {ratio:.3f} ({'within' if ratio <= 1.10 else 'MORE than'} "
              f"10%), python / cli build stages = {ratio_build:.3f}; cpu: python / cli = "
              f"{ratio_cpu:.3f}")


if __name__ == "__main__":
    main()
