# tspline.C1Interpolator: interpolation, reproduction, derivatives, query shapes, fill_value.
import numpy as np
import pytest

import tspline


def linear(p):
    return 1.5 + 3 * p[..., 0] - 2 * p[..., 1]


@pytest.mark.parametrize("fit", ["adaptive", "local", "energy", "lsq", "tangent", "interpolate"])
def test_values_at_data_points_reproduced(scattered, fit):
    p, z = scattered
    f = tspline.C1Interpolator(p, z, fit=fit)
    # the corner control point is the datum: exact up to the conversions of evaluation
    np.testing.assert_allclose(f(p), z, rtol=0, atol=1e-13)


def test_exact_build_interpolates_exactly(dyadic):
    p, z = dyadic
    f = tspline.C1Interpolator(p, z, exact=True)
    assert np.array_equal(f(p), z)


@pytest.mark.parametrize("fit", ["adaptive", "local", "energy", "tangent", "approximate"])
def test_linear_reproduction(scattered, fit):
    p, _ = scattered
    f = tspline.C1Interpolator(p, linear(p), fit=fit)
    q = np.random.default_rng(3).random((500, 2))
    # the energy fit's global solve runs in double: reproduced up to its rounding
    atol = 1e-10 if fit == "energy" else 1e-13
    np.testing.assert_allclose(f(q), linear(q), rtol=0, atol=atol)
    # gradients of a linear function: its constant slope everywhere
    g = f.gradient(q)
    assert g.shape == (500, 2)
    np.testing.assert_allclose(g, np.broadcast_to([3.0, -2.0], g.shape), rtol=0, atol=1e-9)
    h = f.hessian(q)
    assert h.shape == (500, 2, 2)
    np.testing.assert_allclose(h, 0, atol=1e-5 if fit == "energy" else 1e-7)


def test_gradient_matches_finite_differences(scattered):
    p, z = scattered
    f = tspline.C1Interpolator(p, z)
    q = np.array([[0.31, 0.47], [0.62, 0.18], [0.5, 0.83]])
    h = 1e-6
    ex, ey = np.array([h, 0]), np.array([0, h])
    fd = np.column_stack([(f(q + ex) - f(q - ex)) / (2 * h), (f(q + ey) - f(q - ey)) / (2 * h)])
    np.testing.assert_allclose(f.gradient(q), fd, rtol=0, atol=1e-7)
    # and the Hessian the gradient's differences
    gx = (f.gradient(q + ex) - f.gradient(q - ex)) / (2 * h)
    np.testing.assert_allclose(f.hessian(q)[:, 0, :], gx, rtol=0, atol=1e-5)


def test_query_shapes(scattered):
    p, z = scattered
    f = tspline.C1Interpolator(p, z)
    value = f(0.4, 0.6)
    assert isinstance(value, np.ndarray) and value.shape == ()
    assert f((0.4, 0.6)).shape == ()
    assert f([0.4, 0.6]).shape == ()
    assert f([[0.4, 0.6]]).shape == (1,)
    x, y = np.meshgrid(np.linspace(0.1, 0.9, 5), np.linspace(0.1, 0.9, 3))
    grid = f(x, y)
    assert grid.shape == (3, 5)
    assert np.array_equal(grid, f((x, y)))
    assert np.array_equal(grid, f(np.stack([x, y], axis=-1)))
    # broadcasting as scipy: a column of x against a row of y
    assert f(np.linspace(0.1, 0.9, 4)[:, None], np.linspace(0.1, 0.9, 6)).shape == (4, 6)
    assert f.gradient(x, y).shape == (3, 5, 2)
    assert f.hessian(x, y).shape == (3, 5, 2, 2)
    assert f.jets(x, y).shape == (3, 5, 6)
    assert f(np.empty((0, 2))).shape == (0,)
    # points as a tuple of coordinate arrays, as scipy accepts
    g = tspline.C1Interpolator((p[:, 0], p[:, 1]), z)
    assert np.array_equal(g(x, y), grid)


