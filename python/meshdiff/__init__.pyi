"""Types of the package meshdiff (docs/python.md is the reference).

Checked against the module by `python3 -m mypy.stubtest meshdiff` and, keyword by
keyword, against the extension's signatures by python/tests/test_typing.py.
"""
from os import PathLike
from typing import Any, Callable, Dict, Iterable, Optional, Protocol, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str
SAMPLE_KINDS: Tuple[str, ...]
LIMITS: Dict[str, Any]

_ArrayLike = npt.ArrayLike
_Path = Union[str, bytes, PathLike[str], PathLike[bytes]]
_Levels = Union[Iterable[int], str, None]
_Radii = Union[Iterable[float], str, None]
_F64 = npt.NDArray[np.float64]
_Progress = Union[Callable[[str, int, int], object], bool, None]
"""progress=: progress(stage, done, total) as the library works (total 0: not known), or True: a tqdm bar."""
_Report = Dict[str, Any]
"""A report dict: the JSON of the CLI as Python values (docs/cli.md gives the schemas)."""

class _VerticesFaces(Protocol):
    """trimesh.Trimesh and any duck type: .vertices (n, 3), .faces (m, 3)."""

    @property
    def vertices(self) -> Any: ...
    @property
    def faces(self) -> Any: ...

class _VerticesTriangles(Protocol):
    """open3d.geometry.TriangleMesh: .vertices, .triangles."""

    @property
    def vertices(self) -> Any: ...
    @property
    def triangles(self) -> Any: ...

class _PointsCells(Protocol):
    """meshio.Mesh: .points and .cells (triangle cells only)."""

    @property
    def points(self) -> Any: ...
    @property
    def cells(self) -> Any: ...

_MeshLike = Union[_VerticesFaces, _VerticesTriangles, _PointsCells]

class MeshWarning(UserWarning): ...

