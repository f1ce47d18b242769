"""The module and the CLI agree bit for bit: compare_files() and profile_file()
return the dicts that `meshdiff ... --json -` prints, for the same files and
options (every number equal with ==, every type the same)."""
import json
import math
import subprocess

import numpy as np
import pytest

import meshdiff


def differences(a, b, where="$"):
    """The places where a and b differ in value or type (floats exactly)."""
    if type(a) is not type(b):
        return [f"{where}: {type(a).__name__} {a!r} vs {type(b).__name__} {b!r}"]
    if isinstance(a, dict):
        if a.keys() != b.keys():
            return [f"{where}: keys {sorted(a.keys() ^ b.keys())} on one side only"]
        return [d for k in a for d in differences(a[k], b[k], f"{where}.{k}")]
    if isinstance(a, list):
        if len(a) != len(b):
            return [f"{where}: lengths {len(a)} vs {len(b)}"]
        return [d for i, (x, y) in enumerate(zip(a, b)) for d in differences(x, y, f"{where}[{i}]")]
    if isinstance(a, float) and math.isnan(a) and math.isnan(b):
        return []
    return [] if a == b else [f"{where}: {a!r} vs {b!r}"]


def cli_json(cli, *args):
    out = subprocess.run([cli, *args, "--json", "-"], check=True, capture_output=True, text=True).stdout
    return json.loads(out)


# (original, processed, CLI flags, the same options as keywords)
PAIRS = [
    ("bunny_res3.ply", "bunny_res4_ascii.ply", [], {}),
    ("sphere_ico_2562.ply", "sphere_irregular_3072.ply",
     ["--face-sampling", "montecarlo", "--seed", "7", "--levels", "1,2,5"],
     dict(face_sampling="montecarlo", seed=7, levels=[1, 2, 5])),
    ("torus_R1_r025.ply", "torus_R1_r025.ply", ["--density", "2000", "--no-roughness"],
     dict(density=2000.0, roughness=False)),
    ("fandisk.ply", "hemisphere.ply",
     ["--no-edge-samples", "--no-vertex-samples", "-n", "5000", "--no-roughness", "--threads", "1"],
     dict(edge_samples=False, vertex_samples=False, samples=5000, roughness=False, threads=1)),
    ("bunny_res3.ply", "bunny_res4_ascii.ply", ["--no-distance", "--curvature", "meyer"],
     dict(distance=False, curvature="meyer")),
    ("teapot.obj", "hemisphere.ply",
     ["--levels", "1-3,7", "--no-global", "--weighting", "inverse-square", "-k", "0.001", "--curvature", "quadric"],
     dict(levels=[1, 2, 3, 7], global_level=False, weighting="inverse-square", k=0.001, curvature="quadric")),
]


@pytest.mark.parametrize("original,processed,flags,options", PAIRS, ids=lambda x: str(x)[:40])
def test_compare_files_equals_the_cli_json(cli, data, original, processed, flags, options):
    a, b = str(data / original), str(data / processed)
    expected = cli_json(cli, a, b, *flags)
    got = meshdiff.compare_files(a, b, **options)
    assert differences(got, expected) == []
    assert got["schema"] == "meshdiff.compare/2"


@pytest.mark.parametrize("mesh,flags,options", [
    ("fandisk.ply", [], {}),
    ("bunny_res3.ply", ["--levels", "1,4", "--curvature", "meyer"], dict(levels=[1, 4], curvature="meyer")),
    ("teapot.obj", ["--no-global", "--levels", "2"], dict(global_level=False, levels=[2])),
])
def test_profile_file_equals_the_cli_json(cli, data, mesh, flags, options):
    path = str(data / mesh)
    expected = cli_json(cli, "profile", path, *flags)
    assert differences(meshdiff.profile_file(path, **options), expected) == []


def test_arrays_give_the_numbers_of_the_files(data):
    """compare() on the arrays read_mesh() returns: the numbers of compare_files();
    only the reading report differs (the arrays have no unreferenced vertices)."""
    a, b = data / "bunny_res3.ply", data / "bunny_res4_ascii.ply"
    V1, F1 = meshdiff.read_mesh(a)
    V2, F2 = meshdiff.read_mesh(b)
    files = meshdiff.compare_files(a, b, levels=[1, 5, 20])
    arrays = meshdiff.compare(V1, F1, V2, F2, levels=[1, 5, 20])
    assert differences(arrays["surface_distance"], files["surface_distance"]) == []
    assert differences(arrays["roughness_distance"], files["roughness_distance"]) == []
    for side, name in (("original", "V1"), ("processed", "V2")):
        for key in ("sigma", "sigma_global", "level_details", "curvature"):
            assert differences(arrays[side][key], files[side][key]) == []
        assert arrays[side]["mesh"]["path"] == f"<array {name}>"
        assert arrays[side]["mesh"]["unreferenced_vertices_removed"] == 0
    assert files["original"]["mesh"]["unreferenced_vertices_removed"] == 2
    assert files["original"]["mesh"]["path"] == str(a)


def test_profile_of_arrays_equals_profile_file(data):
    path = data / "hemisphere.ply"
    V, F = meshdiff.read_mesh(path)
    arrays = meshdiff.profile(V, F, levels=range(1, 6))
    files = meshdiff.profile_file(path, levels=range(1, 6))
    del arrays["mesh"]["path"], files["mesh"]["path"]
    assert differences(arrays, files) == []


def test_float32_and_strided_input_are_converted_once(data):
    V, F = meshdiff.read_mesh(data / "hemisphere.ply")
    V32 = V.astype(np.float32)
    reference = meshdiff.surface_distance(V32.astype(np.float64), F, V, F, samples=4000)
    assert differences(meshdiff.surface_distance(V32, F.astype(np.int64), V, F, samples=4000), reference) == []
    # Non-contiguous views: every other column of a wider array, Fortran order.
    wide = np.zeros((len(V), 6))
    wide[:, ::2] = V32
    strided = wide[:, ::2]
    assert not strided.flags.c_contiguous
    assert differences(meshdiff.surface_distance(strided, np.asfortranarray(F), V, F, samples=4000), reference) == []
    # Lists work too.
    tri = meshdiff.surface_distance([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]],
                                    [[0, 0, 0.5], [1, 0, 0.5], [0, 1, 0.5]], [[0, 1, 2]])
    assert tri["sampled_hausdorff"] == tri["hausdorff"]["lower"] == 0.5


def test_corsini_profile_equals_the_cli_json(cli, data):
    path = data / "fandisk.ply"
    V, F = meshdiff.read_mesh(path)
    arrays = meshdiff.corsini_profile(V, F, levels=[1, 2, 5], unbiased=True)
    expected = cli_json(cli, "profile", str(path), "--measure", "corsini", "--levels", "1,2,5", "--unbiased-variance")
    del arrays["mesh"]["path"], expected["mesh"]["path"]
    assert differences(arrays, expected) == []
    assert arrays["schema"] == "meshdiff.corsini/1" and len(arrays["corsini"]["roughness"]) == 3
