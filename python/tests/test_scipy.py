# Against scipy's CloughTocher2DInterpolator where scipy is installed (never a dependency).
import numpy as np
import pytest

import tspline

interpolate = pytest.importorskip("scipy.interpolate")


def test_same_hull_same_data_linear_reproduction():
    rng = np.random.default_rng(11)
    p = rng.random((300, 2))
    z = np.exp(p[:, 0]) * np.sin(2 * p[:, 1])
    f = tspline.C1Interpolator(p, z)
    s = interpolate.CloughTocher2DInterpolator(p, z)
    q = np.vstack([rng.random((2000, 2)) * 1.2 - 0.1, p])
    fq, sq = f(q), s(q)
    # the same domain: the convex hull of the points (NaN at the same queries, up to
    # points within rounding of a hull edge)
    differ = np.isnan(fq) != np.isnan(sq)
    assert differ.sum() <= 2
    both = ~np.isnan(fq) & ~np.isnan(sq)
    # both interpolate the data
    np.testing.assert_allclose(f(p), z, atol=1e-13)
    np.testing.assert_allclose(s(p), z, atol=1e-13)
    # both are close to the function; the quintic closer (accuracy of the manual)
    exact = np.exp(q[both, 0]) * np.sin(2 * q[both, 1])
    assert np.abs(fq[both] - exact).max() < np.abs(sq[both] - exact).max()
    assert np.abs(fq[both] - sq[both]).max() < 5e-2
    # linear data: both reproduce them, scipy up to the tolerance of its iterative gradient
    # estimate (tol=1e-6), tspline up to rounding
    lin = 2 * p[:, 0] - p[:, 1]
    inside = q[both]
    exact_lin = 2 * inside[:, 0] - inside[:, 1]
    np.testing.assert_allclose(tspline.C1Interpolator(p, lin)(inside), exact_lin, atol=1e-13)
    np.testing.assert_allclose(interpolate.CloughTocher2DInterpolator(p, lin)(inside), exact_lin,
                               atol=1e-6)
    # the same call shapes
    x, y = np.meshgrid(np.linspace(0.2, 0.8, 7), np.linspace(0.2, 0.8, 5))
    assert f(x, y).shape == s(x, y).shape == (5, 7)
