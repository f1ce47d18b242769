"""Mesh objects in: the (V, F) arrays of the mesh objects people already hold.

meshdiff's functions take a mesh as two arrays, V (n, 3) and F (m, 3). Wherever
they do, the package also takes one mesh object in place of the pair:

- an object with ``.vertices`` and ``.faces`` (trimesh.Trimesh, and any duck type);
- an Open3D ``TriangleMesh`` (``.vertices`` and ``.triangles``);
- a ``meshio.Mesh`` (``.points`` and its "triangle" cells; any other cell type is
  refused with a ValueError, as meshdiff compares triangle meshes only).

The arrays are handed over as they are (no copy where numpy can avoid one); the
extension checks and converts them as it does arrays given directly.
"""
from typing import Any, List, Optional, Sequence, Tuple

import numpy as np


def _meshio_arrays(mesh: Any, name: str) -> Tuple[Any, Any]:
    blocks = list(mesh.cells)
    others = sorted({str(block.type) for block in blocks if block.type != "triangle"})
    if others:
        raise ValueError(f"{name}: the meshio.Mesh has {', '.join(others)} cells; meshdiff takes triangle "
                         f"cells only (triangulate the mesh first)")
    triangles = [np.asarray(block.data) for block in blocks]
    faces = np.concatenate(triangles) if triangles else np.zeros((0, 3), dtype=np.int64)
    return np.asarray(mesh.points), faces


def mesh_arrays(obj: Any, name: str) -> Optional[Tuple[Any, Any]]:
    """(V, F) of the mesh object obj, or None when obj is not a mesh object
    (an array, a list, None: then it is V or F itself). name: the argument's
    name, for the messages."""
    if isinstance(obj, (np.ndarray, list, tuple)) or obj is None:
        return None
    if hasattr(obj, "points") and hasattr(obj, "cells"):  # meshio.Mesh
        return _meshio_arrays(obj, name)
    if hasattr(obj, "vertices") and hasattr(obj, "triangles"):  # open3d.geometry.TriangleMesh
        return np.asarray(obj.vertices), np.asarray(obj.triangles)
    if hasattr(obj, "vertices") and hasattr(obj, "faces"):  # trimesh.Trimesh and duck types
        return np.asarray(obj.vertices), np.asarray(obj.faces)
    return None


def expand(args: Sequence[Any], mesh_names: Sequence[str]) -> List[Any]:
    """The positional arguments args with each mesh object replaced by its V, F.
    mesh_names: the names of the meshes in order ("original", "processed"), for
    the messages."""
    out: List[Any] = []
    for arg in args:
        k = len(out) // 2
        name = mesh_names[k] if k < len(mesh_names) else f"argument {len(out) + 1}"
        vf = mesh_arrays(arg, name) if len(out) % 2 == 0 else None
        if vf is None:
            out.append(arg)
        else:
            out.extend(vf)
    return out
