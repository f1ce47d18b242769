"""The package's pure-Python layer (issue 32): per-vertex maps out of compare(),
one-line TypeErrors, the report warnings through warnings.warn, and a
DistanceIndex that pickles and keeps its thread count."""
import pickle
import warnings

import numpy as np
import pytest

import meshdiff


@pytest.fixture(scope="module")
def pair(data):
    return meshdiff.read_mesh(data / "bunny_res3.ply"), meshdiff.read_mesh(data / "bunny_res4_ascii.ply")


def test_maps_are_the_per_vertex_arrays_behind_the_report(pair):
    (V1, F1), (V2, F2) = pair
    r = meshdiff.compare(V1, F1, V2, F2, levels=[1, 4], maps=True)
    m = r.pop("maps")
    assert r == meshdiff.compare(V1, F1, V2, F2, levels=[1, 4])  # the report itself is unchanged
    assert m["distance_original"].shape == (len(V1),) and m["distance_processed"].shape == (len(V2),)
    assert np.array_equal(m["distance_original"], meshdiff.vertex_distances(V1, F1, V2, F2))
    # every vertex is a sample of its direction: no vertex lies farther than the certified Hausdorff bound
    hd = r["surface_distance"]["hausdorff"]
    assert max(m["distance_original"].max(), m["distance_processed"].max()) <= hd["upper"]
    # D maps: one column per level and the global one; sigma_L is the RMS of a column, bit for bit
    assert m["D_original"].shape == (len(V1), 3) and m["D_processed"].shape == (len(V2), 3)
    for side, V, F in (("original", V1, F1), ("processed", V2, F2)):
        D = m[f"D_{side}"]
        sigma = np.sqrt(np.nanmean(D ** 2, axis=0))
        np.testing.assert_allclose(sigma, r[side]["sigma"] + [r[side]["sigma_global"]], rtol=1e-12)
        # bit for bit the arrays of roughness() (test_roughness.py: they give the profile's sigma exactly)
        assert np.array_equal(D, meshdiff.roughness(V, F, levels=[1, 4], global_level=True)[0], equal_nan=True)


def test_maps_follow_the_paper_method(pair):
    """paper=True computes the report with the goldfeather fit: its D maps are that fit's, and their RMS its sigma."""
    (V1, F1), (V2, F2) = pair
    r = meshdiff.compare(V1, F1, V2, F2, levels=[1, 4], paper=True, distance=False, maps=True)
    D = r["maps"]["D_original"]
    assert np.array_equal(D, meshdiff.roughness(V1, F1, levels=[1, 4], global_level=True, curvature="goldfeather")[0],
                          equal_nan=True)
    np.testing.assert_allclose(np.sqrt(np.nanmean(D ** 2, axis=0)),
                               r["original"]["sigma"] + [r["original"]["sigma_global"]], rtol=1e-12)


def test_no_maps_of_a_half_switched_off(pair):
    (V1, F1), (V2, F2) = pair
    m = meshdiff.compare(V1, F1, V2, F2, levels=[1], roughness=False, maps=True)["maps"]
    assert sorted(m) == ["distance_original", "distance_processed"]
    m = meshdiff.compare(V1, F1, V2, F2, levels=[1], distance=False, maps=True)["maps"]
    assert sorted(m) == ["D_original", "D_processed"]


@pytest.mark.parametrize("call, message", [
    (lambda V, F: meshdiff.compare(V, F, V, F, levles=[1]),
     "compare(): unknown keyword 'levles' (did you mean 'levels'?)"),
    (lambda V, F: meshdiff.compare(V, F, V, F, 4), "compare(): takes 4 positional arguments (V1, F1, V2, F2), "
     "5 given; the options are keyword-only"),
    (lambda V, F: meshdiff.profile(V, F, treads=1), "profile(): unknown keyword 'treads' (did you mean 'threads'?)"),
    (lambda V, F: meshdiff.compare_files("a.ply", "b.ply", zzz=1), "compare_files(): unknown keyword 'zzz'"),
    (lambda V, F: meshdiff.surface_distance(V, F, V), "surface_distance(): missing argument 'F2'"),
])
def test_a_mistyped_call_is_one_line(pair, call, message):
    (V, F), _ = pair
    with pytest.raises(TypeError) as e:
        call(V, F)
    assert str(e.value) == message


