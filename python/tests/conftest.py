# Shared data of the tspline tests. PYTHONPATH points at the built package (ctest python.*).
import os

import numpy as np
import pytest


@pytest.fixture
def scattered():
    """200 seeded random points of [0, 1]^2 with the corners (a square hull)."""
    rng = np.random.default_rng(7)
    p = np.vstack([[[0, 0], [1, 0], [0, 1], [1, 1]], rng.random((196, 2))])
    return p, np.exp(p[:, 0]) * np.sin(2 * p[:, 1])


@pytest.fixture
def data_dir():
    return os.environ.get("TSPLINE_DATA",
                          os.path.join(os.path.dirname(__file__), "..", "..", "data"))


@pytest.fixture
def dyadic():
    """40 points on the 1/32 grid with values rounded to 1/1024: short rationals, so that
    exact builds are quick (each random double is a 53-bit rational, and the adaptive
    fit's exact local polynomials on 40 of them take half a second)."""
    rng = np.random.default_rng(7)
    p = np.unique(np.round(rng.random((60, 2)) * 32) / 32, axis=0)[:40]
    return p, np.round(np.exp(p[:, 0]) * np.sin(2 * p[:, 1]) * 1024) / 1024
