"""C^1 piecewise quintic interpolation of scattered data, with a scipy-shaped API.

The Python face of the C++ library Triangular_spline: Xu's C^1 quintic spline over the
Delaunay triangulation of the data (``C1Interpolator``, in the role of scipy's
``CloughTocher2DInterpolator``), Mann's interpolant (``MannInterpolator``), saved splines
(``load``). Every call into the library releases the GIL.

>>> import numpy as np, tspline
>>> rng = np.random.default_rng(0)
>>> points = rng.random((200, 2))
>>> values = np.exp(points[:, 0]) * np.sin(2 * points[:, 1])
>>> f = tspline.C1Interpolator(points, values)
>>> x, y = np.meshgrid(np.linspace(0.2, 0.8, 4), np.linspace(0.2, 0.8, 3))
>>> f(x, y).shape          # a tuple of arrays: the broadcast shape
(3, 4)
>>> f(points[:3]).shape    # an (n, 2) array: n values
(3,)
>>> bool(np.allclose(f(points), values, rtol=0, atol=1e-12))  # interpolates the data
True

Library errors are Python exceptions with the library's message: invalid input
(``CGAL::Triangular_spline::Invalid_input``) is a ``ValueError``, anything else a
``RuntimeError``.
"""

import numpy as _np

from . import _core

__all__ = ["C1Interpolator", "MannInterpolator", "Interpolator", "load", "blend", "__version__"]

__version__ = _core.__version__

_FITS = ("adaptive", "local", "energy", "lsq", "tangent", "interpolate", "approximate")


def _as_points(points, what="points"):
    """(n, 2) float64 from an (n, 2) array-like or a tuple (x, y) of 1-d arrays."""
    if isinstance(points, tuple):
        if len(points) != 2:
            raise ValueError(f"{what}: a tuple needs 2 arrays (x, y), got {len(points)}")
        x, y = (_np.asarray(c, dtype=float) for c in points)
        if x.shape != y.shape:
            raise ValueError(f"{what}: x and y differ in shape: {x.shape} and {y.shape}")
        return _np.column_stack([x.ravel(), y.ravel()])
    p = _np.asarray(points, dtype=float)
    if p.ndim != 2 or p.shape[1] != 2:
        raise ValueError(f"{what}: expected an array of shape (n, 2), got shape {p.shape}")
    return _np.ascontiguousarray(p)


def _as_values(values, n, what="values"):
    """(n, 1) float64 from n values."""
    z = _np.asarray(values, dtype=float)
    if z.ndim != 1 or z.shape[0] != n:
        raise ValueError(f"{what}: expected an array of shape ({n},), got shape {z.shape}")
    return _np.ascontiguousarray(z.reshape(n, 1))


def _queries(args):
    """The query points as (m, 2) and the shape of the result, as scipy's interpolators:
    f(xi) with xi of shape (..., 2), f((x, y)) or f(x, y) with broadcastable x, y."""
    if len(args) == 1 and not isinstance(args[0], tuple):
        xi = _np.asarray(args[0], dtype=float)
        if xi.ndim == 0 or xi.shape[-1] != 2:
            raise ValueError(f"query points: expected shape (..., 2), got shape {xi.shape}")
        return _np.ascontiguousarray(xi.reshape(-1, 2)), xi.shape[:-1]
    coords = args[0] if len(args) == 1 else args
    if len(coords) != 2:
        raise ValueError(f"query points: expected 2 coordinates (x, y), got {len(coords)}")
    x, y = _np.broadcast_arrays(*(_np.asarray(c, dtype=float) for c in coords))
    return _np.column_stack([x.ravel(), y.ravel()]), x.shape


