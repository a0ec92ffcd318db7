# Type stubs of the tspline package (python/tspline/__init__.py; the compiled core is private).
import os
from typing import Any, Literal, Optional, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str

ArrayLike = npt.ArrayLike
Points = Union[npt.ArrayLike, Tuple[npt.ArrayLike, npt.ArrayLike]]
Fit = Literal["adaptive", "local", "energy", "lsq", "tangent", "interpolate", "approximate"]
Outside = Literal["nan", "nearest", "linear"]

class Interpolator:
    fill_value: float
    outside: Outside
    @overload
    def __call__(self, xi: Points) -> npt.NDArray[np.float64]: ...
    @overload
    def __call__(self, x: ArrayLike, y: ArrayLike) -> npt.NDArray[np.float64]: ...
    @overload
    def gradient(self, xi: Points) -> npt.NDArray[np.float64]: ...
    @overload
    def gradient(self, x: ArrayLike, y: ArrayLike) -> npt.NDArray[np.float64]: ...
    @overload
    def hessian(self, xi: Points) -> npt.NDArray[np.float64]: ...
    @overload
    def hessian(self, x: ArrayLike, y: ArrayLike) -> npt.NDArray[np.float64]: ...
    @overload
    def jets(self, xi: Points) -> npt.NDArray[np.float64]: ...
    @overload
    def jets(self, x: ArrayLike, y: ArrayLike) -> npt.NDArray[np.float64]: ...
    def certify(self, tolerance: Optional[float] = ...) -> dict[str, Any]: ...
    def save(self, path: Union[str, os.PathLike[str]]) -> None: ...
    def dimension(self) -> dict[str, Any]: ...
    @property
    def exact(self) -> bool: ...
    @property
    def degree(self) -> int: ...
    @property
    def free_parameters(self) -> Optional[int]: ...
    @property
    def points(self) -> npt.NDArray[np.float64]: ...
    @property
    def simplices(self) -> npt.NDArray[np.int64]: ...
    @property
    def info(self) -> dict[str, Any]: ...

class C1Interpolator(Interpolator):
    def __init__(
        self,
        points: Points,
        values: ArrayLike,
        *,
        fit: Fit = ...,
        smoothing: Optional[float] = ...,
        gradients: Optional[Points] = ...,
        rescale: bool = ...,
        fill_value: float = ...,
        outside: Outside = ...,
        exact: bool = ...,
        degree: int = ...,
        degree_selection: Literal["cv", "largest"] = ...,
    ) -> None: ...
    def with_values(
        self, values: ArrayLike, gradients: Optional[Points] = ...
    ) -> "C1Interpolator": ...

class MannInterpolator(Interpolator):
    def __init__(
        self,
        points: Points,
        values: ArrayLike,
        *,
        degree: int = ...,
        fill_value: float = ...,
        outside: Outside = ...,
        exact: bool = ...,
    ) -> None: ...

def load(
    path: Union[str, os.PathLike[str]],
    *,
    exact: bool = ...,
    fill_value: float = ...,
    outside: Outside = ...,
) -> Interpolator: ...

@overload
def blend(
    vertices: ArrayLike,
    faces: Any,
    *,
    order: int = ...,
    variant: Literal["basic", "vertex", "open"] = ...,
    vertex_surface: Literal["least", "lsq", "normals"] = ...,
    resolution: int = ...,
    return_properties: Literal[False] = ...,
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...
@overload
def blend(
    vertices: ArrayLike,
    faces: Any,
    *,
    order: int = ...,
    variant: Literal["basic", "vertex", "open"] = ...,
    vertex_surface: Literal["least", "lsq", "normals"] = ...,
    resolution: int = ...,
    return_properties: Literal[True],
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], dict[str, npt.NDArray[Any]]]: ...

# ---- closed surfaces: pseudo-AG^1, surface files, PN triangles ----------------------------

Preset = Literal["thesis", "chapter5", "exact"]

def control_point_index(i: int, j: int, k: int) -> int: ...

