# save / load round trips, and agreement with the command-line tool on the same data.
import os
import subprocess

import numpy as np
import pytest

import tspline


def test_round_trip(tmp_path, scattered):
    p, z = scattered
    f = tspline.C1Interpolator(p, z)
    path = tmp_path / "f.spline"
    f.save(path)
    g = tspline.load(path)
    q = np.random.default_rng(2).random((300, 2)) * 1.2 - 0.1
    # %.17g in the file: the same doubles back
    assert np.array_equal(f(q), g(q), equal_nan=True)
    assert np.array_equal(f.jets(q), g.jets(q), equal_nan=True)
    assert g.degree == 5 and g.free_parameters is None
    assert g.info["faces"] == f.info["faces"]
    # the file of a double build: exact arithmetic sees its round-off (as tspline certify)
    assert tspline.load(path, exact=True).certify()["verdict"] == "failed"


def test_exact_round_trip_is_a_proof(tmp_path, dyadic):
    p, z = dyadic
    f = tspline.C1Interpolator(p, z, exact=True)
    path = tmp_path / "exact.spline"
    f.save(str(path))
    g = tspline.load(path, exact=True)
    assert g.exact and g.certify()["verdict"] == "proof"
    q = np.random.default_rng(2).random((50, 2))
    np.testing.assert_array_equal(f(q), g(q))


def test_load_cli_file(data_dir):
    f = tspline.load(f"{data_dir}/height_field_with_hole.spline", exact=True)
    assert f.certify()["verdict"] == "proof"
    # the values of `tspline eval` on the same file (cli.eval_stdout)
    assert abs(float(f(0.5, 0.5)) - 0.0290332) < 1e-7
    assert np.isnan(f(2.0, 2.0))


CLI = os.environ.get("TSPLINE_CLI")


@pytest.mark.skipif(not (CLI and os.path.exists(CLI)),
                    reason="the tspline executable is not built (TSPLINE_CLI unset or missing)")
@pytest.mark.parametrize("exact", [False, True])
def test_values_equal_the_cli(tmp_path, data_dir, exact):
    xyz = f"{data_dir}/franke_100.xyz"
    data = np.loadtxt(xyz)
    q = np.vstack([np.random.default_rng(9).random((200, 2)), [[0.5, 0.5], [2, 2]]])
    np.savetxt(tmp_path / "q.xy", q, fmt="%.17g")
    command = [CLI, "c1", "--input", xyz, "--query", str(tmp_path / "q.xy"),
               "--values", str(tmp_path / "v.txt"), "--output", str(tmp_path / "c.spline")]
    # exact: the tangent fit (the adaptive one's exact local polynomials from the 53-bit
    # rationals of doubles run at about 300 triangles per second; the CLI reads the short
    # decimals exactly)
    fit = "tangent" if exact else "adaptive"
    subprocess.run(command + (["--exact"] if exact else []) + ["--fit", fit], check=True,
                   capture_output=True)
    cli = np.loadtxt(tmp_path / "v.txt")
    f = tspline.C1Interpolator(data[:, :2], data[:, 2], exact=exact, fit=fit)
    np.testing.assert_allclose(f(q), cli, rtol=0, atol=1e-12, equal_nan=True)
    assert np.isnan(cli[-1])
    # and the CLI's saved file evaluates to the same values
    g = tspline.load(tmp_path / "c.spline", exact=exact)
    np.testing.assert_allclose(g(q), cli, rtol=0, atol=1e-12, equal_nan=True)
