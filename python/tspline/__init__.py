"""C^1 piecewise quintic interpolation of scattered data, with a scipy-shaped API.

The Python face of the C++ library Triangular_spline: Xu's C^1 quintic spline over the
Delaunay triangulation of the data (``C1Interpolator``, in the role of scipy's
``CloughTocher2DInterpolator``), Mann's interpolant (``MannInterpolator``), saved splines
(``load``), Fang's blend of a mesh (``blend``), Xu's pseudo-AG^1 surfaces over closed
triangle meshes (``PseudoAG1Surface``, with ``pn_triangles`` as a comparator), and pictures of
any of them (``render``, as ``tspline render`` draws them). Every call
into the library releases the GIL.

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

import os as _os
import tempfile as _tempfile

import numpy as _np

from . import _core

__all__ = ["C1Interpolator", "MannInterpolator", "Interpolator", "load", "blend",
           "ClosedSurface", "PseudoAG1Surface", "load_surface", "pn_triangles",
           "thesis_polyhedron", "thesis_polyhedron_names", "control_point_index", "render",
           "__version__"]

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

    def dimension(self, rational_fallback=False):
        """The dimension of the spline space S^1_5 over the triangulation, proven exactly by
        two bounds (as ``tspline c1 --dimension``): ``lower_bound``, the free count of the
        scheme's plan over the exact coordinates, proven when ``lower_bound_proven`` (every
        rule checked in rationals, every C^1 condition implied by them); ``upper_bound``,
        the nullity of the C^1 conditions modulo ``prime`` (``primes_tried`` moduli tried).
        ``dimension`` is the proven value when the bounds meet, else None, or, with
        ``rational_fallback=True``, the exact rational rank's nullity (``rational_rank``;
        minutes from 50 scattered points on). ``proven`` says whether ``dimension`` is set.
        Also ``morgan_scott`` (the generic dimension, simply connected domains) and
        ``free_parameters``, this spline's own free count (in double builds it can differ
        from ``lower_bound`` where frames collinear only up to rounding were re-routed).
        About 3 CPU seconds per 10^4 points."""
        return self._core.dimension(rational_fallback)

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
        where they resolve the data, least thin-plate energy with a tension where not), ``"local"``,
        ``"energy"``, ``"lsq"``, ``"tangent"``, ``"interpolate"``, ``"approximate"``
        (does not interpolate), as ``tspline c1 --fit``.
    smoothing : float, optional
        The lambda of ``fit="energy"`` (None or 0 interpolates).
    tension : float, optional
        The weight of a tension toward the piecewise linear interpolant in the energy of
        ``fit="adaptive"`` and ``fit="energy"`` (larger: less overshoot, less smooth; 0: the
        thin plate alone); None: 2 for adaptive, 0 for energy (``tspline c1 --tension``).
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

    def __init__(self, points, values, *, fit="adaptive", smoothing=None, tension=None,
                 gradients=None, rescale=False, fill_value=_np.nan, outside="nan", exact=False,
                 degree=5, degree_selection="cv"):
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
        t = None if tension is None else float(tension)
        core = _core.c1(p, z, g, fit, int(degree), degree_selection, s, t, bool(rescale),
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


# ---- Closed surfaces: pseudo-AG^1 (Xu ch. 5-6), surface files, PN triangles -------------------

_PRESETS = ("thesis", "chapter5", "exact")


def _as_mesh(vertices, faces):
    """(n, 3) float64 vertices and (m, 3) int64 faces, checked."""
    v = _np.asarray(vertices, dtype=float)
    if v.ndim != 2 or v.shape[1] != 3:
        raise ValueError(f"vertices: expected an array of shape (n, 3), got shape {v.shape}")
    f = _np.asarray(faces)
    if f.ndim != 2 or f.shape[1] != 3:
        raise ValueError(f"faces: expected an array of shape (m, 3), got shape {f.shape}")
    if f.size and f.dtype.kind not in "iu":
        raise ValueError(f"faces: expected integer vertex indices, got dtype {f.dtype}")
    return _np.ascontiguousarray(v), _np.ascontiguousarray(f, dtype=_np.int64)


def control_point_index(i, j, k):
    """The position of the control point with multi-index (i, j, k) in a net of degree
    i + j + k (Xu's Table 2.3 order, the order of ``ClosedSurface.control_nets()``): i counts
    the face's first vertex, j its second, k its third. Rows of constant i are stored one
    after the other, j increasing: (0, 0, m), (0, 1, m - 1), ..., (0, m, 0), (1, 0, m - 1), ...,
    (m, 0, 0).

    >>> import tspline
    >>> [tspline.control_point_index(*c) for c in [(0, 0, 5), (0, 5, 0), (5, 0, 0), (1, 1, 3)]]
    [0, 5, 20, 7]
    """
    m = i + j + k
    if min(i, j, k) < 0:
        raise ValueError(f"control_point_index: ({i}, {j}, {k}) has a negative component")
    return i * (m + 1) - i * (i - 1) // 2 + j


class ClosedSurface:
    """A piecewise polynomial surface over a closed triangle mesh: one parametric Bezier
    patch per face. Built by ``PseudoAG1Surface``, ``load_surface`` or ``pn_triangles``.

    Patch ``f`` is a polynomial over the unit triangle whose corners are the vertices
    ``faces[f]``, in that order; ``control_nets()[f]`` holds its control points in Xu's
    Table 2.3 order (``control_point_index``), ``evaluate(f, w)`` takes barycentric weights
    of those three vertices.
    """

    def __init__(self, core):
        self._core = core

    @property
    def vertices(self):
        """The mesh's vertices, (n, 3)."""
        return self._core.vertices()

    @property
    def faces(self):
        """The faces as used by the patches, (m, 3): a rotation of each input face, reversed
        for components that were reoriented outward. Corner a of patch f is ``faces[f, a]``."""
        return self._core.faces()

    @property
    def edges(self):
        """The edges, (E, 2) vertex indices, in the order of every per-edge array."""
        return self._core.edges()

    @property
    def degree(self):
        """The degree of the patches (5 for pseudo-AG^1, 3 for PN triangles)."""
        return self._core.degree

    @property
    def exact(self):
        """True if the control points are exact rationals (so ``certify()`` is a proof)."""
        return self._core.exact

    def control_nets(self):
        """The control points, (m, (d+1)(d+2)/2, 3): (m, 21, 3) for quintic patches. Net f
        is over ``faces[f]``; point (i, j, k) is at ``control_point_index(i, j, k)``, i, j, k
        counting the face's first, second and third vertex: the corners (d,0,0), (0,d,0),
        (0,0,d) are at positions -1, d and 0."""
        return self._core.control_nets()

    def certify(self, tolerance=None):
        """The pseudo-AG^1 certificate, from the control nets (AG1.md §6 M3): per edge the
        C^0 conditions and the five diamonds against the edge's relation, per vertex the
        corner plane. Returns a dict: ``verdict`` (``"proof"``, ``"within_tolerance"``,
        ``"failed"``), ``pseudo_ag1`` (C^0 and middle diamonds on every edge, G^1 at every
        vertex), ``exact``, ``tolerance``, the counts ``c0_edges``, ``middle_edges``,
        ``ag1_edges`` (all five diamonds: tangent planes agree along the edge),
        ``inadmissible_edges``, ``g1_vertices``, ``coplanar_vertices``, ``number_of_edges``,
        ``number_of_vertices``, ``max_edge_residual``, and ``edges``: per edge (order of
        ``edges``) arrays ``vertices``, ``c0``, ``middle``, ``ag1``, ``diamonds`` (E, 5),
        ``admissible``, ``join_order``, ``residual``, ``middle_residual``.

        The verdicts are exact for an exact surface (``tolerance=None``); otherwise residuals
        are compared with ``tolerance`` (default 1e-10 times the bounding-box diagonal). A
        loaded file is certified from its nets alone: the edge relations are solved from the
        middle diamonds (``edges["relation_determined"]``).
        """
        t = -1.0 if tolerance is None else float(tolerance)
        if tolerance is not None and not t > 0:
            raise ValueError(f"tolerance must be a number > 0 (or None), not {tolerance!r}")
        return self._core.certify(t)

    def measure(self, samples=15, levels=2, self_intersections=None):
        """Normal jumps and shape (AG1.md §6 M1, M2, M5): the angle between the two patches'
        normals at ``samples`` interior points of every edge and at the vertices, and the
        shape on a tessellation with 4**levels triangles per face against the input mesh.

        Returns a dict: ``max_jump_deg``, ``mean_jump_deg``, ``rms_jump_deg``,
        ``p95_jump_deg``, ``mean_edge_max_jump_deg``, ``max_unoriented_jump_deg``,
        ``vertex_max_jump_deg`` (0 up to round-off where the surface is G^1 at its vertices),
        ``input_mean_bend_deg``, ``volume``, ``input_volume``, ``volume_ratio``,
        ``hausdorff_rel`` and ``rms_distance_rel`` (relative to the input's diagonal),
        ``inside_fraction``, ``folded_samples``, ``singular_samples``, ``self_intersecting``
        (None when not checked: by default only up to 400,000 triangles), ``gaussian_min``,
        ``gaussian_max``, ``tessellation_faces``, and per edge ``edge_max_jump_deg``,
        ``edge_mean_jump_deg``. The numbers of ``tspline pseudo-ag1 --report``.
        """
        check = None if self_intersections is None else bool(self_intersections)
        return self._core.measure(int(samples), int(levels), check)

    def tessellate(self, levels=3, split_normals=False):
        """A watertight triangulation with 4**levels triangles per face (levels 0-8):
        ``(points (V, 3), triangles (T, 3), normals (V, 3), gaussian (V,))``. Corner and edge
        points are shared by the faces; triangle t lies on face ``t // 4**levels``. With
        ``split_normals=True`` every face has its own copies of its corner and edge points,
        each with that face's normal: not closed, but shading then shows where the tangent
        planes jump across the edges."""
        return self._core.tessellate(int(levels), bool(split_normals))

    def evaluate(self, face_ids, bary):
        """Points and unit normals of the patches: ``face_ids`` (k,) face indices, ``bary``
        (k, 3) barycentric weights (summing to 1) of the face's vertices ``faces[f]``.
        Returns ``(points (k, 3), normals (k, 3))``; a normal is NaN where the patch is
        singular. A single face and weight triple give (3,) arrays."""
        f = _np.asarray(face_ids)
        w = _np.asarray(bary, dtype=float)
        single = f.ndim == 0 and w.ndim == 1
        f = _np.atleast_1d(f)
        w = _np.atleast_2d(w)
        if f.ndim != 1 or (f.size and f.dtype.kind not in "iu"):
            raise ValueError(f"face_ids: expected integer face indices of shape (k,), got "
                             f"{f.dtype} of shape {f.shape}")
        if w.ndim != 2 or w.shape[1] != 3:
            raise ValueError(f"bary: expected an array of shape (k, 3), got shape {w.shape}")
        points, normals = self._core.evaluate(_np.ascontiguousarray(f, dtype=_np.int64),
                                              _np.ascontiguousarray(w))
        return (points[0], normals[0]) if single else (points, normals)

    def save(self, path):
        """Writes the surface as a tspline-surface file (mesh and nets; exact numbers for an
        exact surface), read by ``load_surface``, ``tspline certify`` and ``tspline render``."""
        self._core.save(str(path))

    def __repr__(self):
        return (f"<tspline.{type(self).__name__}: {self._core.kind}, degree {self.degree}, "
                f"{len(self.vertices)} vertices, {len(self.faces)} faces, "
                f"{'exact' if self.exact else 'double'}>")


class PseudoAG1Surface(ClosedSurface):
    """Xu's pseudo-AG^1 surface of a closed triangle mesh (thesis ch. 5-6; ``tspline
    pseudo-ag1``): one quintic patch per face, C^0 everywhere, G^1 at every vertex, the three
    middle diamonds of every edge on one affine relation. Tangent planes may jump inside the
    edges; ``measure()`` says by how much, ``certify()`` which conditions hold.

    Parameters
    ----------
    vertices : (n, 3) array_like
        Finite coordinates.
    faces : (m, 3) array_like of int
        A closed, manifold, consistently oriented triangle mesh, counter-clockwise seen from
        outside (components oriented inward are reversed: see ``reoriented`` and ``faces``).
    preset : str
        ``"thesis"`` (the method of §6.2: area-weighted normals, planes half-way, raised or
        lowered by the mean dihedral angle, umbrella stars, normal offsets), ``"chapter5"``
        (§5.4: planes through the centroids, projected stars, no offsets; every control point
        a convex combination of the vertices) or ``"exact"`` (rational steps only).
    exact : bool
        Compute in exact rationals (``CGAL::Exact_rational``): ``certify()`` is then a proof.
        Needs rational options (presets ``"exact"`` and ``"chapter5"``); unlike ``tspline
        pseudo-ag1 --preset exact``, ``preset="exact"`` alone computes in double.
    **overrides
        Options of AG1.md §4.1 over the preset (the names of ``tspline pseudo-ag1``'s
        options): ``normal`` (``"area"``, ``"average"``, ``"centroid"``), ``tau`` (plane
        position, 0 through the vertex, 1 through the centroid), ``undulation_gain``,
        ``threshold_deg``, ``placement`` (``"umbrella"``, ``"projection"``), ``lengths``,
        ``angles``, ``rotation``, ``recentering`` (bool), ``star_scale`` in (0, 1],
        ``shrink`` (``"none"``, ``"auto"``), ``offsets`` (stars, inner, flips), ``inner``
        (``"offset"``, ``"cross-edge"``), ``edge_map`` (``"parallelogram"``,
        ``"averaged"``), ``flip`` (``"symmetric"``, ``"larger-face"``, ``"lower-index"``).
        The effective options are ``options``.

    Raises
    ------
    ValueError
        With the library's message: an open, non-manifold or inconsistently oriented mesh,
        a non-finite coordinate, a zero-area face, wrong shapes, an option out of range,
        ``exact=True`` with options that are not rational.
    TypeError
        An unknown keyword.

    Examples
    --------
    The regular tetrahedron with the exact preset (AG1.md §8 C23): corner point
    z_a = (13/15)(1, 1, 1), proved pseudo-AG^1, with no edge AG^1:

    >>> import numpy as np, tspline
    >>> v = [[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]]
    >>> f = [[0, 1, 2], [0, 3, 1], [1, 3, 2], [2, 3, 0]]
    >>> s = tspline.PseudoAG1Surface(v, f, preset="exact", exact=True)
    >>> s.faces[0].tolist()                      # corner order of patch 0
    [0, 1, 2]
    >>> (s.control_nets()[0, tspline.control_point_index(5, 0, 0)] * 15).round(12).tolist()
    [13.0, 13.0, 13.0]
    >>> c = s.certify()
    >>> c["verdict"], c["ag1_edges"], c["g1_vertices"]
    ('proof', 0, 4)
    >>> m = s.measure(samples=5, levels=1)
    >>> bool(m["vertex_max_jump_deg"] < 1e-9), bool(m["max_jump_deg"] > 10)
    (True, True)
    >>> points, normals = s.evaluate([0, 0], [[1, 0, 0], [1/3, 1/3, 1/3]])
    >>> (points[0] * 15).round(12).tolist()      # the patch interpolates its corner point
    [13.0, 13.0, 13.0]
    """

    def __init__(self, vertices, faces, *, preset="thesis", exact=False, **overrides):
        if preset not in _PRESETS:
            raise ValueError(f"pseudo-AG1: unknown preset {preset!r} (expected thesis, "
                             f"chapter5 or exact)")
        v, f = _as_mesh(vertices, faces)
        super().__init__(_core.pseudo_ag1(v, f, preset, bool(exact), dict(overrides)))

    @property
    def options(self):
        """The options used (preset with overrides), as a dict; ``rational`` says whether
        every step is a rational function of the input."""
        return self._core.options()

    @property
    def info(self):
        """What the construction found: counts, components, Euler characteristic, genus per
        component, ``reoriented``, ``exact``, and ``flags`` (re-centred corners, folded
        projections, equalised umbrellas, normal fallbacks, inverted corners, averaged-map
        fallbacks, shrinking rounds, dipping edges), as ``tspline pseudo-ag1``."""
        return self._core.info()

    @property
    def reoriented(self):
        """The number of connected components whose faces were reversed to face outward."""
        return self._core.info()["reoriented"]

    def corner_planes(self):
        """Per vertex (n rows): ``corner`` (z_v), unit ``normal``, ``distance`` of the plane
        from the vertex along it, ``centroid`` of the first stars, ``mean_dihedral_deg``,
        ``star_scale``, ``normal_used`` and the flags ``recentred``, ``folded_projection``,
        ``equalised``, ``normal_fallback``, ``inverted_corner``."""
        return self._core.corner_planes()

    def edge_relations(self):
        """Per edge (order of ``edges``, oriented r -> s = ``edges[e]``): the ``relation``
        (lambda, mu, nu) of the middle diamonds, the end relations ``end_r``, ``end_s`` read
        off the corner regions (the edge is AG^1 where all three agree) and their validity,
        ``averaged_fallback``, the input's ``dihedral_deg`` and the ``dip`` of the edge
        control polygon (positive: it bends against the input, Fig. 6.7)."""
        return self._core.edge_relations()


def load_surface(path, *, exact=False):
    """Reads a tspline-surface file (``ClosedSurface.save``, ``tspline pseudo-ag1 --save``)
    as a ``ClosedSurface``. ``exact=True`` reads the numbers exactly: the certificate of a
    file written exactly is then a proof (that of a double file fails on its round-off: give
    a tolerance).

    >>> import os, tempfile, tspline
    >>> v, f = tspline.thesis_polyhedron("octahedron")
    >>> s = tspline.PseudoAG1Surface(v, f, preset="exact", exact=True)
    >>> path = os.path.join(tempfile.mkdtemp(), "octahedron.surface")
    >>> s.save(path)
    >>> t = tspline.load_surface(path, exact=True)
    >>> t.certify()["verdict"], bool((t.control_nets() == s.control_nets()).all())
    ('proof', True)
    """
    return ClosedSurface(_core.load_surface(str(path), bool(exact)))


def pn_triangles(vertices, faces):
    """The curved PN triangles (Vlachos, Peters, Boyd, Mitchell 2001) of a closed triangle
    mesh, the comparator of ``tspline pseudo-ag1``: one cubic patch per face from the
    vertices and their area-weighted normals, C^0 but only G^0 along the edges. Returns a
    ``ClosedSurface`` (degree 3): ``measure()`` gives the numbers of the report's
    ``comparison.pn_triangles``, ``control_nets()`` the (m, 10, 3) nets. ``certify()`` is
    for quintic pseudo-AG^1 surfaces and refuses it.

    >>> import tspline
    >>> v, f = tspline.thesis_polyhedron("icosahedron")
    >>> pn = tspline.pn_triangles(v, f)
    >>> pn.control_nets().shape
    (20, 10, 3)
    >>> ag1 = tspline.PseudoAG1Surface(v, f)
    >>> bool(ag1.measure(levels=1)["mean_jump_deg"] < pn.measure(levels=1)["mean_jump_deg"])
    True
    """
    v, f = _as_mesh(vertices, faces)
    return ClosedSurface(_core.pn_triangles(v, f))


def thesis_polyhedron(name):
    """The test solids of ``tspline pseudo-ag1 --shape`` as ``(vertices (n, 3), faces (m, 3))``,
    faces counter-clockwise seen from outside; ``thesis_polyhedron_names()`` lists them.

    >>> import tspline
    >>> v, f = tspline.thesis_polyhedron("tetrahedron")
    >>> v.tolist(), f.shape
    ([[1.0, 1.0, 1.0], [1.0, -1.0, -1.0], [-1.0, 1.0, -1.0], [-1.0, -1.0, 1.0]], (4, 3))
    """
    return _core.thesis_polyhedron(str(name))


def thesis_polyhedron_names():
    """The names ``thesis_polyhedron`` accepts.

    >>> import tspline
    >>> tspline.thesis_polyhedron_names()[:3]
    ['tetrahedron', 'sato', 'octahedron']
    """
    return list(_core.thesis_polyhedron_names())


_RENDER_MODES = ("shaded", "curvature", "isophotes", "net", "jump")


def _pair(value, what, kind):
    try:
        a, b = value
        return kind(a), kind(b)
    except (TypeError, ValueError):
        raise ValueError(f"{what} must be a pair of numbers, not {value!r}") from None


def render(source, path=None, *, mode="shaded", view=(-35, 35), size=(800, 600), levels=None,
           bands=12, range=None, light=None, perspective=False, samples=2, legend=True):
    """Draws a spline or surface as ``tspline render`` does: the same tessellation (normals
    and Gaussian curvature from the exact patch derivatives), the same software rasteriser,
    so the same options give the same pixels.

    ``source``: a ``C1Interpolator``, ``MannInterpolator`` or loaded spline (drawn from
    memory), a ``ClosedSurface`` or ``PseudoAG1Surface`` (drawn as its ``.surface`` file),
    or a path to a ``.spline``, ``.surface`` or mesh file (``.ply/.off/.obj/.stl``).
    ``path``: the PNG file to write, whose path is returned; without it, the picture is
    returned as an ``(H, W, 3)`` ``uint8`` array (rows from the top).

    The keywords are the options of ``tspline render``: ``mode`` (``"shaded"``,
    ``"curvature"``, ``"isophotes"``, ``"net"``, or ``"jump"`` for closed surfaces),
    ``view=(azimuth, elevation)`` in degrees (MATLAB's convention; ``(0, 90)`` is the top
    view), ``size=(width, height)``, ``levels`` (4-split levels of the tessellation; default
    about 2.6e5 triangles), ``bands`` (isophotes), ``range`` (where the curvature or jump
    colours saturate), ``light=(x, y, z)``, ``perspective``, ``samples`` (per pixel along each
    axis, 1 to 4) and ``legend``.

    >>> import numpy as np, tspline
    >>> rng = np.random.default_rng(0)
    >>> points = rng.random((100, 2))
    >>> f = tspline.C1Interpolator(points, np.sin(3 * points[:, 0]) * points[:, 1])
    >>> image = tspline.render(f, mode="curvature", size=(320, 240))
    >>> image.shape, image.dtype
    ((240, 320, 3), dtype('uint8'))
    >>> v, faces = tspline.thesis_polyhedron("icosahedron")
    >>> tspline.render(tspline.PseudoAG1Surface(v, faces), mode="jump", size=(64, 48)).shape
    (48, 64, 3)
    """
    if mode not in _RENDER_MODES:
        raise ValueError(f"mode must be one of {', '.join(_RENDER_MODES)}, not {mode!r}")
    azimuth, elevation = _pair(view, "view", float)
    width, height = _pair(size, "size", int)
    if light is not None:
        light = tuple(float(c) for c in light)
        if len(light) != 3:
            raise ValueError(f"light must be three numbers (x, y, z), not {light!r}")
    options = {"mode": mode, "width": width, "height": height, "azimuth": azimuth,
               "elevation": elevation, "perspective": bool(perspective), "light": light,
               "bands": int(bands), "range": None if range is None else float(range),
               "samples": int(samples), "legend": bool(legend),
               "levels": None if levels is None else int(levels)}
    output = None if path is None else _os.fspath(path)
    if isinstance(source, Interpolator):
        return source._core.render(output, options)
    if isinstance(source, ClosedSurface):
        # drawn from its file, as `tspline render` draws the file `pseudo-ag1 --save` writes:
        # the closed tessellation, Fig. 6.9 net and jump curves live with the file reader
        with _tempfile.TemporaryDirectory(prefix="tspline_render_") as directory:
            saved = _os.path.join(directory, "surface.surface")
            source.save(saved)
            return _core.render_file(saved, output, options)
    if isinstance(source, (str, _os.PathLike)):
        return _core.render_file(_os.fspath(source), output, options)
    raise TypeError("render: expected an interpolator, a closed surface or a file path, not "
                    f"{type(source).__name__}")
