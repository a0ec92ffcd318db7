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