def test_fill_value_outside_the_hull(scattered):
    p, z = scattered
    outside = np.array([[1.5, 0.5], [-0.1, 0.2], [0.5, 2.0]])
    assert np.isnan(tspline.C1Interpolator(p, z)(outside)).all()
    f = tspline.C1Interpolator(p, z, fill_value=-9999)
    assert np.array_equal(f(outside), [-9999.0] * 3)
    assert np.array_equal(f.gradient(outside)[:, 0], [-9999.0] * 3)
    assert f(0.5, 0.5) != -9999
    assert np.isnan(tspline.C1Interpolator(p, z)(np.nan, 0.5))


def test_extrapolation_modes(scattered):
    p, _ = scattered
    f = tspline.C1Interpolator(p, linear(p), outside="linear")
    q = np.array([[1.5, 0.5], [-0.5, -0.5]])
    np.testing.assert_allclose(f(q), linear(q), atol=1e-9)
    g = tspline.C1Interpolator(p, linear(p), outside="nearest")
    np.testing.assert_allclose(g(1.5, 0.5), linear(np.array([1.0, 0.5])), atol=1e-9)


def test_given_gradients_are_interpolated(scattered):
    p, z = scattered
    grad = np.column_stack([np.exp(p[:, 0]) * np.sin(2 * p[:, 1]),
                            2 * np.exp(p[:, 0]) * np.cos(2 * p[:, 1])])
    f = tspline.C1Interpolator(p, z, gradients=grad)
    interior = (p > 0.05).all(axis=1) & (p < 0.95).all(axis=1)
    np.testing.assert_allclose(f.gradient(p[interior]), grad[interior], atol=1e-10)


def test_properties(scattered):
    p, z = scattered
    f = tspline.C1Interpolator(p, z)
    assert np.array_equal(f.points, p)  # in input order
    s = f.simplices
    assert s.shape[1] == 3 and s.min() == 0 and s.max() == len(p) - 1
    assert f.degree == 5 and not f.exact
    i = f.info
    assert i["vertices"] == len(p) and i["faces"] == len(s) and i["fit"] == "adaptive"
    # random signs on the free points outside the corner regions stay near a sign's size
    assert 1 <= i["propagation_amplification"] <= 2 * 16 + 1
    assert i["near_singular_vertices"] >= 0
    assert i["plan_rounds"] in (1, 2)  # 2: a dependency cycle of thin re-routings was broken
    # 3V + 3F + E_I + 3E_B + sigma, Morgan-Scott's dimension on a generic triangulation
    d = f.dimension()
    assert f.free_parameters == d["free_parameters"] == d["upper_bound"] == d["lower_bound"]
    assert d["proven"] and d["lower_bound_proven"] and d["dimension"] == d["upper_bound"]
    assert d["primes_tried"] == 1 and d["prime"] > 2**30 and not d["rational_rank"]
    assert "C1Interpolator" in repr(f)


def test_rescale_anisotropic():
    rng = np.random.default_rng(5)
    p = rng.random((100, 2)) * [1.0, 1e-6]
    z = np.sin(3 * p[:, 0]) + np.cos(2e6 * p[:, 1])
    f = tspline.C1Interpolator(p, z, rescale=True)
    assert f.info["rescale_y_factor"] == 2.0**20
    np.testing.assert_allclose(f(p), z, atol=1e-12)
    assert f.certify()["certified"]


def test_with_values_reuses_the_triangulation(scattered):
    p, z = scattered
    f = tspline.C1Interpolator(p, z)
    g = f.with_values(linear(p))
    assert type(g) is tspline.C1Interpolator
    assert np.array_equal(g.simplices, f.simplices)
    q = np.random.default_rng(4).random((100, 2))
    np.testing.assert_allclose(g(q), linear(q), atol=1e-11)
    # the same as building anew (same triangulation, same fit)
    np.testing.assert_allclose(g(q), tspline.C1Interpolator(p, linear(p))(q), atol=1e-13)
    # the original is untouched
    np.testing.assert_allclose(f(p), z, atol=1e-13)
    with pytest.raises(ValueError, match=r"values: expected an array of shape \(200,\)"):
        f.with_values(z[:10])


