# Failure paths: bad input is a ValueError carrying the library's message.
import numpy as np
import pytest

import tspline

SQUARE = np.array([[0, 0], [1, 0], [0, 1], [1, 1], [0.5, 0.4]])
Z = np.array([0.0, 1, 2, 3, 4])


def test_nan_value():
    z = Z.copy()
    z[2] = np.nan
    with pytest.raises(ValueError, match="^fit: non-finite data value$"):
        tspline.C1Interpolator(SQUARE, z)


def test_nan_point():
    p = SQUARE.copy()
    p[3, 0] = np.inf
    with pytest.raises(ValueError, match="point 3 has a non-finite coordinate"):
        tspline.C1Interpolator(p, Z)


def test_duplicate_points():
    p = np.vstack([SQUARE, SQUARE[1]])
    with pytest.raises(ValueError, match="^scattered data: 1 points repeat an earlier point$"):
        tspline.C1Interpolator(p, np.append(Z, 9))


@pytest.mark.parametrize("n", [0, 1, 2])
def test_too_few_points(n):
    with pytest.raises(ValueError, match="collinear: no triangle"):
        tspline.C1Interpolator(SQUARE[:n], Z[:n])


def test_collinear_points():
    p = np.column_stack([np.arange(5.0), 2 * np.arange(5.0)])
    with pytest.raises(ValueError, match="^scattered data: all 5 points are collinear"):
        tspline.C1Interpolator(p, Z)


@pytest.mark.parametrize("points, values, message", [
    (SQUARE[:, 0], Z, r"points: expected an array of shape \(n, 2\), got shape \(5,\)"),
    (np.ones((5, 3)), Z, r"points: expected an array of shape \(n, 2\), got shape \(5, 3\)"),
    (SQUARE, Z[:4], r"values: expected an array of shape \(5,\), got shape \(4,\)"),
    (SQUARE, Z.reshape(5, 1), r"values: expected an array of shape \(5,\)"),
    ((SQUARE[:, 0], SQUARE[:4, 1]), Z, "x and y differ in shape"),
])
def test_wrong_shapes(points, values, message):
    with pytest.raises(ValueError, match=message):
        tspline.C1Interpolator(points, values)


def test_wrong_query_shape():
    f = tspline.C1Interpolator(SQUARE, Z)
    with pytest.raises(ValueError, match=r"expected shape \(\.\.\., 2\), got shape \(4, 3\)"):
        f(np.ones((4, 3)))
    with pytest.raises(ValueError, match="expected 2 coordinates"):
        f(1.0, 2.0, 3.0)


def test_bad_options():
    with pytest.raises(ValueError, match="fit must be one of"):
        tspline.C1Interpolator(SQUARE, Z, fit="best")
    # the library's own checks
    with pytest.raises(ValueError, match="smoothing"):
        tspline.C1Interpolator(SQUARE, Z, fit="adaptive", smoothing=1.0)
    with pytest.raises(ValueError, match="smoothing"):
        tspline.C1Interpolator(SQUARE, Z, fit="energy", smoothing=-1.0)
    with pytest.raises(ValueError, match="the tension must be a finite number"):
        tspline.C1Interpolator(SQUARE, Z, tension=-1.0)
    with pytest.raises(ValueError, match="a tension needs the adaptive or the minimal-energy"):
        tspline.C1Interpolator(SQUARE, Z, fit="local", tension=1.0)
    with pytest.raises(ValueError, match="does not go with smoothing"):
        tspline.C1Interpolator(SQUARE, Z, fit="energy", smoothing=1.0, tension=1.0)
    with pytest.raises(ValueError, match="given gradients need an interpolating fit"):
        tspline.C1Interpolator(SQUARE, Z, fit="approximate", gradients=np.zeros((5, 2)))
    with pytest.raises(ValueError, match="non-finite gradient"):
        tspline.C1Interpolator(SQUARE, Z, gradients=np.full((5, 2), np.nan))
    with pytest.raises(ValueError, match="outside must be"):
        tspline.C1Interpolator(SQUARE, Z, outside="far")
    with pytest.raises(ValueError, match="Mann interpolant"):
        tspline.MannInterpolator(SQUARE, Z, degree=0)


def test_load_errors(tmp_path, data_dir):
    with pytest.raises(ValueError, match="cannot open"):
        tspline.load(tmp_path / "no_such.spline")
    with pytest.raises(ValueError, match=r"franke_100\.xyz:2: not a tspline spline file"):
        tspline.load(f"{data_dir}/franke_100.xyz")
    with pytest.raises(ValueError, match="parametric spline"):
        tspline.load(f"{data_dir}/random_parametric_network.spline")


def test_save_to_a_missing_directory(tmp_path):
    f = tspline.C1Interpolator(SQUARE, Z)
    with pytest.raises(RuntimeError, match="cannot write"):
        f.save(tmp_path / "no_such_dir" / "x.spline")
