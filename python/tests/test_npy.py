# .npy input of the CLI (issue 15): arrays written by numpy.save, read by tspline c1 / mann /
# eval, give what the same data in text give; bad arrays are one line and exit 1.
import os
import subprocess

import numpy as np
import pytest

import tspline

CLI = os.environ.get("TSPLINE_CLI")
pytestmark = pytest.mark.skipif(not (CLI and os.path.exists(CLI)),
                                reason="the tspline executable is not built")


def run(*args):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)


@pytest.mark.parametrize("dtype,order", [("<f8", "C"), ("<f8", "F"), ("<f4", "C")])
def test_c1_npy_equals_the_module_and_the_text_file(tmp_path, scattered, dtype, order):
    p, z = scattered
    # extra columns around the data, chosen with --columns
    table = np.column_stack([np.arange(len(z)), z, p]).astype(dtype)
    table = np.asfortranarray(table) if order == "F" else np.ascontiguousarray(table)
    np.save(tmp_path / "t.npy", table)
    q = np.random.default_rng(3).random((50, 2))
    np.save(tmp_path / "q.npy", q)
    r = run("c1", "--input", tmp_path / "t.npy", "--columns", "2,3,1", "--query",
            tmp_path / "q.npy", "--values", tmp_path / "v.txt")
    assert r.returncode == 0, r.stderr
    cli = np.loadtxt(tmp_path / "v.txt")
    # the module on the same (float32-rounded) numbers
    x = table.astype(np.float64)
    f = tspline.C1Interpolator(x[:, 2:4], x[:, 1])
    np.testing.assert_allclose(f(q), cli, rtol=0, atol=1e-12)
    # the same numbers as text (17 digits: exact) give the same spline
    np.savetxt(tmp_path / "t.xyz", x[:, [2, 3, 1]], fmt="%.17g")
    np.savetxt(tmp_path / "q.xy", q, fmt="%.17g")
    r = run("c1", "--input", tmp_path / "t.xyz", "--query", tmp_path / "q.xy", "--values",
            tmp_path / "w.txt")
    assert r.returncode == 0, r.stderr
    np.testing.assert_array_equal(np.loadtxt(tmp_path / "w.txt"), cli)


def test_integer_columns_and_gradients(tmp_path):
    # z = x + 2y on a 6x6 integer grid, int64 and int32, gradients (1, 2) given
    x, y = np.meshgrid(np.arange(6), np.arange(6))
    grid = np.column_stack([x.ravel(), y.ravel(), (x + 2 * y).ravel(),
                            np.ones(36, int), 2 * np.ones(36, int)])
    for dtype in ("<i8", "<i4"):
        np.save(tmp_path / "g.npy", grid.astype(dtype))
        r = run("c1", "--input", tmp_path / "g.npy", "--gradients", "--exact", "--query",
                tmp_path / "g.npy", "--values", "-")
        assert r.returncode == 0, r.stderr
        np.testing.assert_array_equal(np.loadtxt(r.stdout.splitlines()), grid[:, 2])


def test_bad_arrays_are_one_line(tmp_path):
    p = np.random.default_rng(1).random((10, 3))
    cases = {
        "complex": (p.astype(np.complex128), "unsupported dtype '<c16'"),
        "big": (p.astype(">f8"), "big-endian dtype '>f8'"),
        "three_d": (p.reshape(10, 3, 1), "shape (10, 3, 1) is not two-dimensional"),
        "short": (p[:, :2], "shape (10, 2): choose the columns"),
        "inf": (np.where(np.arange(30).reshape(10, 3) == 13, np.inf, p),
                "row 4, column 1: infinity is not a coordinate"),
    }
    for name, (array, message) in cases.items():
        np.save(tmp_path / f"{name}.npy", array)
        r = run("c1", "--input", tmp_path / f"{name}.npy")
        assert r.returncode == 1, name
        assert r.stderr.count("\n") == 1 and message in r.stderr, r.stderr
    # a pickled object array: refused, never unpickled
    np.save(tmp_path / "objects.npy", np.array([{"x": 1}], dtype=object), allow_pickle=True)
    r = run("c1", "--input", tmp_path / "objects.npy")
    assert r.returncode == 1 and "unsupported dtype '|O'" in r.stderr, r.stderr