def read_mesh(path: _Path, *, report: bool = ...) -> Any: ...
@overload
def compare(
    original: _MeshLike, processed: _MeshLike, /,
    *,
    levels: _Levels = ...,
    radii: _Radii = ...,
    global_level: bool = ...,
    curvature: Optional[str] = ...,
    weighting: Optional[str] = ...,
    measure: Optional[str] = ...,
    unbiased_variance: bool = ...,
    normalize: Optional[str] = ...,
    trim: Optional[float] = ...,
    bootstrap: Optional[int] = ...,
    bootstrap_seed: Optional[int] = ...,
    paper: bool = ...,
    local: bool = ...,
    local_trim: Optional[float] = ...,
    k: Optional[float] = ...,
    roughness: bool = ...,
    distance: bool = ...,
    samples: Optional[int] = ...,
    density: Optional[float] = ...,
    face_sampling: Optional[str] = ...,
    seed: Optional[int] = ...,
    vertex_samples: bool = ...,
    edge_samples: bool = ...,
    face_samples: bool = ...,
    hausdorff: Optional[str] = ...,
    hausdorff_tolerance: Optional[float] = ...,
    hausdorff_abs_tolerance: Optional[float] = ...,
    hausdorff_budget: Optional[int] = ...,
    fscore: Optional[Iterable[float]] = ...,
    histogram: Optional[int] = ...,
    json: Optional[_Path] = ...,
    distance_map: Optional[_Path] = ...,
    distance_map_original: Optional[_Path] = ...,
    distance_maps: Optional[_Path] = ...,
    samples_out: Optional[_Path] = ...,
    html: Optional[_Path] = ...,
    color_range: Union[str, Tuple[float, float], None] = ...,
    html_face_budget: Optional[int] = ...,
    threads: Optional[int] = ...,
    progress: _Progress = ...,
    maps: bool = ...,
    index_original: Optional[DistanceIndex] = ...,
    index_processed: Optional[DistanceIndex] = ...,
) -> _Report: ...
@overload
def compare(
    V1: _ArrayLike, F1: Optional[_ArrayLike], V2: _ArrayLike, F2: Optional[_ArrayLike],
    *,
    levels: _Levels = ...,
    radii: _Radii = ...,
    global_level: bool = ...,
    curvature: Optional[str] = ...,
    weighting: Optional[str] = ...,
    measure: Optional[str] = ...,
    unbiased_variance: bool = ...,
    normalize: Optional[str] = ...,
    trim: Optional[float] = ...,
    bootstrap: Optional[int] = ...,
    bootstrap_seed: Optional[int] = ...,
    paper: bool = ...,
    local: bool = ...,
    local_trim: Optional[float] = ...,
    k: Optional[float] = ...,
    roughness: bool = ...,
    distance: bool = ...,
    samples: Optional[int] = ...,
    density: Optional[float] = ...,
    face_sampling: Optional[str] = ...,
    seed: Optional[int] = ...,
    vertex_samples: bool = ...,
    edge_samples: bool = ...,
    face_samples: bool = ...,
    hausdorff: Optional[str] = ...,
    hausdorff_tolerance: Optional[float] = ...,
    hausdorff_abs_tolerance: Optional[float] = ...,
    hausdorff_budget: Optional[int] = ...,
    fscore: Optional[Iterable[float]] = ...,
    histogram: Optional[int] = ...,
    json: Optional[_Path] = ...,
    distance_map: Optional[_Path] = ...,
    distance_map_original: Optional[_Path] = ...,
    distance_maps: Optional[_Path] = ...,
    samples_out: Optional[_Path] = ...,
    html: Optional[_Path] = ...,
    color_range: Union[str, Tuple[float, float], None] = ...,
    html_face_budget: Optional[int] = ...,
    threads: Optional[int] = ...,
    progress: _Progress = ...,
    maps: bool = ...,
    index_original: Optional[DistanceIndex] = ...,
    index_processed: Optional[DistanceIndex] = ...,
) -> _Report: ...
def compare_files(
    original: _Path,
    processed: _Path,
    *,
    levels: _Levels = ...,
    radii: _Radii = ...,
    global_level: bool = ...,
    curvature: Optional[str] = ...,
    weighting: Optional[str] = ...,
    measure: Optional[str] = ...,
    unbiased_variance: bool = ...,
    normalize: Optional[str] = ...,
    trim: Optional[float] = ...,
    bootstrap: Optional[int] = ...,
    bootstrap_seed: Optional[int] = ...,
    paper: bool = ...,
    local: bool = ...,
    local_trim: Optional[float] = ...,
    k: Optional[float] = ...,
    roughness: bool = ...,
    distance: bool = ...,
    samples: Optional[int] = ...,
    density: Optional[float] = ...,
    face_sampling: Optional[str] = ...,
    seed: Optional[int] = ...,
    vertex_samples: bool = ...,
    edge_samples: bool = ...,
    face_samples: bool = ...,
    hausdorff: Optional[str] = ...,
    hausdorff_tolerance: Optional[float] = ...,
    hausdorff_abs_tolerance: Optional[float] = ...,
    hausdorff_budget: Optional[int] = ...,
    fscore: Optional[Iterable[float]] = ...,
    histogram: Optional[int] = ...,
    json: Optional[_Path] = ...,
    distance_map: Optional[_Path] = ...,
    distance_map_original: Optional[_Path] = ...,
    distance_maps: Optional[_Path] = ...,
    samples_out: Optional[_Path] = ...,
    html: Optional[_Path] = ...,
    color_range: Union[str, Tuple[float, float], None] = ...,
    html_face_budget: Optional[int] = ...,
    threads: Optional[int] = ...,
    progress: _Progress = ...,
    maps: bool = ...,
    index_original: Optional[DistanceIndex] = ...,
    index_processed: Optional[DistanceIndex] = ...,
) -> _Report: ...
@overload
def profile(
    mesh: _MeshLike, /,
    *,
    levels: _Levels = ...,
    radii: _Radii = ...,
    global_level: bool = ...,
    curvature: Optional[str] = ...,
    weighting: Optional[str] = ...,
    measure: Optional[str] = ...,
    unbiased_variance: bool = ...,
    normalize: Optional[str] = ...,
    trim: Optional[float] = ...,
    bootstrap: Optional[int] = ...,
    bootstrap_seed: Optional[int] = ...,
    paper: bool = ...,
    json: Optional[_Path] = ...,
    vertex_data: Optional[_Path] = ...,
    html: Optional[_Path] = ...,
    color_range: Optional[float] = ...,
    exact: bool = ...,
    exact_property: Optional[str] = ...,
    html_face_budget: Optional[int] = ...,
    threads: Optional[int] = ...,
    progress: _Progress = ...,
) -> _Report: ...
@overload
def profile(
    V: _ArrayLike, F: _ArrayLike,
    *,
    levels: _Levels = ...,
    radii: _Radii = ...,
    global_level: bool = ...,
    curvature: Optional[str] = ...,
    weighting: Optional[str] = ...,
    measure: Optional[str] = ...,
    unbiased_variance: bool = ...,
    normalize: Optional[str] = ...,
    trim: Optional[float] = ...,
    bootstrap: Optional[int] = ...,
    bootstrap_seed: Optional[int] = ...,
    paper: bool = ...,
    json: Optional[_Path] = ...,
    vertex_data: Optional[_Path] = ...,
    html: Optional[_Path] = ...,
    color_range: Optional[float] = ...,
    exact: bool = ...,
    exact_property: Optional[str] = ...,
    html_face_budget: Optional[int] = ...,
    threads: Optional[int] = ...,
    progress: _Progress = ...,
) -> _Report: ...
def profile_file(
    path: _Path,
    *,
    levels: _Levels = ...,
    radii: _Radii = ...,
    global_level: bool = ...,
    curvature: Optional[str] = ...,
    weighting: Optional[str] = ...,
    measure: Optional[str] = ...,
    unbiased_variance: bool = ...,
    normalize: Optional[str] = ...,
    trim: Optional[float] = ...,
    bootstrap: Optional[int] = ...,
    bootstrap_seed: Optional[int] = ...,
    paper: bool = ...,
    json: Optional[_Path] = ...,
    vertex_data: Optional[_Path] = ...,
    html: Optional[_Path] = ...,
    color_range: Optional[float] = ...,
    exact: bool = ...,
    exact_property: Optional[str] = ...,
    html_face_budget: Optional[int] = ...,
    threads: Optional[int] = ...,
    progress: _Progress = ...,
) -> _Report: ...
@overload
def corsini_profile(
    mesh: _MeshLike, /,
    *,
    levels: _Levels = ...,
    global_level: bool = ...,
    unbiased: bool = ...,
    threads: Optional[int] = ...,
    progress: _Progress = ...,
) -> _Report: ...
@overload
def corsini_profile(
    V: _ArrayLike, F: _ArrayLike,
    *,
    levels: _Levels = ...,
    global_level: bool = ...,
    unbiased: bool = ...,
    threads: Optional[int] = ...,
    progress: _Progress = ...,
) -> _Report: ...
@overload
def mean_curvature(
    mesh: _MeshLike, /,
    *,
    method: Optional[str] = ...,
    weighting: Optional[str] = ...,
    min_neighbors: Optional[int] = ...,
    max_normal_angle_deg: Optional[float] = ...,
    threads: Optional[int] = ...,
    progress: _Progress = ...,
) -> _F64: ...
@overload
def mean_curvature(
    V: _ArrayLike, F: _ArrayLike,
    *,
    method: Optional[str] = ...,
    weighting: Optional[str] = ...,
    min_neighbors: Optional[int] = ...,
    max_normal_angle_deg: Optional[float] = ...,
    threads: Optional[int] = ...,
    progress: _Progress = ...,
) -> _F64: ...
@overload
def roughness(
    mesh: _MeshLike, /,
    *,
    levels: _Levels = ...,
    global_level: bool = ...,
    curvature: Optional[str] = ...,
    weighting: Optional[str] = ...,
    normalize: Optional[str] = ...,
    threads: Optional[int] = ...,
    progress: _Progress = ...,
) -> Tuple[_F64, _F64]: ...
@overload
def roughness(
    V: _ArrayLike, F: _ArrayLike,
    *,
    levels: _Levels = ...,
    global_level: bool = ...,
    curvature: Optional[str] = ...,
    weighting: Optional[str] = ...,
    normalize: Optional[str] = ...,
    threads: Optional[int] = ...,
    progress: _Progress = ...,
) -> Tuple[_F64, _F64]: ...
@overload
def surface_distance(
    A: _MeshLike, B: _MeshLike, /,
    *,
    samples: Optional[int] = ...,
    density: Optional[float] = ...,
    face_sampling: Optional[str] = ...,
    seed: Optional[int] = ...,
    vertex_samples: bool = ...,
    edge_samples: bool = ...,
    face_samples: bool = ...,
    return_samples: bool = ...,
    threads: Optional[int] = ...,
    hausdorff: Optional[str] = ...,
    hausdorff_tolerance: Optional[float] = ...,
    hausdorff_abs_tolerance: Optional[float] = ...,
    hausdorff_budget: Optional[int] = ...,
    progress: _Progress = ...,
) -> _Report: ...
@overload
def surface_distance(
    V1: _ArrayLike, F1: Optional[_ArrayLike], V2: _ArrayLike, F2: Optional[_ArrayLike],
    *,
    samples: Optional[int] = ...,
    density: Optional[float] = ...,
    face_sampling: Optional[str] = ...,
    seed: Optional[int] = ...,
    vertex_samples: bool = ...,
    edge_samples: bool = ...,
    face_samples: bool = ...,
    return_samples: bool = ...,
    threads: Optional[int] = ...,
    hausdorff: Optional[str] = ...,
    hausdorff_tolerance: Optional[float] = ...,
    hausdorff_abs_tolerance: Optional[float] = ...,
    hausdorff_budget: Optional[int] = ...,
    progress: _Progress = ...,
) -> _Report: ...
@overload
def vertex_distances(
    A: _MeshLike, B: _MeshLike, /,
    *,
    threads: Optional[int] = ...,
    progress: _Progress = ...,
) -> _F64: ...
@overload
def vertex_distances(
    V1: _ArrayLike, F1: Optional[_ArrayLike], V2: _ArrayLike, F2: Optional[_ArrayLike],
    *,
    threads: Optional[int] = ...,
    progress: _Progress = ...,
) -> _F64: ...

class DistanceIndex:
    """An exact closest-point index over a mesh's triangles (docs/python.md)."""

    @overload
    def __init__(self, mesh: _MeshLike, /, *, threads: Optional[int] = ...) -> None: ...
    @overload
    def __init__(self, V: _ArrayLike, F: _ArrayLike, *, threads: Optional[int] = ...) -> None: ...
    def query(
        self, P: _ArrayLike, *, threads: Optional[int] = ...
    ) -> Tuple[_F64, npt.NDArray[np.int64], _F64]: ...
    @property
    def n_faces(self) -> int: ...
    @property
    def bounds(self) -> Tuple[_F64, _F64]: ...
    @property
    def memory_bytes(self) -> int: ...
    def __reduce__(self) -> Any: ...
