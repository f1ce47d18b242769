"""compare(..., maps=True) (issues 29 and 32): the per-vertex arrays are the ones
the comparison itself kept, so they are, bit for bit, the numbers the CLI writes
per vertex for every normalisation: the D_L columns of `meshdiff profile
--vertex-data` (paper, area), the local differences and distances of `meshdiff
compare --distance-maps` (paper, area, original). The maps used to be computed
again in Python, on the paper's scale whatever normalize said."""
import subprocess

import numpy as np
import pytest

import meshdiff

LEVELS = [1, 4]


@pytest.fixture(scope="module")
def spheres(cli, tmp_path_factory):
    """A closed pair (both directions signed): a sphere and a noisy one."""
    d = tmp_path_factory.mktemp("maps")
    a, b = d / "a.ply", d / "b.ply"
    subprocess.run([cli, "generate", "sphere", "--subdivisions", "3", str(a)], check=True, capture_output=True)
    subprocess.run([cli, "generate", "noisy-sphere", "--frequency", "10", str(b)], check=True, capture_output=True)
    return str(a), str(b)


def scalars(path):
    _, _, report = meshdiff.read_mesh(path, report=True)
    return report["vertex_scalars"]


def same(x, y):
    return x.shape == y.shape and np.array_equal(x, y, equal_nan=True)


def cli_profile_D(cli, mesh, normalize, tmp_path):
    """The D_L columns (levels, then global) that `meshdiff profile --vertex-data` writes."""
    out = tmp_path / f"v_{normalize}_{abs(hash(mesh))}.ply"
    subprocess.run([cli, "profile", mesh, "--levels", ",".join(map(str, LEVELS)), "--normalize", normalize,
                    "--vertex-data", str(out)], check=True, capture_output=True)
    s = scalars(out)
    return np.column_stack([s[f"D_{level}"] for level in LEVELS] + [s["D_global"]])


@pytest.mark.parametrize("normalize", ["paper", "area", "original"])
def test_maps_are_the_cli_maps_for_every_normalisation(cli, spheres, normalize, tmp_path):
    a, b = spheres
    r = meshdiff.compare_files(a, b, levels=LEVELS, normalize=normalize, maps=True)
    m = r.pop("maps")
    assert r == meshdiff.compare_files(a, b, levels=LEVELS, normalize=normalize)  # the report is unchanged
    n1, n2 = r["original"]["mesh"]["vertices"], r["processed"]["mesh"]["vertices"]
    assert sorted(m) == ["D_original", "D_processed", "distance_original", "distance_processed", "local_processed",
                         "signed_distance_original", "signed_distance_processed"]
    assert m["D_original"].shape == (n1, 3) and m["D_processed"].shape == (n2, 3)
    assert m["local_processed"].shape == (n2, len(r["roughness_distance"]["local"]["levels"]))
    # The CLI's distance maps of the same comparison: distances, signed distances, local_L.
    prefix = tmp_path / "maps"
    subprocess.run([cli, a, b, "--levels", ",".join(map(str, LEVELS)), "--normalize", normalize,
                    "--distance-maps", str(prefix)], check=True, capture_output=True)
    original, processed = scalars(f"{prefix}_original.ply"), scalars(f"{prefix}_processed.ply")
    assert same(m["distance_original"], original["distance"])
    assert same(m["signed_distance_original"], original["signed_distance"])
    assert same(m["distance_processed"], processed["distance"])
    assert same(m["signed_distance_processed"], processed["signed_distance"])
    for k, level in enumerate(r["roughness_distance"]["local"]["levels"]):
        assert same(m["local_processed"][:, k], processed[f"local_{level}"]), level
    # D_L per vertex: the profile's vertex data of each mesh on its own scale (paper, area); in the
    # original's frame the original's D is its paper-scale one.
    if normalize in ("paper", "area"):
        assert same(m["D_processed"], cli_profile_D(cli, b, normalize, tmp_path))
    assert same(m["D_original"], cli_profile_D(cli, a, "paper" if normalize == "original" else normalize, tmp_path))
    # Each column's RMS is the report's sigma (untrimmed), the processed mesh's in the original's frame too.
    for side in ("original", "processed"):
        rms = np.sqrt(np.nanmean(m[f"D_{side}"] ** 2, axis=0))
        np.testing.assert_allclose(rms, r[side]["sigma"] + [r[side]["sigma_global"]], rtol=1e-12)


def test_area_maps_differ_from_paper_maps(spheres):
    """Regression (issue 29's note): normalize="area" used to give the paper-scale D maps."""
    a, b = spheres
    paper = meshdiff.compare_files(a, b, levels=LEVELS, distance=False, maps=True)["maps"]
    area = meshdiff.compare_files(a, b, levels=LEVELS, distance=False, normalize="area", maps=True)["maps"]
    assert not np.allclose(paper["D_processed"], area["D_processed"], equal_nan=True)


def test_maps_with_radii(spheres):
    a, b = spheres
    r = meshdiff.compare_files(a, b, levels=[1], radii=[0.1, 0.2], distance=False, maps=True)
    m = r["maps"]
    assert m["D_radii_original"].shape == (r["original"]["mesh"]["vertices"], 2)
    assert m["D_radii_processed"].shape == (r["processed"]["mesh"]["vertices"], 2)
    assert "local_processed" not in m  # the local maps come with the distance half


def test_maps_of_the_corsini_measure(spheres):
    a, b = spheres
    m = meshdiff.compare_files(a, b, measure="corsini", maps=True)["maps"]
    assert sorted(m) == ["distance_original", "distance_processed", "signed_distance_original",
                         "signed_distance_processed"]
    assert "maps" not in meshdiff.compare_files(a, b, measure="corsini")


def test_roughness_takes_normalize(cli, spheres, tmp_path):
    """roughness() (no comparison) takes normalize= paper or area, as profile(): the same D as --vertex-data."""
    a, _ = spheres
    V, F = meshdiff.read_mesh(a)
    for normalize in ("paper", "area"):
        D, sigma = meshdiff.roughness(V, F, levels=LEVELS, global_level=True, normalize=normalize)
        assert same(D, cli_profile_D(cli, a, normalize, tmp_path)), normalize
        p = meshdiff.profile(V, F, levels=LEVELS, normalize=normalize)
        np.testing.assert_allclose(sigma, p["sigma"] + [p["sigma_global"]], rtol=1e-12)
    with pytest.raises(ValueError, match="^normalize"):
        meshdiff.roughness(V, F, normalize="original")
    with pytest.raises(ValueError, match="^normalize"):
        meshdiff.roughness(V, F, normalize="volume")