class Interpolator:
    """A spline z = F(x, y) over a triangulated domain, callable like scipy's interpolators.

    Built by ``C1Interpolator``, ``MannInterpolator`` or ``load``. Queries outside the
    domain (the convex hull of the data, or a hole of a loaded domain) get ``fill_value``,
    unless ``outside`` is ``"nearest"`` (the spline at the nearest boundary point) or
    ``"linear"`` (its tangent plane there).
    """

    def __init__(self, core, fill_value=_np.nan, outside="nan"):
        if outside not in ("nan", "nearest", "linear"):
            raise ValueError(f"outside must be nan, nearest or linear, not {outside!r}")
        self._core = core
        self.fill_value = float(fill_value)
        self.outside = outside

    def _evaluate(self, args, order):
        xi, shape = _queries(args)
        jets = self._core.evaluate(xi, order, self.outside)
        if not _np.isnan(self.fill_value):
            jets[_np.isnan(jets[:, 0])] = self.fill_value
        return jets, shape

    def __call__(self, *args):
        """Values at the query points: f(xi) with xi of shape (..., 2) returns shape (...);
        f(x, y) or f((x, y)) the broadcast shape of x and y.

        >>> import tspline
        >>> f = tspline.C1Interpolator([[0, 0], [1, 0], [0, 1], [1, 1]], [0, 1, 2, 3])
        >>> round(float(f(0.25, 0.5)), 12)   # z = x + 2y is reproduced
        1.25
        >>> float(f(2.0, 2.0))       # outside the convex hull: fill_value
        nan
        """
        jets, shape = self._evaluate(args, 0)
        return jets[:, 0].reshape(shape)

    def gradient(self, *args):
        """(dF/dx, dF/dy) at the query points: shape (..., 2).

        >>> import tspline
        >>> f = tspline.C1Interpolator([[0, 0], [1, 0], [0, 1], [1, 1]], [0, 1, 2, 3])
        >>> f.gradient(0.3, 0.3).round(12).tolist()
        [1.0, 2.0]
        """
        jets, shape = self._evaluate(args, 1)
        return jets[:, 1:3].reshape(shape + (2,))

    def hessian(self, *args):
        """The Hessian [[F_xx, F_xy], [F_xy, F_yy]] at the query points: shape (..., 2, 2).
        On an edge or at a vertex it is one incident patch's (one-sided for a C^1 spline)."""
        jets, shape = self._evaluate(args, 2)
        h = jets[:, [3, 4, 4, 5]].reshape(shape + (2, 2))
        return h

    def jets(self, *args):
        """Value, gradient and Hessian at once: shape (..., 6), columns
        z, zx, zy, zxx, zxy, zyy (as ``tspline eval --derivatives 2``)."""
        jets, shape = self._evaluate(args, 2)
        return jets.reshape(shape + (6,))

    def certify(self, tolerance=None):
        """Checks the C^1 conditions on every interior edge and returns a dict: ``verdict``
        (``"proof"`` only for an exact spline whose conditions all hold exactly,
        ``"within_tolerance"``, ``"failed"``), ``proof``, ``certified``, ``max_residual``,
        counts, and ``edges``: per interior edge, arrays ``edge``, ``vertices`` (indices of
        the input points), ``achieved_order``, ``c1``, ``zero``, ``residual``.

        The default tolerance is 0 for an exact spline and 1e-10 times the largest control
        value for a double one (its round-off), as ``tspline c1``.

        >>> import tspline
        >>> f = tspline.C1Interpolator([[0, 0], [1, 0], [0, 1], [1, 1.5]], [0, 1, 2, 0],
        ...                            exact=True)
        >>> f.certify()["verdict"]
        'proof'
        """
        return self._core.certify(tolerance)

    def save(self, path):
        """Writes the spline as a tspline-spline file (``tspline eval``, ``tspline certify``
        and ``tspline.load`` read it; exact splines are written exactly)."""
        self._core.save(str(path))

    @property
    def exact(self):
        """True if the spline is in exact rational arithmetic."""
        return self._core.exact

    @property
    def degree(self):
        """The degree of the patches."""
        return self._core.degree

    @property
    def free_parameters(self):
        """The number of free control values of Xu's scheme (None for other splines)."""
        return self._core.free_parameters

    @property
    def points(self):
        """The domain's vertices, (n, 2), in the order of the input points."""
        return self._core.points()

    @property
    def simplices(self):
        """The triangles, (F, 3), as indices into ``points`` (scipy's Delaunay.simplices)."""
        return self._core.triangles()

    @property
    def info(self):
        """What the construction did: domain counts, fit statistics, degenerate frames."""
        return self._core.info()

    def dimension(self):
        """The dimension of the spline space S^1_5 over the triangulation: ``upper_bound``
        (the rank of the C^1 conditions modulo ``prime``), ``morgan_scott`` (the generic
        dimension, simply connected domains), ``free_parameters``, and ``proven``: the
        scheme's free parameters meet the upper bound, so they are the dimension."""
        return self._core.dimension()

    def __repr__(self):
        i = self.info
        return (f"<tspline.{type(self).__name__}: {self._core.kind}, degree {self.degree}, "
                f"{i['vertices']} vertices, {i['faces']} triangles, "
                f"{'exact' if self.exact else 'double'}>")


