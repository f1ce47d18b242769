"""Metric levels (radii) through profile() and profile_file(): the same numbers as the CLI's JSON."""
import json
import subprocess

import pytest

import meshdiff


def test_profile_radii_fields(data):
    V, F = meshdiff.read_mesh(data / "fandisk.ply")
    p = meshdiff.profile(V, F, levels=[1], radii=[0.05, 0.1])
    assert p["radii"] == [0.05, 0.1]
    assert len(p["sigma_radii"]) == 2 and all(s > 0 for s in p["sigma_radii"])
    assert p["radius_details"][0]["radius"] == 0.05
    assert p["levels"] == [1]
    q = meshdiff.profile_file(data / "fandisk.ply", levels=[], radii="default", global_level=False)
    assert q["radii"] == [0.0125 * 2 ** (k / 2) for k in range(9)] and q["levels"] == [] and q["sigma_global"] is None
    assert "radii" not in meshdiff.profile(V, F, levels=[1])


def test_profile_radii_match_cli(data, cli):
    p = meshdiff.profile_file(data / "bunny_res3.ply", levels=[1], radii=[0.1, 0.3])
    out = subprocess.run([cli, "profile", str(data / "bunny_res3.ply"), "--levels", "1", "--radii", "0.1,0.3",
                          "--json", "-"], check=True, capture_output=True, text=True).stdout
    assert json.loads(out)["sigma_radii"] == p["sigma_radii"]


@pytest.mark.parametrize("radii", [[0.0], [-1.0], [float("nan")], [float("inf")], "abc", [5000.0], [0.1] * 65])
def test_bad_radii(data, radii):
    V, F = meshdiff.read_mesh(data / "fandisk.ply")
    with pytest.raises(ValueError, match="radii"):
        meshdiff.profile(V, F, radii=radii)


@pytest.mark.parametrize("radii", [[0.1, "x"], 3.0, [True]])
def test_radii_of_the_wrong_type(data, radii):
    V, F = meshdiff.read_mesh(data / "fandisk.ply")
    with pytest.raises(TypeError, match="radii"):
        meshdiff.profile(V, F, radii=radii)


def test_radii_of_any_float_dtype(data):
    """A float32 array of radii gives the profile of the same radii as float64 (issue 26)."""
    import numpy as np
    V, F = meshdiff.read_mesh(data / "fandisk.ply")
    r32 = np.array([0.05, 0.1], dtype=np.float32)
    got = meshdiff.profile(V, F, radii=r32)
    want = meshdiff.profile(V, F, radii=[float(r) for r in r32])
    assert got == want


def test_compare_files_radii_match_cli(data, cli):
    a, b = data / "bunny_res3.ply", data / "bunny_res4_ascii.ply"
    c = meshdiff.compare_files(a, b, levels=[1], radii=[0.1, 0.3], distance=False)
    d = c["roughness_distance"]
    assert d["radii"] == [0.1, 0.3] and len(d["distance_radii"]) == 2 and len(d["relative_change_radii"]) == 2
    out = subprocess.run([cli, str(a), str(b), "--levels", "1", "--radii", "0.1,0.3", "--no-distance", "--json", "-"],
                         check=True, capture_output=True, text=True).stdout
    assert json.loads(out)["roughness_distance"]["distance_radii"] == d["distance_radii"]
    V, F = meshdiff.read_mesh(a)
    assert "radii" not in meshdiff.compare(V, F, V, F, levels=[1], distance=False)["roughness_distance"]