def test_tension():
    # 30 points of a cliff: the adaptive fit's tension (default 2) is reported and used;
    # tension=0 is the thin plate alone; energy's default is 0; with_values keeps it.
    p = np.random.default_rng(7).random((30, 2))
    z = np.tanh(9 * (p[:, 1] - p[:, 0]))
    q = np.random.default_rng(8).random((200, 2)) * 0.8 + 0.1
    default = tspline.C1Interpolator(p, z)
    assert default.info["tension"] == 2.0
    assert np.array_equal(tspline.C1Interpolator(p, z, tension=2)(q), default(q), equal_nan=True)
    plain = tspline.C1Interpolator(p, z, tension=0)
    assert plain.info["tension"] == 0.0
    assert not np.allclose(plain(q), default(q), equal_nan=True)
    assert tspline.C1Interpolator(p, z, fit="energy").info["tension"] == 0.0
    tense = tspline.C1Interpolator(p, z, fit="energy", tension=5)
    np.testing.assert_allclose(tense(p), z, rtol=0, atol=1e-13)  # still interpolates
    again = plain.with_values(z)
    assert np.array_equal(again(q), plain(q), equal_nan=True)


def test_solver_statistics():
    # The global fits report their solve: small sets in one direct solve; the local fit
    # solves nothing, hence no entry.
    p = np.random.default_rng(11).random((200, 2))
    z = np.sin(3 * p[:, 0]) * p[:, 1]
    for fit in ("energy", "lsq"):
        solver = tspline.C1Interpolator(p, z, fit=fit).info["solver"]
        assert solver["method"] == "direct"
        assert solver["sweeps"] == 1 and solver["windows_per_sweep"] == 0
        assert solver["window_solves"] == 1 and solver["converged"]
    assert "solver" not in tspline.C1Interpolator(p, z, fit="local").info


def test_certify_exact_is_a_proof(dyadic):
    p, z = dyadic
    c = tspline.C1Interpolator(p, z, exact=True).certify()
    assert c["verdict"] == "proof" and c["proof"] and c["exact"]
    assert c["failed_edges"] == 0 and c["max_residual"] == 0
    e = c["edges"]
    assert len(e["edge"]) == c["interior_edges"] > 0
    assert e["vertices"].shape == (c["interior_edges"], 2)
    assert e["c1"].all() and e["zero"].all()
    # a double build is certified within its round-off, never a proof
    d = tspline.C1Interpolator(p, z).certify()
    assert d["verdict"] == "within_tolerance" and not d["proof"] and d["certified"]
    # with tolerance 0 its round-off fails
    assert tspline.C1Interpolator(p, z).certify(tolerance=0)["verdict"] == "failed"


def test_mann(scattered, dyadic):
    p, z = scattered
    f = tspline.MannInterpolator(p, z)
    np.testing.assert_allclose(f(p), z, atol=1e-12)
    assert f.degree == 5 and f.info["continuity"] == 1
    assert f.certify()["certified"]
    assert f.free_parameters is None
    with pytest.raises(ValueError, match="with_values"):
        f._core.with_values(z.reshape(-1, 1))
    g = tspline.MannInterpolator(p, linear(p))
    np.testing.assert_allclose(g(0.3, 0.7), linear(np.array([0.3, 0.7])), atol=1e-10)
    assert tspline.MannInterpolator(*dyadic, exact=True).certify()["verdict"] == "proof"


def test_flat_hull_triangles_of_a_jittered_grid_are_removed():
    # A grid whose coordinates carry rounding: the slivers closing its hull are removed, every
    # hull point is on the boundary, and queries on the old hull lines are snapped (no NaN).
    rng = np.random.default_rng(8)
    n = 24
    g = np.arange(n + 1) / n
    p = np.array([(x, y) for x in g for y in g]) + 1e-14 * (rng.random(((n + 1) ** 2, 2)) - 0.5)
    z = np.exp(p[:, 0]) * np.sin(2 * p[:, 1])
    f = tspline.C1Interpolator(p, z)
    i = f.info
    assert i["flat_hull_faces_removed"] > 0
    assert i["boundary_edges"] == 4 * n and i["vertices"] == (n + 1) ** 2
    assert f.certify()["certified"]
    t = rng.random(1000)
    q = np.concatenate([np.c_[0 * t, t], np.c_[t, 0 * t], np.c_[1 + 0 * t, t], np.c_[t, 1 + 0 * t]])
    err = np.abs(f(q) - np.exp(q[:, 0]) * np.sin(2 * q[:, 1]))
    assert np.all(err < 1e-6)