class C1Interpolator(Interpolator):
    """Xu's C^1 piecewise quintic spline over the Delaunay triangulation of the points.

    In the role of ``scipy.interpolate.CloughTocher2DInterpolator(points, values,
    fill_value)``: callable on (n, 2) arrays or (x, y) tuples, ``fill_value`` outside the
    convex hull.

    Parameters
    ----------
    points : (n, 2) array_like or tuple (x, y) of 1-d arrays
        Distinct data points, not all collinear.
    values : (n,) array_like
        The data values.
    fit : str
        How the free control points are set: ``"adaptive"`` (default: local polynomials
        where they resolve the data, least thin-plate energy where not), ``"local"``,
        ``"energy"``, ``"lsq"``, ``"tangent"``, ``"interpolate"``, ``"approximate"``
        (does not interpolate), as ``tspline c1 --fit``.
    smoothing : float, optional
        The lambda of ``fit="energy"`` (None or 0 interpolates).
    gradients : (n, 2) array_like, optional
        (dz/dx, dz/dy) at every point, interpolated instead of estimated.
    rescale : bool
        Triangulate and fit with y scaled by the power of two that makes its extent closest
        to x's (for anisotropic data; scipy's ``rescale``); the result is over the data's
        own points.
    fill_value : float
        The value outside the domain (default NaN).
    outside : str
        ``"nan"`` (fill_value), ``"nearest"`` or ``"linear"`` extrapolation.
    exact : bool
        Build in exact rational arithmetic: ``certify()`` is then a proof of C^1. Slower
        (about 5000 triangles per second).
    degree : int
        The largest degree (0-5) of the local polynomials (adaptive, local, lsq fits).
    degree_selection : str
        ``"cv"`` (cross-validation, default) or ``"largest"``.

    Raises
    ------
    ValueError
        Invalid input, with the library's message: non-finite numbers, repeated points,
        fewer than 3 points or all collinear, wrong shapes, unknown options.

    Examples
    --------
    >>> import numpy as np, tspline
    >>> rng = np.random.default_rng(1)
    >>> p = rng.random((50, 2))
    >>> f = tspline.C1Interpolator(p, 3 * p[:, 0] - p[:, 1] + 1)
    >>> bool(np.allclose(f(0.5, 0.5), 2.0))           # linear data are reproduced
    True
    >>> g = f.with_values(p[:, 0] ** 2)                # same triangulation, new data
    >>> bool(np.allclose(g(p), p[:, 0] ** 2, atol=1e-12))
    True
    """

    def __init__(self, points, values, *, fit="adaptive", smoothing=None, gradients=None,
                 rescale=False, fill_value=_np.nan, outside="nan", exact=False, degree=5,
                 degree_selection="cv"):
        if fit not in _FITS:
            raise ValueError(f"fit must be one of {', '.join(_FITS)}, not {fit!r}")
        if degree_selection not in ("cv", "largest"):
            raise ValueError(f"degree_selection must be cv or largest, not {degree_selection!r}")
        if not 0 <= int(degree) <= 5:
            raise ValueError(f"degree must be between 0 and 5, not {degree}")
        p = _as_points(points)
        z = _as_values(values, p.shape[0])
        g = None if gradients is None else _as_points(gradients, "gradients")
        s = 0.0 if smoothing is None else float(smoothing)
        core = _core.c1(p, z, g, fit, int(degree), degree_selection, s, bool(rescale),
                        bool(exact))
        super().__init__(core, fill_value, outside)

    def with_values(self, values, gradients=None):
        """A new interpolant of other values at the same points, with the same options:
        the triangulation, its degenerate frames and the propagation plan are reused, only
        the fit runs again (scipy PR #18376 asks this of CloughTocher2DInterpolator)."""
        n = self.points.shape[0]
        z = _as_values(values, n)
        g = None if gradients is None else _as_points(gradients, "gradients")
        result = object.__new__(type(self))
        Interpolator.__init__(result, self._core.with_values(z, g), self.fill_value,
                              self.outside)
        return result


