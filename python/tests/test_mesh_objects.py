"""Mesh objects in (issue 32): a trimesh-like object (.vertices, .faces), an
Open3D TriangleMesh and a meshio.Mesh give the numbers of their arrays, wherever
V, F are taken; a meshio.Mesh with other than triangle cells is refused."""
import meshio
import numpy as np
import open3d as o3d
import pytest

import meshdiff

OPTIONS = dict(levels=[1, 3], samples=2000)


class Duck:
    """A stand-in for trimesh.Trimesh (not packaged in Debian): .vertices, .faces."""

    def __init__(self, V, F):
        self.vertices, self.faces = V, F


def open3d_mesh(V, F):
    return o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(V), o3d.utility.Vector3iVector(F))


def meshio_mesh(V, F):
    return meshio.Mesh(V, [("triangle", F)])


MAKERS = {"duck": Duck, "open3d": open3d_mesh, "meshio": meshio_mesh}


@pytest.fixture(scope="module")
def pair(data):
    return meshdiff.read_mesh(data / "bunny_res3.ply"), meshdiff.read_mesh(data / "bunny_res4_ascii.ply")


@pytest.fixture(scope="module")
def expected(pair):
    (V1, F1), (V2, F2) = pair
    return meshdiff.compare(V1, F1, V2, F2, **OPTIONS)


@pytest.mark.parametrize("kind", sorted(MAKERS))
def test_compare_takes_mesh_objects(pair, expected, kind):
    (V1, F1), (V2, F2) = pair
    make = MAKERS[kind]
    assert meshdiff.compare(make(V1, F1), make(V2, F2), **OPTIONS) == expected
    # one object and one pair of arrays
    assert meshdiff.compare(make(V1, F1), V2, F2, **OPTIONS) == expected
    assert meshdiff.compare(V1, F1, make(V2, F2), **OPTIONS) == expected


@pytest.mark.parametrize("kind", sorted(MAKERS))
def test_single_mesh_functions_take_mesh_objects(pair, kind):
    (V1, F1), (V2, F2) = pair
    m1, m2 = MAKERS[kind](V1, F1), MAKERS[kind](V2, F2)
    assert meshdiff.profile(m1, levels=[1, 2]) == meshdiff.profile(V1, F1, levels=[1, 2])
    assert np.array_equal(meshdiff.mean_curvature(m1), meshdiff.mean_curvature(V1, F1), equal_nan=True)
    D, sigma = meshdiff.roughness(m1, levels=[2])
    D0, sigma0 = meshdiff.roughness(V1, F1, levels=[2])
    assert np.array_equal(D, D0, equal_nan=True) and np.array_equal(sigma, sigma0)
    assert meshdiff.surface_distance(m1, m2, samples=500) == meshdiff.surface_distance(V1, F1, V2, F2, samples=500)
    assert np.array_equal(meshdiff.vertex_distances(m1, m2), meshdiff.vertex_distances(V1, F1, V2, F2))
    P = V2[:50] + 0.01
    for a, b in zip(meshdiff.DistanceIndex(m1).query(P), meshdiff.DistanceIndex(V1, F1).query(P)):
        assert np.array_equal(a, b)


def test_meshio_with_other_cells_is_refused(pair):
    (V1, F1), (V2, F2) = pair
    mixed = meshio.Mesh(V1, [("triangle", F1), ("quad", np.array([[0, 1, 2, 3]]))])
    with pytest.raises(ValueError, match=r"^original: the meshio.Mesh has quad cells; meshdiff takes triangle"):
        meshdiff.compare(mixed, meshio_mesh(V2, F2))
    with pytest.raises(ValueError, match=r"^mesh: the meshio.Mesh has quad cells"):
        meshdiff.profile(mixed)


def test_meshio_triangle_blocks_are_joined(pair):
    (V1, F1), _ = pair
    split = meshio.Mesh(V1, [("triangle", F1[:100]), ("triangle", F1[100:])])
    assert meshdiff.profile(split, levels=[1]) == meshdiff.profile(V1, F1, levels=[1])


def test_a_bad_mesh_object_is_named_like_its_arrays(pair):
    (V1, F1), (V2, F2) = pair
    bad = F1.copy()
    bad[7, 1] = len(V1)
    with pytest.raises(ValueError, match=r"^F1: row 7 "):
        meshdiff.compare(Duck(V1, bad), Duck(V2, F2))
