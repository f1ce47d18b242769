"""compare(..., index_original=, index_processed=) (issue 32): a DistanceIndex
built once stands in for the index a comparison would build of that mesh. The
numbers are bit for bit those without it; the comparison builds no index of its
own for that mesh (the library reports each index it builds as the stage
"index": counted through progress=); an index of another mesh is refused,
naming the keyword."""
import pickle

import numpy as np
import pytest

import meshdiff


@pytest.fixture(scope="module")
def pair(data):
    return meshdiff.read_mesh(data / "bunny_res3.ply"), meshdiff.read_mesh(data / "bunny_res4_ascii.ply")


def index_builds(*args, **options):
    """The result of compare(*args, **options) and how many indexes it built."""
    stages = []
    result = meshdiff.compare(*args, progress=lambda stage, done, total: stages.append((stage, done)), **options)
    # A build starts at ("index", 0); the hook may see that twice when the build is slow to make progress.
    starts = [k for k, s in enumerate(stages) if s == ("index", 0) and (k == 0 or stages[k - 1] != s)]
    return result, len(starts)


def same_maps(x, y):
    return sorted(x) == sorted(y) and all(np.array_equal(x[k], y[k], equal_nan=True) for k in x)


@pytest.mark.parametrize("options", [dict(levels=[1, 4]), dict(levels=[1], hausdorff="sampled", radii=[0.1]),
                                     dict(measure="corsini"), dict(roughness=False, samples=20000)])
def test_the_same_numbers_and_no_index_built_again(pair, options):
    (V1, F1), (V2, F2) = pair
    ia, ib = meshdiff.DistanceIndex(V1, F1), meshdiff.DistanceIndex(V2, F2)
    plain, built = index_builds(V1, F1, V2, F2, maps=True, **options)
    both, built_both = index_builds(V1, F1, V2, F2, maps=True, index_original=ia, index_processed=ib, **options)
    one, built_one = index_builds(V1, F1, V2, F2, maps=True, index_original=ia, **options)
    maps = plain.pop("maps")
    for r in (both, one):
        assert same_maps(r.pop("maps"), maps)
        assert r == plain  # every number of the report, bit for bit
    # Without indexes: one of each mesh for the surface distance (the original's also serves the local
    # roughness difference's ring levels: built once, then handed on) and, with radii, one more of the
    # processed mesh (the local difference's radii); with both given, none; with the original's, the
    # processed mesh's ones.
    local = options.get("measure") != "corsini" and options.get("roughness", True)
    radii = local and bool(options.get("radii"))
    assert built == 2 + radii and built_both == 0 and built_one == 1 + radii


def test_one_index_serves_many_comparisons(pair):
    """The use it is made for: one original against several processed meshes, the index reused as is
    (also after a pickle round trip, as Dask or multiprocessing hand it over)."""
    (V1, F1), (V2, F2) = pair
    index = meshdiff.DistanceIndex(V1, F1)
    again = pickle.loads(pickle.dumps(index))
    for k, V in enumerate([V2, V2 * 1.01, V2 + 0.001]):
        expected = meshdiff.compare(V1, F1, V, F2, levels=[1])
        for i in (index, again):
            got, built = index_builds(V1, F1, V, F2, levels=[1], index_original=i)
            assert got == expected and built == 1, k  # the processed mesh's, for the surface distance
    # mesh objects and files too
    class Mesh:
        def __init__(self, V, F):
            self.vertices, self.faces = V, F

    assert meshdiff.compare(Mesh(V1, F1), Mesh(V2, F2), levels=[1], index_original=index) == \
        meshdiff.compare(Mesh(V1, F1), Mesh(V2, F2), levels=[1])


def test_compare_files_takes_an_index_of_the_mesh_as_read(pair, data):
    a, b = str(data / "bunny_res3.ply"), str(data / "bunny_res4_ascii.ply")
    index = meshdiff.DistanceIndex(*meshdiff.read_mesh(b))
    assert meshdiff.compare_files(a, b, levels=[1], index_processed=index) == meshdiff.compare_files(a, b, levels=[1])
    with pytest.raises(ValueError, match=r"^index_original: the DistanceIndex is of a mesh with \d+ vertices"):
        meshdiff.compare_files(a, b, levels=[1], index_original=index)


def test_an_index_of_another_mesh_is_refused(pair):
    (V1, F1), (V2, F2) = pair
    with pytest.raises(ValueError, match=r"^index_original: the DistanceIndex is of a mesh with 1887 vertices and "
                                         r"3851 faces, the original has 453 and 948$"):
        meshdiff.compare(V2, F2, V1, F1, index_original=meshdiff.DistanceIndex(V1, F1))
    moved = meshdiff.DistanceIndex(V2 + 1e-9, F2)  # same counts, other coordinates
    with pytest.raises(ValueError, match=r"^index_processed: the DistanceIndex is of another mesh than the processed"):
        meshdiff.compare(V1, F1, V2, F2, index_processed=moved)
    flipped = meshdiff.DistanceIndex(V2, F2[:, ::-1])  # same coordinates, other faces
    with pytest.raises(ValueError, match=r"^index_processed: .* other coordinates or faces"):
        meshdiff.compare(V1, F1, V2, F2, index_processed=flipped)
    with pytest.raises(TypeError, match=r"^index_processed: expected a meshdiff.DistanceIndex or None"):
        meshdiff.compare(V1, F1, V2, F2, index_processed=(V2, F2))


def test_beside_a_point_cloud(pair):
    """A cloud has no DistanceIndex: one given for it is refused; the mesh's index beside it is used."""
    (V1, F1), (V2, F2) = pair
    with pytest.raises(ValueError, match=r"^index_original: .* the original has 1887 and 0$"):
        meshdiff.compare(V1, None, V2, F2, index_original=meshdiff.DistanceIndex(V1, F1))
    got, built = index_builds(V1, None, V2, F2, index_processed=meshdiff.DistanceIndex(V2, F2))
    assert got == meshdiff.compare(V1, None, V2, F2) and built == 0