def test_report_warnings_are_python_warnings(pair):
    (V1, F1), (V2, F2) = pair
    V1 = np.vstack([V1, [[10.0, 10.0, 10.0]]])  # an isolated vertex: a warning of the original
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = meshdiff.compare(V1, F1, V2, F2, levels=[1])
    texts = [str(w.message) for w in caught
             if issubclass(w.category, meshdiff.MeshWarning) and str(w.message).startswith("original: ")]
    assert r["original"]["warnings"] and texts == [f"original: {t}" for t in r["original"]["warnings"]]
    assert caught[0].filename == __file__  # attributed to the caller


def test_distance_index_pickles(pair):
    (V1, F1), (V2, _) = pair
    index = meshdiff.DistanceIndex(V1, F1, threads=1)
    again = pickle.loads(pickle.dumps(index))
    assert isinstance(again, meshdiff.DistanceIndex) and again.n_faces == index.n_faces
    for a, b in zip(index.query(V2), again.query(V2)):
        assert np.array_equal(a, b)
    assert again._threads == 1


def test_surface_distance_certifies_like_compare(pair):
    (V1, F1), (V2, F2) = pair
    certified = meshdiff.surface_distance(V1, F1, V2, F2, hausdorff="certified")
    assert certified == meshdiff.compare(V1, F1, V2, F2, roughness=False)["surface_distance"]
    h = certified["hausdorff"]
    assert h["certified"] and h["lower"] <= h["upper"]
    # the default stays the sampled maxima, which the certified interval bounds from above
    sampled = meshdiff.surface_distance(V1, F1, V2, F2)
    assert sampled["hausdorff"]["method"] == "sampled" and sampled["hausdorff"]["upper"] is None
    assert sampled["hausdorff"]["lower"] <= h["upper"]
    assert sampled == meshdiff.surface_distance(V1, F1, V2, F2, hausdorff="sampled")
    # with the samples kept, the same report
    kept = meshdiff.surface_distance(V1, F1, V2, F2, hausdorff="certified", hausdorff_tolerance=1e-3,
                                     return_samples=True)
    loose = meshdiff.surface_distance(V1, F1, V2, F2, hausdorff="certified", hausdorff_tolerance=1e-3)
    for side in ("forward", "backward"):
        for key in ("points", "distances", "signed_distances", "kinds", "elements"):
            kept[side].pop(key)
    assert kept == loose
    with pytest.raises(ValueError, match="^hausdorff_tolerance"):
        meshdiff.surface_distance(V1, F1, V2, F2, hausdorff_tolerance=1e-3)


@pytest.mark.parametrize("name", ["read_mesh", "compare", "compare_files", "profile", "profile_file",
                                  "corsini_profile", "mean_curvature", "roughness", "surface_distance",
                                  "vertex_distances", "DistanceIndex"])
def test_every_function_documents_an_example(name):
    doc = getattr(meshdiff, name).__doc__
    assert "Example" in doc and getattr(meshdiff, name).__module__ == "meshdiff"
    if name not in ("read_mesh", "compare_files", "profile_file", "DistanceIndex"):
        assert "mesh object" in doc  # the package's additions are in help() too


def test_arrays_by_name_still_work(pair):
    (V1, F1), (V2, F2) = pair
    index = meshdiff.DistanceIndex(V=V1, F=F1)
    assert pickle.loads(pickle.dumps(index)).n_faces == index.n_faces == len(F1)
    r = meshdiff.compare(V1, F1, V2=V2, F2=F2, levels=[1], maps=True)
    assert np.array_equal(r["maps"]["distance_processed"], meshdiff.vertex_distances(V2, F2, V1, F1))
