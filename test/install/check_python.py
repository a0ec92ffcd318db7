# Run by run_install_test.cmake with PYTHONPATH=<prefix>/<python dir>: the installed package
# imports from the prefix (not the build tree) and interpolates.
import sys

import numpy as np
import tspline

prefix = sys.argv[1]
assert tspline.__file__.startswith(prefix), f"tspline imported from {tspline.__file__}"
f = tspline.C1Interpolator(np.array([[0, 0], [1, 0], [0, 1], [1, 1]]), [0, 1, 2, 3])
value = float(f(0.25, 0.5))
assert abs(value - 1.25) < 1e-12, value  # z = x + 2y is reproduced
print(f"tspline {tspline.__version__} from {tspline.__file__}: f(0.25, 0.5) = {value}")
