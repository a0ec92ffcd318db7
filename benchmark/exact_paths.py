#!/usr/bin/python3
"""The exact paths of issue 12, timed through the command line on seeded random points of
[0, 1]^2 with 6-decimal coordinates and values (parsed exactly, as a user's data are):

  dimension  `tspline c1 --dimension`: the stage 'dimension' of the report (exact plan check
             + rank modulo a prime), and the argument that proved it;
  exact      `tspline c1 --exact --fit FIT` (default: the default fit, adaptive): faces per
             second of the whole process (wall and CPU), and of the certificate stage alone.

Every run is a whole process; the machine may be shared, so CPU time (user + system of the
child) is printed beside the wall time, and each figure is the median of --repeats runs.

usage: benchmark/exact_paths.py [--cli build/src/tspline/tspline] [--repeats 3]
       [--dimension 30,50,100,1000,10000] [--exact 1000,3000,10000] [--fit adaptive]
"""
import argparse
import json
import os
import random
import resource
import statistics
import subprocess
import tempfile
import time


def write_points(path, n):
    rng = random.Random(n)
    with open(path, "w") as f:
        for _ in range(n):
            x, y = rng.random(), rng.random()
            f.write(f"{x:.6f} {y:.6f} {(x * x - y) * 0.5 + x * y:.6f}\n")


def run(cli, args):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run([cli] + args, check=True, stdout=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cli", default="build/src/tspline/tspline")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--dimension", default="30,50,100,1000,10000")
    parser.add_argument("--exact", default="1000,3000,10000")
    parser.add_argument("--fit", default="adaptive")
    a = parser.parse_args()
    sizes = lambda s: [int(x) for x in s.split(",") if x]
    with tempfile.TemporaryDirectory() as tmp:
        report = os.path.join(tmp, "r.json")
        for n in sizes(a.dimension):
            points = os.path.join(tmp, f"p{n}.xyz")
            write_points(points, n)
            stage, wall, cpu = [], [], []
            for _ in range(a.repeats):
                w, c = run(a.cli, ["c1", "--input", points, "--dimension", "--report", report])
                r = json.load(open(report))
                stage.append(r["timings_seconds"]["dimension"])
                wall.append(w)
                cpu.append(c)
            print(f"dimension n={n}: stage {statistics.median(stage):.3f} s "
                  f"(process wall {statistics.median(wall):.2f} s, cpu {statistics.median(cpu):.2f} s), "
                  f"dimension {r['dimension']} = free {r['free_parameters']}, "
                  f"argument: {r['dimension_argument']}", flush=True)
        for n in sizes(a.exact):
            points = os.path.join(tmp, f"p{n}.xyz")
            write_points(points, n)
            rows = []
            for _ in range(a.repeats):
                w, c = run(a.cli, ["c1", "--input", points, "--exact", "--fit", a.fit,
                                   "--report", report])
                r = json.load(open(report))
                rows.append((w, c, r["timings_seconds"]["certify"], r["faces"], r["timings_seconds"]))
            wall = statistics.median(x[0] for x in rows)
            cpu = statistics.median(x[1] for x in rows)
            certify = statistics.median(x[2] for x in rows)
            faces = rows[0][3]
            stages = ", ".join(f"{k} {v:.2f}" for k, v in rows[-1][4].items())
            print(f"exact --fit {a.fit} n={n} ({faces} faces): {faces / wall:.0f} faces/s wall, "
                  f"{faces / cpu:.0f} faces/s cpu, certificate {faces / certify:.0f} faces/s; "
                  f"stages (s): {stages}", flush=True)


if __name__ == "__main__":
    main()
