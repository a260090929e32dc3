# Type stubs of the gsp package (the compiled gsp._gsp plus gsp/__init__.py).
import os
from typing import Callable, Literal, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

from . import metric as metric
from .metric import Metric

__version__: str

ArrayLike = npt.ArrayLike
FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
PathLike = Union[str, "os.PathLike[str]"]
Progress = Optional[Callable[[float], object]]

class Error(RuntimeError): ...
class NoPathError(Error): ...
class RemeshWarning(UserWarning): ...

class SurfacePoint:
    def __init__(self, face: int, barycentric: Sequence[float]) -> None: ...
    @property
    def face(self) -> int: ...
    @property
    def barycentric(self) -> Tuple[float, float, float]: ...

Point = Union[int, np.integer, SurfacePoint]
Points = Union[Point, Sequence[Point], npt.NDArray[np.integer]]
MetricLike = Union[Metric, ArrayLike, None]

class Path:
    points: FloatArray
    faces: IntArray
    barycentric: FloatArray
    length: float
    def __len__(self) -> int: ...

class GeodesicSolver:
    def __init__(self, V: ArrayLike, F: ArrayLike, *, intrinsic_delaunay: bool = ..., metric: MetricLike = ...,
                 optimize_layout: bool | str = ...) -> None: ...
    @property
    def optimize_layout(self) -> bool: ...
    @property
    def num_vertices(self) -> int: ...
    @property
    def num_faces(self) -> int: ...
    @overload
    def distance(self, sources: Points, *, max_distance: float = ..., strategy: str = ..., threads: int = ...,
                 labels: bool = ..., precision: str = ..., relax: bool = ...) -> FloatArray: ...
    @overload
    def distance(self, sources: Points, *, max_distance: float = ..., strategy: str = ..., threads: int = ...,
                 labels: bool, precision: str = ..., relax: bool = ...) -> Union[FloatArray, Tuple[FloatArray, IntArray]]: ...
    def distance_at(self, faces: ArrayLike, barycentric: ArrayLike, *, sources: Optional[Points] = ...,
                    max_distance: float = ..., strategy: str = ..., precision: str = ..., relax: bool = ...) -> FloatArray: ...
    def distance_matrix(self, points: Points, *, targets: Union[None, str, Points] = ..., max_distance: float = ...,
                        strategy: str = ..., threads: int = ..., precision: str = ..., relax: bool = ...,
                        progress: Progress = ...) -> FloatArray: ...
    def path(self, a: Point, b: Point, *, method: str = ..., both_ends: bool = ..., precision: str = ...) -> Path: ...
    def paths(self, a: Point, b: Points, *, method: str = ..., both_ends: bool = ...,
              precision: str = ...) -> list[Path]: ...

def geodesic_distance(V: ArrayLike, F: ArrayLike, sources: Points, **options: object) -> FloatArray: ...
@overload
def window_distance(V: ArrayLike, F: ArrayLike, sources: Points, *,
                    windows: int = ..., labels: Literal[False] = ..., max_distance: float = ...) -> FloatArray: ...
@overload
def window_distance(V: ArrayLike, F: ArrayLike, sources: Points, *,
                    windows: int = ..., labels: Literal[True], max_distance: float = ...) -> Tuple[FloatArray, IntArray]: ...
def read_mesh(path: PathLike, weld: Optional[bool] = ..., *, weld_tolerance: float = ...) -> Tuple[FloatArray, IntArray]: ...
@overload
def read_points(path: PathLike) -> FloatArray: ...
@overload
def read_points(path: PathLike, *, normals: bool) -> Union[FloatArray, Tuple[FloatArray, FloatArray]]: ...
def write_mesh(path: PathLike, V: ArrayLike, F: ArrayLike, values: Optional[ArrayLike] = ..., *,
               labels: Optional[ArrayLike] = ..., name: str = ..., label_name: str = ...,
               colormap: Optional[str] = ..., ascii: bool = ...) -> None: ...
def line_distance(V: ArrayLike, F: ArrayLike, *, polylines: Optional[Sequence[ArrayLike]] = ...,
                  edges: Optional[ArrayLike] = ..., boundary: bool = ..., max_distance: float = ...,
                  labels: bool = ...) -> Union[FloatArray, Tuple[FloatArray, IntArray]]: ...

class PointCloudSolver:
    def __init__(self, P: ArrayLike, *, k: int = ..., normals: Optional[ArrayLike] = ...) -> None: ...
    @property
    def num_points(self) -> int: ...
    @property
    def components(self) -> int: ...
    @property
    def normals(self) -> FloatArray: ...
    def distance(self, sources: Union[None, int, Sequence[int], ArrayLike] = ..., *, positions: Optional[ArrayLike] = ...,
                 method: str = ..., max_distance: float = ...,
                 labels: bool = ...) -> Union[FloatArray, Tuple[FloatArray, IntArray]]: ...
    def distance_matrix(self, points: Union[Sequence[int], ArrayLike], *, targets: Optional[Union[Sequence[int], ArrayLike]] = ...,
                        method: str = ..., threads: int = ...) -> FloatArray: ...

class Samples:
    points: FloatArray
    faces: IntArray
    barycentric: FloatArray
    normals: FloatArray
    radius: float
    coverage: FloatArray
    count_met: bool
    def __len__(self) -> int: ...

def sample(V: ArrayLike, F: ArrayLike, *, count: Optional[int] = ..., radius: Optional[float] = ..., mode: str = ...,
           seed: int = ..., exact: bool = ..., fill: bool = ..., progress: Progress = ...) -> Samples: ...

class Cvt:
    sites: FloatArray
    faces: IntArray
    barycentric: FloatArray
    labels: IntArray
    energy: float
    energy_curve: FloatArray
    iterations: int
    converged: bool

def cvt(V: ArrayLike, F: ArrayLike, *, sites: Optional[int] = ..., edge_length: Optional[float] = ...,
        iterations: int = ..., seed: int = ..., init: str = ..., feature_angle: float = ...,
        threads: int = ..., progress: Progress = ..., cone_angle: float = ...) -> Cvt: ...
def remesh(V: ArrayLike, F: ArrayLike, *, vertices: Optional[int] = ..., edge_length: Optional[float] = ...,
           iterations: int = ..., seed: int = ..., flip: bool = ..., smooth: bool = ...,
           feature_angle: float = ..., threads: int = ..., progress: Progress = ...,
           method: str = ..., cone_angle: float = ..., sizing_angle: float = ...) -> Tuple[FloatArray, IntArray]: ...