class ClosedSurface:
    @property
    def vertices(self) -> npt.NDArray[np.float64]: ...
    @property
    def faces(self) -> npt.NDArray[np.int64]: ...
    @property
    def edges(self) -> npt.NDArray[np.int64]: ...
    @property
    def degree(self) -> int: ...
    @property
    def exact(self) -> bool: ...
    def control_nets(self) -> npt.NDArray[np.float64]: ...
    def certify(self, tolerance: Optional[float] = ...) -> dict[str, Any]: ...
    def measure(
        self, samples: int = ..., levels: int = ..., self_intersections: Optional[bool] = ...
    ) -> dict[str, Any]: ...
    def tessellate(
        self, levels: int = ..., split_normals: bool = ...
    ) -> Tuple[
        npt.NDArray[np.float64],
        npt.NDArray[np.int64],
        npt.NDArray[np.float64],
        npt.NDArray[np.float64],
    ]: ...
    def evaluate(
        self, face_ids: ArrayLike, bary: ArrayLike
    ) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
    def save(self, path: Union[str, os.PathLike[str]]) -> None: ...

class PseudoAG1Surface(ClosedSurface):
    def __init__(
        self,
        vertices: ArrayLike,
        faces: ArrayLike,
        *,
        preset: Preset = ...,
        exact: bool = ...,
        normal: Literal["area", "average", "centroid"] = ...,
        tau: float = ...,
        undulation_gain: float = ...,
        threshold_deg: float = ...,
        placement: Literal["umbrella", "projection"] = ...,
        lengths: Literal["rigid", "proportional", "equal"] = ...,
        angles: Literal["proportional", "equal"] = ...,
        rotation: Literal["least-squares", "first-star"] = ...,
        recentering: bool = ...,
        star_scale: float = ...,
        shrink: Literal["none", "auto"] = ...,
        offsets: Tuple[float, float, float] = ...,
        inner: Literal["offset", "cross-edge"] = ...,
        edge_map: Literal["parallelogram", "averaged"] = ...,
        flip: Literal["symmetric", "larger-face", "lower-index"] = ...,
    ) -> None: ...
    @property
    def options(self) -> dict[str, Any]: ...
    @property
    def info(self) -> dict[str, Any]: ...
    @property
    def reoriented(self) -> int: ...
    def corner_planes(self) -> dict[str, Any]: ...
    def edge_relations(self) -> dict[str, Any]: ...

def load_surface(path: Union[str, os.PathLike[str]], *, exact: bool = ...) -> ClosedSurface: ...
def pn_triangles(vertices: ArrayLike, faces: ArrayLike) -> ClosedSurface: ...
def thesis_polyhedron(
    name: str,
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...
def thesis_polyhedron_names() -> list[str]: ...

# ---- pictures: tspline render ------------------------------------------------------------

RenderMode = Literal["shaded", "curvature", "isophotes", "net", "jump"]
RenderSource = Union[Interpolator, ClosedSurface, str, os.PathLike[str]]

@overload
def render(
    source: RenderSource,
    path: None = ...,
    *,
    mode: RenderMode = ...,
    view: Tuple[float, float] = ...,
    size: Tuple[int, int] = ...,
    levels: Optional[int] = ...,
    bands: int = ...,
    range: Optional[float] = ...,
    light: Optional[Tuple[float, float, float]] = ...,
    perspective: bool = ...,
    samples: int = ...,
    legend: bool = ...,
) -> npt.NDArray[np.uint8]: ...
@overload
def render(
    source: RenderSource,
    path: Union[str, os.PathLike[str]],
    *,
    mode: RenderMode = ...,
    view: Tuple[float, float] = ...,
    size: Tuple[int, int] = ...,
    levels: Optional[int] = ...,
    bands: int = ...,
    range: Optional[float] = ...,
    light: Optional[Tuple[float, float, float]] = ...,
    perspective: bool = ...,
    samples: int = ...,
    legend: bool = ...,
) -> str: ...
