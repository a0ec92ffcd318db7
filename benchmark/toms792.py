#!/usr/bin/python3
"""TOMS 792 accuracy test of `tspline c1` beside scipy's CloughTocher2DInterpolator.

The test suite is that of ACM Algorithm 792 (R. J. Renka and R. Brown, "Algorithm 792:
accuracy tests of ACM algorithms for interpolation of scattered data in the plane", ACM
TOMS 25(1), 1999, 78-94), which took it from ACM Algorithm SURVEY:

* the five node sets of its subroutine TESTDT: 1 Franke's 100 nodes, 2 Franke's 33 nodes,
  3 Lawson's 25 nodes, 4 a random 100-node set, 5 the 9 x 9 uniform grid (81 nodes). The
  hulls of sets 1 and 3 stick out of the unit square without covering it, those of sets 2
  and 5 are the unit square, that of set 4 is a large part of it. The coordinates below are
  transcribed from the DATA statements of TESTDT (public copy: toms792/toms792.f in the
  GitHub repository johannesgerer/jburkardt-f77);
* the ten test functions of its subroutine TSTFN1, re-written here in numpy: Franke's six
  (1 Exponential, 2 Cliff, 3 Saddle, 4 Gentle, 5 Steep, 6 Sphere) and Renka's four
  (7 Trig, 8 Synergistic Gaussian, 9 Cloverleaf asymmetric peak/valley, 10 Cosine peak).
  As in TSTFN1, function 6 is 0 outside the circle of radius 8/9 about (1/2, 1/2).

For each node set and function the data are the function's values at the nodes; each method
interpolates them and is evaluated on the 33 x 33 uniform grid (i/32, j/32) of the unit
square, at the grid points inside (or on) the convex hull of the nodes only. The measure is

    SSE/SSM = sum (s - f)^2 / sum (f - mean f)^2

over those grid points (s the interpolant, f the true function, mean f their mean). 0 is
exact; 1 is as bad as the constant mean. The tables give it per function, and its average
over the ten functions per node set. (Algorithm 792's own driver CS2TST sums over all 1089
grid points, as its methods extrapolate; the numbers here are therefore not directly
comparable with the paper's where a hull does not cover the square: sets 1, 3, 4.)

Methods: `tspline c1 --fit FIT` for every FIT of --fits (a spec 'local:3' means
'--fit local --degree 3', 'energy:t=2' '--fit energy --tension 2', as in convergence.py),
run on a temporary `.xyz` file with
`--query`/`--values`; and scipy.interpolate.CloughTocher2DInterpolator on the same nodes
(skipped if scipy is not installed). A data set that tspline rejects is reported, not fatal;
a NaN at a grid point inside the hull is reported and that point left out of the sums.

Usage: toms792.py [--tspline PATH] [--fits local,local:3,tangent] [--sets 1,2,3,4,5]
                  [--markdown]
Needs numpy; scipy is optional.
"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from convergence import fit_arguments  # noqa: E402

# Node sets 1-5 of TESTDT (ACM Algorithm 792 / SURVEY), in TESTDT's order: (x, y) pairs.
NODE_SETS = {
    1: ("Franke's 100-node set", [
        (0.0227035, -0.0310206), (0.0539888, 0.1586742), (0.0217008, 0.2576924),
        (0.0175129, 0.3414014), (0.0019029, 0.4943596), (-0.0509685, 0.5782854),
        (0.0395408, 0.6993418), (-0.0487061, 0.7470194), (0.0315828, 0.9107649),
        (-0.0418785, 0.996289), (0.1324189, 0.050133), (0.1090271, 0.0918555),
        (0.1254439, 0.2592973), (0.093454, 0.3381592), (0.0767578, 0.4171125),
        (0.1451874, 0.5615563), (0.0626494, 0.6552235), (0.1452734, 0.7524066),
        (0.0958668, 0.9146523), (0.0695559, 0.9632421), (0.2645602, 0.0292939),
        (0.2391645, 0.0602303), (0.208899, 0.2668783), (0.2767329, 0.3696044),
        (0.1714726, 0.4801738), (0.2266781, 0.5940595), (0.1909212, 0.6878797),
        (0.1867647, 0.8185576), (0.2304634, 0.9046507), (0.2426219, 0.9805412),
        (0.3663168, 0.0396955), (0.3857662, 0.0684484), (0.3832392, 0.2389548),
        (0.3179087, 0.3124129), (0.3466321, 0.4902989), (0.3776591, 0.5199303),
        (0.3873159, 0.6445227), (0.3812917, 0.8203789), (0.3795364, 0.8938079),
        (0.2803515, 0.9711719), (0.4149771, -0.0284618), (0.4277679, 0.1560965),
        (0.420001, 0.2262471), (0.4663631, 0.3175094), (0.4855658, 0.3891417),
        (0.4092026, 0.5084949), (0.4792578, 0.6324247), (0.4812279, 0.7511007),
        (0.3977761, 0.8489712), (0.4027321, 0.9978728), (0.5848691, -0.0271948),
        (0.5730076, 0.127243), (0.6063893, 0.2709269), (0.5013894, 0.3477728),
        (0.5741311, 0.4259422), (0.6106955, 0.6084711), (0.5990105, 0.6733781),
        (0.5380621, 0.7235242), (0.6096967, 0.9242411), (0.5026188, 1.0308762),
        (0.6616928, 0.0255959), (0.6427836, 0.0707835), (0.6396475, 0.2008336),
        (0.6703963, 0.3259843), (0.7001181, 0.4890704), (0.633359, 0.5096324),
        (0.6908947, 0.669788), (0.6895638, 0.7759569), (0.6718889, 0.9366096),
        (0.6837675, 1.0064516), (0.7736939, 0.0285374), (0.7635332, 0.1021403),
        (0.7410424, 0.1936581), (0.8258981, 0.3235775), (0.7306034, 0.4714228),
        (0.8086609, 0.6091595), (0.8214531, 0.6685053), (0.729064, 0.8022808),
        (0.8076643, 0.847679), (0.8170951, 1.0512371), (0.8424572, 0.0380499),
        (0.8684053, 0.0902048), (0.8366923, 0.2083092), (0.9418461, 0.3318491),
        (0.8478122, 0.4335632), (0.8599583, 0.5910139), (0.91757, 0.6307383),
        (0.8596328, 0.8144841), (0.9279871, 0.904231), (0.8512805, 0.969603),
        (1.044982, -0.01209), (0.9670631, 0.1334114), (0.9857884, 0.2695844),
        (0.9676313, 0.3795281), (1.0129299, 0.4396054), (0.965704, 0.5044425),
        (1.0019855, 0.6941519), (1.0359297, 0.7459923), (1.0414677, 0.8682081),
        (0.9471506, 0.9801409),
    ]),
    2: ("Franke's 33-node set", [
        (0.05, 0.45), (0.0, 0.5), (0.0, 1.0),
        (0.0, 0.0), (0.1, 0.15), (0.1, 0.75),
        (0.15, 0.3), (0.2, 0.1), (0.25, 0.2),
        (0.3, 0.35), (0.35, 0.85), (0.5, 0.0),
        (0.5, 1.0), (0.55, 0.95), (0.6, 0.25),
        (0.6, 0.65), (0.6, 0.85), (0.65, 0.7),
        (0.7, 0.2), (0.7, 0.65), (0.7, 0.9),
        (0.75, 0.1), (0.75, 0.35), (0.75, 0.85),
        (0.8, 0.4), (0.8, 0.65), (0.85, 0.25),
        (0.9, 0.35), (0.9, 0.8), (0.95, 0.9),
        (1.0, 0.0), (1.0, 0.5), (1.0, 1.0),
    ]),
    3: ("Lawson's 25-node set", [
        (0.1375, 0.975), (0.9125, 0.9875), (0.7125, 0.7625),
        (0.225, 0.8375), (-0.05, 0.4125), (0.475, 0.6375),
        (0.05, -0.05), (0.45, 1.0375), (1.0875, 0.55),
        (0.5375, 0.8), (-0.0375, 0.75), (0.1875, 0.575),
        (0.7125, 0.55), (0.85, 0.4375), (0.7, 0.3125),
        (0.275, 0.425), (0.45, 0.2875), (0.8125, 0.1875),
        (0.45, -0.0375), (1.0, 0.2625), (0.5, 0.4625),
        (0.1875, 0.2625), (0.5875, 0.125), (1.05, -0.06125),
        (0.1, 0.1125),
    ]),
    4: ("Random 100-node set", [
        (0.0096326, 0.3083158), (0.0216348, 0.2450434), (0.029836, 0.8613847),
        (0.0417447, 0.0977864), (0.0470462, 0.3648355), (0.0562965, 0.7156339),
        (0.0646857, 0.5311312), (0.0740377, 0.9755672), (0.0873907, 0.1781117),
        (0.0934832, 0.5452797), (0.1032216, 0.1603881), (0.1110176, 0.7837139),
        (0.1181193, 0.9982015), (0.1251704, 0.6910589), (0.132733, 0.104958),
        (0.1439536, 0.8184662), (0.1564861, 0.7086405), (0.1651043, 0.4456593),
        (0.1786039, 0.1178342), (0.1886405, 0.3189021), (0.2016706, 0.9668446),
        (0.2099886, 0.7571834), (0.2147003, 0.2016598), (0.2204141, 0.3232444),
        (0.2343715, 0.4368583), (0.240966, 0.8907869), (0.252774, 0.064726),
        (0.2570839, 0.5692618), (0.2733365, 0.2947027), (0.2853833, 0.4332426),
        (0.2901755, 0.3347464), (0.2964854, 0.7436284), (0.3019725, 0.1066265),
        (0.3125695, 0.8845357), (0.3307163, 0.515873), (0.3378504, 0.9425637),
        (0.3439061, 0.4799701), (0.3529922, 0.1783069), (0.3635507, 0.114676),
        (0.3766172, 0.8225797), (0.3822429, 0.2270688), (0.3869838, 0.4073598),
        (0.3973137, 0.887508), (0.4170708, 0.7631616), (0.4255588, 0.9972804),
        (0.4299218, 0.4959884), (0.4372839, 0.3410421), (0.4705033, 0.249812),
        (0.4736655, 0.6409007), (0.4879299, 0.105869), (0.494026, 0.5411969),
        (0.5055324, 0.0089792), (0.5162593, 0.8784268), (0.5219219, 0.5515874),
        (0.5348529, 0.4038952), (0.5483213, 0.1654023), (0.5569571, 0.2965158),
        (0.5638611, 0.3660356), (0.5784908, 0.0366554), (0.586395, 0.950242),
        (0.5929148, 0.2638101), (0.5987839, 0.9277386), (0.6117561, 0.5377694),
        (0.6252296, 0.7374676), (0.6331381, 0.4674627), (0.6399048, 0.9186109),
        (0.6488972, 0.0416884), (0.6558537, 0.1291029), (0.6677405, 0.6763676),
        (0.6814074, 0.8444238), (0.6887812, 0.3273328), (0.6940896, 0.1893879),
        (0.7061687, 0.0645923), (0.7160957, 0.0180147), (0.7317445, 0.8904992),
        (0.7370798, 0.4160648), (0.746203, 0.4688995), (0.7566957, 0.2174508),
        (0.7699998, 0.5734231), (0.7879347, 0.8853319), (0.7944014, 0.8018436),
        (0.8164468, 0.6388941), (0.8192794, 0.8931002), (0.8368405, 0.1000558),
        (0.8500993, 0.2789506), (0.8588255, 0.9082948), (0.8646496, 0.3259159),
        (0.8792329, 0.8318747), (0.8837536, 0.0508513), (0.8900077, 0.970845),
        (0.8969894, 0.5120548), (0.9044917, 0.2859716), (0.9083947, 0.9581641),
        (0.9203972, 0.6183429), (0.9347906, 0.3779934), (0.9434519, 0.4010423),
        (0.9490328, 0.9478657), (0.9569571, 0.7425486), (0.9772067, 0.8883287),
        (0.9983493, 0.549675),
    ]),
    5: ("9 x 9 grid, 81 nodes", [
        (0.125, 0.0), (0.0, 0.125), (0.0, 0.25),
        (0.0, 0.375), (0.0, 0.5), (0.0, 0.625),
        (0.0, 0.75), (0.0, 0.875), (0.0, 1.0),
        (0.0, 0.0), (0.125, 0.125), (0.125, 0.25),
        (0.125, 0.375), (0.125, 0.5), (0.125, 0.625),
        (0.125, 0.75), (0.125, 0.875), (0.125, 1.0),
        (0.25, 0.0), (0.25, 0.125), (0.25, 0.25),
        (0.25, 0.375), (0.25, 0.5), (0.25, 0.625),
        (0.25, 0.75), (0.25, 0.875), (0.25, 1.0),
        (0.375, 0.0), (0.375, 0.125), (0.375, 0.25),
        (0.375, 0.375), (0.375, 0.5), (0.375, 0.625),
        (0.375, 0.75), (0.375, 0.875), (0.375, 1.0),
        (0.5, 0.0), (0.5, 0.125), (0.5, 0.25),
        (0.5, 0.375), (0.5, 0.5), (0.5, 0.625),
        (0.5, 0.75), (0.5, 0.875), (0.5, 1.0),
        (0.625, 0.0), (0.625, 0.125), (0.625, 0.25),
        (0.625, 0.375), (0.625, 0.5), (0.625, 0.625),
        (0.625, 0.75), (0.625, 0.875), (0.625, 1.0),
        (0.75, 0.0), (0.75, 0.125), (0.75, 0.25),
        (0.75, 0.375), (0.75, 0.5), (0.75, 0.625),
        (0.75, 0.75), (0.75, 0.875), (0.75, 1.0),
        (0.875, 0.0), (0.875, 0.125), (0.875, 0.25),
        (0.875, 0.375), (0.875, 0.5), (0.875, 0.625),
        (0.875, 0.75), (0.875, 0.875), (0.875, 1.0),
        (1.0, 0.0), (1.0, 0.125), (1.0, 0.25),
        (1.0, 0.375), (1.0, 0.5), (1.0, 0.625),
        (1.0, 0.75), (1.0, 0.875), (1.0, 1.0),
    ]),
}


# The ten test functions of TSTFN1 (values only).
def exponential(x, y):
    return (0.75 * np.exp(-((9 * x - 2) ** 2 + (9 * y - 2) ** 2) / 4)
            + 0.75 * np.exp(-((9 * x + 1) ** 2) / 49 - (9 * y + 1) / 10)
            + 0.5 * np.exp(-((9 * x - 7) ** 2 + (9 * y - 3) ** 2) / 4)
            - 0.2 * np.exp(-(9 * x - 4) ** 2 - (9 * y - 7) ** 2))


def cliff(x, y):
    return (np.tanh(9 * (y - x)) + 1) / 9


def saddle(x, y):
    return (1.25 + np.cos(5.4 * y)) / (6 + 6 * (3 * x - 1) ** 2)


def gentle(x, y):
    return np.exp(-5.0625 * ((x - 0.5) ** 2 + (y - 0.5) ** 2)) / 3


def steep(x, y):
    return np.exp(-20.25 * ((x - 0.5) ** 2 + (y - 0.5) ** 2)) / 3


def sphere(x, y):
    t = 64 - 81 * ((x - 0.5) ** 2 + (y - 0.5) ** 2)
    return np.where(t >= 0, np.sqrt(np.maximum(t, 0)) / 9 - 0.5, 0.0)


def trig(x, y):
    return 2 * np.cos(10 * x) * np.sin(10 * y) + np.sin(10 * x * y)


def synergistic_gaussian(x, y):
    gx = np.exp(-0.5 * (5 - 10 * x) ** 2)
    gy = np.exp(-0.5 * (5 - 10 * y) ** 2)
    return gx + 0.75 * gy * (1 + gx)


def cloverleaf(x, y):
    t1 = np.exp((10 - 20 * x) / 3)
    t2 = np.exp((10 - 20 * y) / 3)
    t3 = 1 / (1 + t1)
    t4 = 1 / (1 + t2)
    return ((20 / 3) ** 3 * t1 * t2) ** 2 * (t3 * t4) ** 5 * (t1 - 2 * t3) * (t2 - 2 * t4)


def cosine_peak(x, y):
    r = np.sqrt((80 * x - 40) ** 2 + (90 * y - 45) ** 2)
    return np.exp(-0.04 * r) * np.cos(0.15 * r)


FUNCTIONS = [("Exponential", exponential), ("Cliff", cliff), ("Saddle", saddle),
             ("Gentle", gentle), ("Steep", steep), ("Sphere", sphere), ("Trig", trig),
             ("Synergistic Gaussian", synergistic_gaussian), ("Cloverleaf", cloverleaf),
             ("Cosine peak", cosine_peak)]


def convex_hull(points):
    """Vertices of the convex hull, counter-clockwise (Andrew's monotone chain)."""
    pts = sorted(map(tuple, points))

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    def chain(seq):
        out = []
        for p in seq:
            while len(out) >= 2 and cross(out[-2], out[-1], p) <= 0:
                out.pop()
            out.append(p)
        return out[:-1]

    return np.array(chain(pts) + chain(pts[::-1]))


def inside_hull(hull, q, tol=1e-12):
    """True for the query points inside or on the (counter-clockwise) convex hull."""
    inside = np.ones(len(q), dtype=bool)
    for a, b in zip(hull, np.roll(hull, -1, axis=0)):
        edge = b - a
        cross = edge[0] * (q[:, 1] - a[1]) - edge[1] * (q[:, 0] - a[0])
        inside &= cross >= -tol * np.hypot(*edge)
    return inside


def grid_points(ni=33):
    """The NI x NI grid (i/(NI-1), j/(NI-1)) of CS2TST, x varying slowest."""
    p = np.arange(ni) / (ni - 1)
    gx, gy = np.meshgrid(p, p, indexing="ij")
    return np.column_stack([gx.ravel(), gy.ravel()])


def run_tspline(tspline, points, values, queries, fit, extra, workdir):
    """Values at the queries, or (None, message) if tspline fails."""
    data = os.path.join(workdir, "data.xyz")
    query = os.path.join(workdir, "query.xy")
    out = os.path.join(workdir, "values.txt")
    if os.path.exists(out):
        os.remove(out)
    np.savetxt(data, np.column_stack([points, values]), fmt="%.17g")
    np.savetxt(query, queries, fmt="%.17g")
    run = subprocess.run([tspline, "c1", "--input", data, "--fit", fit, "--query", query,
                          "--values", out, *extra],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if run.returncode != 0:
        lines = [line for line in run.stderr.strip().splitlines() if line.strip()]
        return None, f"exit {run.returncode}: {lines[-1] if lines else '(no message)'}"
    v = np.atleast_1d(np.loadtxt(out))
    if v.size != len(queries):
        return None, f"{v.size} values for {len(queries)} queries"
    return v, ""


def sse_ssm(v, exact):
    """(SSE/SSM over the points where v is finite, number of non-finite v)."""
    ok = np.isfinite(v)
    ssm = np.sum((exact - exact.mean()) ** 2)
    return float(np.sum((v[ok] - exact[ok]) ** 2) / ssm), int(np.count_nonzero(~ok))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--tspline", default=os.path.join("build", "src", "tspline", "tspline"))
    parser.add_argument("--fits", default="local")
    parser.add_argument("--sets", default="1,2,3,4,5")
    parser.add_argument("--markdown", action="store_true")
    args = parser.parse_args()
    fits = [f for f in args.fits.split(",") if f]
    sets = [int(k) for k in args.sets.split(",") if k]
    try:
        from scipy.interpolate import CloughTocher2DInterpolator
    except ImportError:
        CloughTocher2DInterpolator = None
        print("(scipy not installed: no comparison column)", file=sys.stderr)
    columns = [f"tspline {f}" for f in fits]
    if CloughTocher2DInterpolator:
        columns.append("scipy CT")
    grid = grid_points()

    def row(cells):
        return ("| " + " | ".join(cells) + " |") if args.markdown else \
            "  ".join(c.ljust(w) for c, w in zip(cells, widths)).rstrip()

    averages = {}
    with tempfile.TemporaryDirectory() as workdir:
        for k in sets:
            name, nodes = NODE_SETS[k]
            nodes = np.array(nodes, dtype=float)
            queries = grid[inside_hull(convex_hull(nodes), grid)]
            print(f"\nNode set {k}: {name}, N = {len(nodes)}; SSE/SSM over the "
                  f"{len(queries)} of {len(grid)} grid points in the hull")
            header = ["function"] + columns
            widths = [24] + [max(12, len(c)) for c in columns]
            print(row(header))
            print(("|" + "---|" * len(header)) if args.markdown else
                  row(["-" * w for w in widths]))
            sums = {c: [] for c in columns}
            notes = []
            for j, (fname, f) in enumerate(FUNCTIONS, 1):
                z = f(nodes[:, 0], nodes[:, 1])
                exact = f(queries[:, 0], queries[:, 1])
                cells = [f"{j:2d} {fname}"]
                results = {}
                for fit in fits:
                    method, extra = fit_arguments(fit)
                    v, message = run_tspline(args.tspline, nodes, z, queries, method, extra,
                                             workdir)
                    if v is None:
                        results[f"tspline {fit}"] = None
                        notes.append(f"function {j}, tspline {fit}: rejected ({message})")
                    else:
                        results[f"tspline {fit}"] = v
                if CloughTocher2DInterpolator:
                    results["scipy CT"] = CloughTocher2DInterpolator(nodes, z)(queries)
                for c in columns:
                    if results[c] is None:
                        cells.append("failed")
                        sums[c].append(np.nan)
                        continue
                    e, missing = sse_ssm(results[c], exact)
                    sums[c].append(e)
                    cells.append(f"{e:.3e}" + (f" ({missing} nan)" if missing else ""))
                    if missing:
                        notes.append(f"function {j}, {c}: NaN at {missing} grid points "
                                     "in the hull (left out)")
                print(row(cells))
            averages[k] = {c: float(np.mean(sums[c])) for c in columns}
            print(row(["average"] + [f"{averages[k][c]:.3e}" for c in columns]))
            for note in notes:
                print(f"  note: {note}")

    print("\nAverage SSE/SSM over the ten functions")
    header = ["node set"] + columns + ["better on average"]
    widths = [10] + [max(12, len(c)) for c in columns] + [20]
    print(row(header))
    print(("|" + "---|" * len(header)) if args.markdown else row(["-" * w for w in widths]))
    for k in sets:
        a = averages[k]
        ok = {c: e for c, e in a.items() if np.isfinite(e)}
        ts = {c: e for c, e in ok.items() if c != "scipy CT"}
        if not ts:
            verdict = "tspline failed"
        elif "scipy CT" in ok:
            best = min(ts, key=ts.get)
            ratio = ok["scipy CT"] / ts[best] if ts[best] > 0 else np.inf
            verdict = (f"{best} ({ratio:.2f}x lower)" if ratio > 1 else
                       f"scipy CT ({1 / ratio:.2f}x lower than {best})")
        else:
            verdict = min(ts, key=ts.get)
        print(row([str(k)] + [f"{a[c]:.3e}" for c in columns] + [verdict]))


if __name__ == "__main__":
    main()
