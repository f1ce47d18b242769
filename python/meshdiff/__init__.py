"""meshdiff: how a processed triangle mesh differs from its original.

The compiled extension meshdiff._meshdiff holds the library; this package
re-exports it and adds, in pure Python, what a Python user expects of a library:
mesh objects (trimesh, Open3D, meshio) wherever V, F are taken, one-line errors for mistyped keywords, the
reports' warnings through warnings.warn, and a picklable DistanceIndex. Every
number is the extension's. The reference is docs/python.md; help(meshdiff.compare)
lists the options.
"""
from typing import Any, Callable, Optional

import numpy as np

from . import _meshdiff
from ._calls import MeshWarning, call, warn_report
from ._meshes import expand
from ._meshdiff import LIMITS, SAMPLE_KINDS, __version__

__doc__ = (__doc__ or "") + "\n" + (_meshdiff.__doc__ or "")

__all__ = [
    "DistanceIndex", "LIMITS", "MeshWarning", "SAMPLE_KINDS", "__version__", "compare", "compare_files",
    "corsini_profile", "mean_curvature", "profile", "profile_file", "read_mesh", "roughness", "surface_distance",
    "vertex_distances",
]

_ORIGINAL_PROCESSED = ("original", "processed")


_MESH_OBJECTS = """
A mesh object may stand for each V, F pair: an object with .vertices and .faces
(trimesh), an Open3D TriangleMesh (.vertices, .triangles) or a meshio.Mesh
(.points, triangle cells only; other cells: ValueError)."""

_PROGRESS = """
progress=None: a callable progress(stage, done, total), called about every 20 ms
while the library works (total 0: not known in advance), or True for a tqdm bar
per stage; an exception it raises stops the call. Ctrl-C stops the call with
KeyboardInterrupt."""

# The package's additions to the extension's docstrings (python/docs.h): its keywords, and an example.
_EXTRA_DOC = {
    "read_mesh": """
Example: V, F = meshdiff.read_mesh("bunny.ply")""",
    "compare": _MESH_OBJECTS + _PROGRESS + """
Report warnings are also raised as meshdiff.MeshWarning.

Example: meshdiff.compare(mesh_a, mesh_b, maps=True)["maps"]["distance_original"]
Example: index = meshdiff.DistanceIndex(mesh_a)
         [meshdiff.compare(mesh_a, b, index_original=index) for b in decimations]""",
    "compare_files": _PROGRESS + """
Report warnings are also raised as meshdiff.MeshWarning.

Example: meshdiff.compare_files("a.ply", "b.ply")["surface_distance"]["hausdorff"]["upper"]""",
    "profile": _MESH_OBJECTS + _PROGRESS + """
Example: meshdiff.profile(V, F, levels=[1, 5, 20])["sigma"]""",
    "profile_file": _PROGRESS + """
Example: meshdiff.profile_file("bunny.ply", levels=[1, 5, 20])["sigma_global"]""",
    "corsini_profile": _MESH_OBJECTS + _PROGRESS + """
Example: meshdiff.corsini_profile(V, F)["corsini"]["multiscale"]""",
    "mean_curvature": _MESH_OBJECTS + _PROGRESS + """
Example: H = meshdiff.mean_curvature(V, F)  # (n,), 1/length unit""",
    "roughness": _MESH_OBJECTS + _PROGRESS + """
Example: D, sigma = meshdiff.roughness(V, F, levels=[1, 5])  # D (n, 2), sigma (2,)""",
    "surface_distance": _MESH_OBJECTS + _PROGRESS,
    "vertex_distances": _MESH_OBJECTS + _PROGRESS + """
Example: d = meshdiff.vertex_distances(V1, F1, V2, F2)  # (n1,), the meshes' unit""",
}


def _public(fn: Callable[..., Any], name: str) -> Callable[..., Any]:
    """fn as the package's function name, with the extension's docstring and the package's additions."""
    fn.__name__ = fn.__qualname__ = name
    fn.__module__ = __name__
    fn.__doc__ = (getattr(_meshdiff, name).__doc__ or "") + _EXTRA_DOC.get(name, "")
    return fn


def _mesh_function(name: str, mesh_names: tuple, warn_sides: Optional[tuple] = None) -> Callable[..., Any]:
    """The extension's function name, taking a mesh object wherever it takes V, F."""
    ext = getattr(_meshdiff, name)

    def function(*args: Any, **options: Any) -> Any:
        result = call(name, ext, expand(args, mesh_names), options)
        if warn_sides is not None:
            warn_report(result, warn_sides)
        return result

    return _public(function, name)


profile = _mesh_function("profile", ("mesh",), ())
corsini_profile = _mesh_function("corsini_profile", ("mesh",), ())
mean_curvature = _mesh_function("mean_curvature", ("mesh",))
roughness = _mesh_function("roughness", ("mesh",))
surface_distance = _mesh_function("surface_distance", ("A", "B"))
vertex_distances = _mesh_function("vertex_distances", ("A", "B"))


def read_mesh(*args: Any, **options: Any) -> Any:
    if "progress" in options:
        raise TypeError("read_mesh(): unknown keyword 'progress'")
    return call("read_mesh", _meshdiff.read_mesh, args, options)


def profile_file(*args: Any, **options: Any) -> Any:
    result = call("profile_file", _meshdiff.profile_file, args, options)
    warn_report(result, ())
    return result


def compare_files(*args: Any, **options: Any) -> Any:
    result = call("compare_files", _meshdiff.compare_files, args, options)
    warn_report(result, _ORIGINAL_PROCESSED)
    return result


def compare(*args: Any, **options: Any) -> Any:
    result = call("compare", _meshdiff.compare, expand(args, _ORIGINAL_PROCESSED), options)
    warn_report(result, _ORIGINAL_PROCESSED)
    return result


compare = _public(compare, "compare")
read_mesh = _public(read_mesh, "read_mesh")
profile_file = _public(profile_file, "profile_file")
compare_files = _public(compare_files, "compare_files")


class DistanceIndex(_meshdiff.DistanceIndex):
    __doc__ = (_meshdiff.DistanceIndex.__doc__ or "") + """
DistanceIndex(V, F, *, threads=None) or DistanceIndex(mesh): threads is the
default of query(). The index pickles (for Dask or multiprocessing): it keeps
V, F as arrays for that; unpickling builds it again.

Example: distance, face, closest = meshdiff.DistanceIndex(V, F).query(P)"""

    def __init__(self, *args: Any, threads: Any = None, **arrays: Any) -> None:
        given = expand(args, ("mesh",))
        super().__init__(*given, **arrays)  # checks the arrays (V, F by position or name) as the extension does
        V, F = (list(given) + [arrays.get(name) for name in ("V", "F")[len(given):]])[:2]
        # Copies for pickling (the index keeps its own copy of the mesh, not exposed).
        self._V = np.array(V, dtype=np.float64)
        self._F = np.array(F, dtype=np.int64)
        self._threads = threads

    def query(self, P: Any, *, threads: Any = None) -> Any:
        return super().query(P, threads=self._threads if threads is None else threads)

    query.__doc__ = _meshdiff.DistanceIndex.query.__doc__

    def __reduce__(self) -> Any:
        return (_rebuild_index, (self._V, self._F, self._threads))


def _rebuild_index(V: Any, F: Any, threads: Any) -> DistanceIndex:
    return DistanceIndex(V, F, threads=threads)