class MannInterpolator(Interpolator):
    """Mann's C^k interpolant of degree ``degree`` over the Delaunay triangulation:
    vertex derivatives estimated by local least squares, a C^0 network raised to C^k with
    k = floor((degree - 1) / 4) (C^1 for the default quintic), as ``tspline mann``.

    >>> import numpy as np, tspline
    >>> p = np.array([[0, 0], [1, 0], [0, 1], [1, 1], [0.4, 0.6]])
    >>> f = tspline.MannInterpolator(p, p[:, 0] + p[:, 1], degree=5)
    >>> round(float(f(0.5, 0.25)), 12)
    0.75
    """

    def __init__(self, points, values, *, degree=5, fill_value=_np.nan, outside="nan",
                 exact=False):
        p = _as_points(points)
        z = _as_values(values, p.shape[0])
        super().__init__(_core.mann(p, z, int(degree), bool(exact)), fill_value, outside)


def load(path, *, exact=False, fill_value=_np.nan, outside="nan"):
    """Reads a spline saved by ``Interpolator.save`` or by ``tspline c1/mann/adjust
    --output``. ``exact=True`` reads the numbers exactly (``certify()`` is then the exact
    check of ``tspline certify``).

    >>> import os, tempfile, tspline
    >>> f = tspline.C1Interpolator([[0, 0], [1, 0], [0, 1], [1, 1]], [0, 1, 2, 3])
    >>> path = os.path.join(tempfile.mkdtemp(), "plane.spline")
    >>> f.save(path)
    >>> g = tspline.load(path)
    >>> round(float(g(0.25, 0.5)), 12)
    1.25
    """
    return Interpolator(_core.load(str(path), bool(exact)), fill_value, outside)


def blend(vertices, faces, *, order=2, variant="open", vertex_surface="least", resolution=8,
          return_properties=False):
    """Fang's generalized blending surface of a closed or open polygon mesh, tessellated:
    as ``tspline blend``. Returns ``(points, triangles)``: the tessellation's vertices
    (m, 3) and triangles (t, 3); with ``return_properties=True`` also a dict of per-vertex
    ``normals``, ``gaussian_curvature``, ``mean_curvature`` and per-triangle ``input_face``.

    Parameters
    ----------
    vertices : (n, 3) array_like
        The mesh's vertices.
    faces : (f, k) array_like or sequence of sequences
        Polygons as vertex indices, consistently oriented (any number of sides >= 3).
    order : int
        The blending order d >= 0 (C^d where the variant achieves it).
    variant : str
        ``"basic"``, ``"vertex"`` (vertex continuity) or ``"open"`` (open-set continuity).
    vertex_surface : str
        ``"least"``, ``"lsq"`` or ``"normals"``: how the vertex surfaces are fitted.
    resolution : int
        Segments per mesh edge in the tessellation (1-1024).

    >>> import numpy as np, tspline
    >>> v = [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]]
    >>> f = [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4],
    ...      [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]]
    >>> points, triangles = tspline.blend(v, f, order=2, resolution=4)
    >>> points.shape[1], triangles.shape[1]
    (3, 3)
    """
    v = _np.asarray(vertices, dtype=float)
    if v.ndim != 2 or v.shape[1] != 3:
        raise ValueError(f"vertices: expected an array of shape (n, 3), got shape {v.shape}")
    f = faces.tolist() if isinstance(faces, _np.ndarray) else [list(face) for face in faces]
    points, triangles, properties = _core.blend(v, f, int(order), variant, vertex_surface,
                                                int(resolution))
    return (points, triangles, properties) if return_properties else (points, triangles)
