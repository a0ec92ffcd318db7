#!/usr/bin/env python3
"""The comparison table of the manual's pseudo-AG^1 section: tspline pseudo-ag1 on the thesis'
solids and on real meshes, with PN triangles and Fang's order-1 blend measured on the same
mesh by the same code (normal jumps from exact derivatives at 15 points per edge).

usage: pseudo_ag1_table.py --tspline PATH [--meshes DIR] [--preset P]
DIR holds CGAL's sample meshes (Debian libcgal-demo: data.tar.gz, data/meshes); those not
found are skipped.
"""
import argparse
import json
import os
import subprocess
import tempfile

SHAPES = ["tetrahedron", "sato", "octahedron", "cube", "cube-centres", "icosahedron",
          "pentakis", "torus", "star"]
MESHES = ["elephant.off", "knot1.off", "blobby.off", "bull.off", "homer.off", "camel.off",
          "armadillo.off"]


def run(tspline, args):
    with tempfile.TemporaryDirectory() as tmp:
        report = os.path.join(tmp, "r.json")
        subprocess.run([tspline, "pseudo-ag1", *args, "--report", report], check=True,
                       stdout=subprocess.DEVNULL)
        with open(report) as f:
            return json.load(f)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--tspline", required=True)
    p.add_argument("--meshes", default="")
    p.add_argument("--preset", default="smooth")
    a = p.parse_args()
    inputs = [("--shape", s, s) for s in SHAPES]
    for m in MESHES:
        path = os.path.join(a.meshes, m)
        if a.meshes and os.path.exists(path):
            inputs.append(("--input", path, m))
    print("| mesh | faces | pseudo-AG1 max / mean jump (deg) | volume ratio | PN max / mean | "
          "Fang d=1 mean | input bend | s |")
    print("|---|---|---|---|---|---|---|---|")
    for flag, value, name in inputs:
        r = run(a.tspline, [flag, value, "--preset", a.preset])
        j = r["normal_jump_deg"]
        pn = r["comparison"]["pn_triangles"]["normal_jump_deg"]
        fang = r["comparison"]["fang_order1"]
        fang_mean = fang["normal_jump_deg"]["mean"] if "normal_jump_deg" in fang else float("nan")
        build = r["timings"]["build"]
        print(f"| {name} | {r['faces']} | {j['max']:.1f} / {j['mean']:.2f} | "
              f"{r['volume_ratio']:.2f} | {pn['max']:.1f} / {pn['mean']:.2f} | {fang_mean:.2f} | "
              f"{j['input_mean_bend']:.1f} | {build:.2f} |")


if __name__ == "__main__":
    main()
