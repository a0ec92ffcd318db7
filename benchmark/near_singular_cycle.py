#!/usr/bin/python3
"""The links around a near-singular vertex (issue 10, item 1): why single propagation weights
grow without bound there, and that the rules written directly in the free data do not.

At an interior vertex r with k edges, the corner diamond of edge i (faces i-1 and i) reads

    star_i = mu_b CI_{i-1} + mu_a CI_i + mu_e EM_i,   r = mu_b p_{i-1} + mu_e p_i + mu_a p_{i+1}

(CI: corner-inner points, EM: the edge-middle point next to r). Printed here:

1. The product of the link ratios -mu_b/mu_a around r is (-1)^k for every geometry, so the
   cycle of links with the edge points given is singular for every even k. A vertex of degree
   4 cannot close its cycle of links: one corner-inner point stays free and one link is solved
   for its edge point (the plan's "regular link" at a near-singular vertex).
2. At vertices of degree 4 whose edges are eps radians from two lines (near-singular), that
   plan's single weights (1/mu_a, 1/mu_e, ...) grow as 1/eps, but the same rules written
   directly in the free data (the corner frame's plane a + b.x, the free corner-inner point and
   the other edge points; b scaled by the shortest edge) keep coefficients of about 10: the
   cancellation the amplification measure sees. A bounded plan needs rules with up to 8 sources.

usage: benchmark/near_singular_cycle.py [--trials 300]
"""
import argparse

import numpy as np


def barycentric(x, a, b, c):
    t = np.array([[a[0], b[0], c[0]], [a[1], b[1], c[1]], [1, 1, 1]])
    return np.linalg.solve(t, [x[0], x[1], 1])


def links(points):
    """mu_b, mu_e, mu_a of every edge of the star of the origin."""
    k = len(points)
    mu = np.array([barycentric(np.zeros(2), points[(i - 1) % k], points[i], points[(i + 1) % k])
                   for i in range(k)])
    return mu[:, 0], mu[:, 1], mu[:, 2]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--trials", type=int, default=300)
    a = parser.parse_args()
    rng = np.random.default_rng(2)

    print("1. product of -mu_b/mu_a around random vertices")
    for k in range(3, 9):
        products = []
        for _ in range(a.trials):
            angles = np.sort(rng.uniform(0, 2 * np.pi, k))
            if np.max(np.diff(np.append(angles, angles[0] + 2 * np.pi))) >= np.pi:
                continue  # not an interior vertex
            radii = rng.uniform(0.5, 2, k)
            mb, _, ma = links(np.column_stack([radii * np.cos(angles), radii * np.sin(angles)]))
            products.append(np.prod(-mb / ma))
        print(f"   k = {k}: {len(products)} vertices, product in "
              f"[{min(products):.12f}, {max(products):.12f}]")

    print("2. degree-4 vertices eps from two lines: largest |coefficient|")
    print(f"   {'eps':>7} {'single weight':>14} {'edge point':>11} {'corner-inner':>13}")
    k = 4
    for eps in [1e-2, 1e-4, 1e-6, 1e-8]:
        single = edge = inner = 0.0
        for _ in range(a.trials):
            angles = np.arange(k) * np.pi / 2 + rng.uniform(0.3, 1.2) + eps * rng.standard_normal(k)
            radii = rng.uniform(0.5, 2, k)
            p = np.column_stack([radii * np.cos(angles), radii * np.sin(angles)])
            mb, me, ma = links(p)
            c = int(np.argmax(np.abs(me)))  # the closing link: the least thin
            # unknowns: a, b_x, b_y (the frame's plane), the free CI, EM_0 .. EM_3
            n = 4 + k
            unit = np.eye(n)
            star = [unit[0] + p[i, 0] / 5 * unit[1] + p[i, 1] / 5 * unit[2] for i in range(k)]
            ci = {c: unit[3]}
            for s in range(1, k):  # solve the links away from the free CI
                i = (c + s) % k
                ci[i] = (star[i] - mb[i] * ci[(i - 1) % k] - me[i] * unit[4 + i]) / ma[i]
                single = max(single, abs(1 / ma[i]), abs(mb[i] / ma[i]), abs(me[i] / ma[i]))
            closing = (star[c] - mb[c] * ci[(c - 1) % k] - ma[c] * ci[c]) / me[c]
            single = max(single, abs(1 / me[c]), abs(ma[c] / me[c]), abs(mb[c] / me[c]))
            h = radii.min()
            closing[1:3] *= h
            closing[4 + c] = 0
            edge = max(edge, np.abs(closing).max())
            for v in ci.values():
                w = v.copy()
                w[1:3] *= h
                inner = max(inner, np.abs(w).max())
        print(f"   {eps:7.0e} {single:14.3g} {edge:11.3g} {inner:13.3g}")


if __name__ == "__main__":
    main()
